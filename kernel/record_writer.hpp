#pragma once
// Text records written at disk speed: record i is formatted by `format(i, out)` with
// std::to_chars into a block buffer (no stdio formatting, no locale), blocks of
// records are formatted in parallel and written in order, so the bytes are the same
// for every thread count. Doubles are written in the shortest form that reads back
// to the same double (std::to_chars without a precision).
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "kernel/output_file.hpp"
#include "kernel/parallel_for.hpp"

namespace dtlab {

// Upper bounds of one formatted field, for `max_bytes` below.
inline constexpr std::size_t kMaxDoubleChars = 24;  // -1.2345678901234567e-308
inline constexpr std::size_t kMaxIntChars = 20;     // 2^64 - 1

inline char* put_chars(char* out, std::uint64_t v) { return std::to_chars(out, out + kMaxIntChars, v).ptr; }
inline char* put_chars(char* out, double v) { return std::to_chars(out, out + kMaxDoubleChars, v).ptr; }

// Writes records [0, count) to f; each takes at most `max_bytes` characters.
template <class Format>
void write_records(OutputFile& f, std::size_t count, std::size_t max_bytes, unsigned threads, Format&& format) {
  constexpr std::size_t kBlock = 1 << 15;  // records per block: a few MB of text
  // One buffer per block in flight: no more workers than blocks, nor than the machine
  // runs at once (the bytes do not depend on the count), and no block larger than the file.
  const std::size_t block_count = std::max<std::size_t>((count + kBlock - 1) / kBlock, 1);
  const unsigned workers = static_cast<unsigned>(
      std::min<std::size_t>({thread_count(threads), thread_count(0), block_count}));
  std::vector<std::vector<char>> buffers(workers, std::vector<char>(std::min(kBlock, count) * max_bytes));
  std::vector<std::size_t> used(workers);
  for (std::size_t round = 0; round < count; round += kBlock * workers) {
    // One block per worker: formatted in parallel, then written in block order.
    const std::size_t blocks = std::min<std::size_t>(workers, (count - round + kBlock - 1) / kBlock);
    parallel_chunks(blocks, workers, 1, [&](std::size_t b, std::size_t, unsigned) {
      const std::size_t first = round + b * kBlock, last = std::min(count, first + kBlock);
      char* out = buffers[b].data();
      for (std::size_t i = first; i < last; ++i) out = format(i, out);
      used[b] = static_cast<std::size_t>(out - buffers[b].data());
    });
    for (std::size_t b = 0; b < blocks; ++b) std::fwrite(buffers[b].data(), 1, used[b], f.get());
  }
}

}  // namespace dtlab
