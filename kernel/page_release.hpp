#pragma once
// Handing the pages of a buffer already read back to the system (the compactions of
// kernel/build_impl.hpp and kernel/canonical_order.cpp), and committing a new buffer's
// pages from several threads.
#include <cstdint>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace dtlab::detail {

// Page-aligned ranges of a buffer already read can be handed back to the system, so
// that the compaction's output grows while the mesh it reads shrinks (peak memory is
// the mesh's, not the mesh's plus the output's).
// Releases the whole pages in [begin, end); returns where the next release starts
// (the page holding `end`, not yet released).
inline const char* release_pages(const char* begin, const char* end) {
  constexpr std::uintptr_t kPage = 4096;
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(begin) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t e = reinterpret_cast<std::uintptr_t>(end) & ~(kPage - 1);
#ifdef __linux__
  if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_DONTNEED);
#endif
  return e > b ? reinterpret_cast<const char*>(e) : begin;
}

// Commits the whole pages in [begin, end) for writing, as first writes would (where the
// system offers it: Linux 5.14's MADV_POPULATE_WRITE; elsewhere nothing), so that several
// threads can take a new buffer's page faults before one thread fills it.
inline void populate_pages(char* begin, char* end) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::uintptr_t kPage = 4096;
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(begin) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t e = reinterpret_cast<std::uintptr_t>(end) & ~(kPage - 1);
  if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_POPULATE_WRITE);  // an old kernel says EINVAL: no harm
#else
  (void)begin, (void)end;
#endif
}

}  // namespace dtlab::detail
