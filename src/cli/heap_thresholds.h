// Where glibc serves a run's large buffers from. Private to the executables.
#pragma once

#include <malloc.h>

namespace isolab::cli {

// A run allocates and frees buffers of a megabyte or more: its record, the model summary's, the
// results file's chunks, a study's per-run response arrays. glibc maps each block of 128 KiB or
// more from the kernel and unmaps it when it is freed, raising that threshold only after such a
// free, so the pages are faulted in and zeroed again: about 300 of the 2,450 page faults of a
// one-step 1000-story run, and in a study every run's (with threads sharing one address space,
// TLB shootdowns too: 15 % of the 2-thread throughput on the bundled study). Served and reused
// from the heap instead, up to glibc's ceiling for the threshold (32 MiB on 64-bit). Called by
// the front (`run`, `spectrum`, `bounds`, whose short runs end before glibc has learnt) and by
// `compare`.
inline void KeepLargeBuffersInTheHeap() {
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
}

}  // namespace isolab::cli
