#pragma once
// Opening an input file: a missing file, a directory or an unreadable file is an
// InputError naming it (line 0). Shared by the text readers and sampling's ByteSource.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "kernel/input_error.hpp"

namespace dtlab {

// Throws unless `path` can be opened as a file; returns its size in bytes when it is a
// regular file (a pipe or device has none, so readers cannot cap counts by it).
inline std::optional<std::uintmax_t> input_file_size(const std::string& path) {
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(st)) throw InputError(path, 0, "cannot open file");
  if (std::filesystem::is_directory(st)) throw InputError(path, 0, "is a directory");
  if (!std::filesystem::is_regular_file(st)) return std::nullopt;
  const auto n = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;
  return n;
}

// A count read from a file that promises `count` records of at least `min_tokens`
// tokens each (a token and a separator: 2 bytes) cannot exceed what `bytes` hold.
inline bool count_fits(long count, int min_tokens, std::optional<std::uintmax_t> bytes) {
  if (count < 0) return false;
  if (!bytes) return true;
  return static_cast<std::uintmax_t>(count) <= (*bytes + 1) / (2u * static_cast<unsigned>(min_tokens));
}

// Up-front reservations from a file's counts stop here; vectors grow past it as the
// records are actually read.
inline constexpr std::size_t kMaxReserve = std::size_t{1} << 20;

// Attributes per record in .node/.ele headers: more than any real file has, and small
// enough that field arithmetic cannot overflow.
inline constexpr long kMaxAttributes = 1 << 20;

}  // namespace dtlab
