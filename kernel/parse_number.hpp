#pragma once
// Strict number parsing for the readers: the whole token, finite, in range. On failure
// the reason names the token (shortened: a 400-digit token is not echoed in full).
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace dtlab {

// The token as quoted in a message: at most 32 characters, bytes that would not show
// (a byte order mark, a control character) written as \xNN.
inline std::string quote_token(std::string_view tok) {
  // Built by append: GCC 12's -Wrestrict misfires on chains of operator+ here.
  std::string out(1, '\'');
  for (const char c : tok.substr(0, tok.size() <= 32 ? tok.size() : 24)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out.push_back(c);
    } else {
      const char* hex = "0123456789ABCDEF";
      out.append("\\x").append(1, hex[u >> 4]).append(1, hex[u & 15]);
    }
  }
  if (tok.size() <= 32) return out.append(1, '\'');
  return out.append("...' (").append(std::to_string(tok.size())).append(" characters)");
}

// Empty string on success, else the reason.
inline std::string parse_double(std::string_view tok, double& v) {
  const char* b = tok.data();
  const char* e = b + tok.size();
  if (b != e && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc::result_out_of_range && p == e)
    return "number out of range of a double: " + quote_token(tok);
  if (ec != std::errc() || p != e) return "not a number: " + quote_token(tok);
  if (!std::isfinite(v)) return "non-finite coordinate: " + quote_token(tok);
  return {};
}

inline std::string parse_long(std::string_view tok, long& v) {
  const char* b = tok.data();
  const char* e = b + tok.size();
  if (b != e && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc::result_out_of_range && p == e) return "integer out of range: " + quote_token(tok);
  if (ec != std::errc() || p != e) return "not an integer: " + quote_token(tok);
  return {};
}

}  // namespace dtlab
