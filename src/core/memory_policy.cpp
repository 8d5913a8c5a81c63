#include "ramus/memory_policy.hpp"

#include <algorithm>
#include <climits>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ramus {

void keepFreedMemoryForReuse(std::size_t maxRetainedBytes) {
#if defined(__GLIBC__)
    // mallopt takes an int; setting either value also turns off glibc's adaptive thresholds,
    // which would otherwise move the mmap threshold back down after a large block.
    const int bytes = static_cast<int>(std::min<std::size_t>(maxRetainedBytes, INT_MAX));
    mallopt(M_MMAP_THRESHOLD, bytes);
    mallopt(M_TRIM_THRESHOLD, bytes);
#else
    (void)maxRetainedBytes;
#endif
}

}  // namespace ramus
