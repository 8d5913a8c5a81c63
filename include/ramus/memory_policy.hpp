// Process-wide allocator policy for repeated generation (batches, the studio, benchmarks).
#pragma once

#include <cstddef>

namespace ramus {

/// Tunes the C library's allocator so that memory freed by one generated item is kept for the
/// next one instead of being handed back to the kernel and faulted in again page by page.
///
/// Why: glibc returns freed blocks above its (adaptive) mmap threshold and the freed top of the
/// heap above its trim threshold to the kernel right away; the next skeleton or tree then takes
/// a page fault (and a zeroed page) for every 4 KiB it writes. Measured in the 2-core sandbox:
/// 48 page faults per box skeleton, and scene + GLB took 363–414 µs without this policy against
/// 225–239 µs with it (docs/BENCHMARKS.md). With this policy
/// blocks up to `maxRetainedBytes` come from the heap and up to that much freed memory stays
/// mapped for reuse. Results are unchanged; only the process's resident memory after a large
/// item stays higher (at most its peak). Call once at start-up, before other threads start.
/// No effect outside glibc.
void keepFreedMemoryForReuse(std::size_t maxRetainedBytes = std::size_t{1} << 30);

}  // namespace ramus
