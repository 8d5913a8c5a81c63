// The skeleton statistics built from the thesis's 44 species, built once per test process.
#pragma once

#include "ramus/skeleton_stats.hpp"

namespace ramus::test {

inline const SkeletonStats& thesisModel() {
    static const SkeletonStats stats = SkeletonStats::builtin();
    return stats;
}

}  // namespace ramus::test
