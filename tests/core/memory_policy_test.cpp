#include "ramus/memory_policy.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#if defined(__GLIBC__)
#include <sys/resource.h>
#endif

// GCC defines __SANITIZE_ADDRESS__ under AddressSanitizer, clang answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define RAMUS_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAMUS_TEST_ASAN 1
#endif
#endif

namespace ramus {
namespace {

#if defined(__GLIBC__)
long minorFaults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// Writes a fresh 16 MiB block and frees it; returns the page faults that took.
long faultsOfOneLargeBlock() {
    constexpr std::size_t kBytes = std::size_t{16} << 20;
    const long before = minorFaults();
    {
        std::unique_ptr<char[]> block(new char[kBytes]);
        std::memset(block.get(), 1, kBytes);
        EXPECT_EQ(block[kBytes - 1], 1);
    }
    return minorFaults() - before;
}

// The second item of a batch reuses the first one's freed memory instead of faulting every
// page in again (4096 pages of 4 KiB here).
TEST(MemoryPolicy, ASecondLargeBlockReusesTheFreedMemory) {
#if defined(RAMUS_TEST_ASAN)
    GTEST_SKIP() << "AddressSanitizer brings its own allocator; glibc's tuning does not apply";
#endif
    keepFreedMemoryForReuse();
    (void)faultsOfOneLargeBlock();  // the first one maps its pages
    EXPECT_LT(faultsOfOneLargeBlock(), 256);
}
#endif

}  // namespace
}  // namespace ramus
