#include "base/prefault.h"

#include <omp.h>

#include <algorithm>
#include <cstdint>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace somicage {

void prefaultForWriting(void* data, std::size_t bytes, int threads) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::uintptr_t kPage = 4096, kSlice = std::uintptr_t(1) << 21;
  // Whole pages only: madvise takes a page-aligned start, and the buffer's first and last pages may be shared with
  // other allocations (those fault as usual).
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end <= begin) return;
  const long slices = static_cast<long>((end - begin + kSlice - 1) / kSlice);
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (long s = 0; s < slices; ++s) {
    const std::uintptr_t first = begin + static_cast<std::uintptr_t>(s) * kSlice;
    // Only advice: an error (an older kernel, no memory left to populate) leaves the pages to fault in as before.
    (void)madvise(reinterpret_cast<void*>(first), std::min(kSlice, end - first), MADV_POPULATE_WRITE);
  }
#else
  (void)data;
  (void)bytes;
  (void)threads;
#endif
}

}  // namespace somicage
