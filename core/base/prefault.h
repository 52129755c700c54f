// Populating a fresh buffer before it is written: a buffer written once right after its allocation (the coordinate
// gradients, 3 x 140 MB for FIREHYDRANT) otherwise takes a page fault at the first write of each 4 kB page, and on
// this project's virtual machine the fault's trap costs about as much as the page itself (7 % of the gradients'
// time in a profile). One system call per 2 MB slice, on every thread, allocates the same pages without the traps.
#pragma once

#include <cstddef>

namespace somicage {

// Allocates the pages of [data, data + bytes) for writing on `threads` OpenMP threads (0: the default), where the
// system can (Linux 5.14 and later: MADV_POPULATE_WRITE); elsewhere, or if it fails, the first writes fault them in
// as before. The contents are unchanged.
void prefaultForWriting(void* data, std::size_t bytes, int threads);

}  // namespace somicage
