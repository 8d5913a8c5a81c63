// Which skeletons a request makes — shared by `ramus skeleton` and the studio: fresh designs,
// a loaded design regenerated, or variations of a loaded or example design (seed 000 §6.2, §6.3).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus::cli {

/// Bounds of the numeric skeleton inputs wherever they come from (flags, studio, batches):
/// neck and tail lengths in px of the 1000 px frame, body height and length in metres.
inline constexpr double kMaxFrameLength = 2000.0;
inline constexpr double kMinBodyMetres = 1e-3;
inline constexpr double kMaxBodyMetres = 1e3;

/// Default of `ramus skeleton --max-count` (more skeletons belong in a batch manifest).
inline constexpr int kDefaultMaxSkeletons = 10'000;

/// What to make: `count` skeletons named `name`0, `name`1, …
struct SkeletonPlanRequest {
    SkeletonInputs inputs;
    std::optional<LoadedSkeleton> loaded;  ///< a saved skeleton (metadata) to regenerate or vary
    bool variations = false;               ///< vary the loaded (or example) skeleton
    int count = 1;
    std::optional<std::uint64_t> seed;  ///< default: the loaded skeleton's seed, else 1
    std::string name = "skeleton";      ///< "skeleton" = the loaded skeleton's name when reused
};

/// One skeleton to build and save.
struct PlannedSkeleton {
    SkeletonDesign design;
    std::string name;
    std::uint64_t seed = 0;  ///< the request's seed, saved in the metadata
};

/// The designs of a request, in order. Skeleton i draws from Rng::forStream(seed, i), a
/// variations source from the stream ~0, so any subset regenerates the same designs. A loaded
/// skeleton without variations gives exactly it once. An example species without a head kind
/// gets the skull of its class (defaultHeadKind), saved in the designs. Throws Error for
/// inconsistent requests (count < 1, variations without a source, a loaded skeleton with
/// count > 1 but no variations, both a loaded skeleton and an example, an unknown head kind).
std::vector<PlannedSkeleton> planSkeletons(const SkeletonStats& stats,
                                           const SkeletonPlanRequest& request);

/// A plan request from JSON inputs with the keys of docs/studio.md ("POST /api/skeleton"; also
/// batch manifests' skeleton inputs): legs, wings, arms, fins, neck_y, tail_x, height_m,
/// length_m, two_per_girdle, neck_shoulder, head, example, spacing, spread, saved (metadata),
/// variations, count (1…maxCount), seed, name. Absent keys have no influence. Throws Error
/// naming the key. Other keys are left to the caller (e.g. "resolution").
SkeletonPlanRequest skeletonPlanFromJson(const nlohmann::json& inputs, int maxCount);

/// Whether `key` is one of the keys skeletonPlanFromJson reads.
bool isSkeletonInputKey(const std::string& key);

}  // namespace ramus::cli
