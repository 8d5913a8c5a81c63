// Skeleton real size and metadata files (seed 000 §6.2; SPEC §G; docs/skeleton.md "Real size"
// and "Metadata format").
//
// Real size: the annotation frame's 1000 px span the larger side of the animal's skeleton
// (seed 000 §7.4.1), so metres per px = extent / 1000 with the extent from an allometric rule
// extent = a·W^b fitted on the 44 species (data/species/sizes.csv), or from a height or length
// the user gives.
//
// Metadata: a versioned JSON file ("format": "ramus-skeleton", "version": 1) holding the design
// (everything buildSkeleton needs: loading it and building again gives identical bytes) and, for
// other tools, the resulting bones (hierarchy, transforms, joint axes and limits, ground
// height), which loading does not read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "ramus/skeleton.hpp"

namespace ramus {

// ---- real size -------------------------------------------------------------------------------

/// The allometric rule extent_m = kSizeRuleCoefficient · weight_kg ^ kSizeRuleExponent: the
/// least-squares line in log–log space through the 44 species' weights (species.json) and
/// typical extents (data/species/sizes.csv), rounded to 4 significant digits. Typical error: a
/// factor of 1.36 (root mean square of the log residuals).
inline constexpr double kSizeRuleCoefficient = 0.3822;
inline constexpr double kSizeRuleExponent = 0.3460;
/// Weights are clamped to [kSizeRuleMinWeightKg, kMaxWeightKg] before the rule is applied (a
/// sampled feature point can decode to a weight ≤ 0 or beyond the heaviest vertebrate).
inline constexpr double kSizeRuleMinWeightKg = 0.001;

/// The real extent (m) of the annotation frame's 1000 px for an animal of the given weight
/// (kg): kSizeRuleCoefficient · w^kSizeRuleExponent with w clamped (a NaN counts as the
/// minimum). skeletonScaleFromWeight(w) = skeletonExtentFromWeight(w) / 1000.
double skeletonExtentFromWeight(double weightKg);

/// Metres per px from a requested real height or length of a built skeleton: height / (the y
/// extent of its bounding box) or length / (its x extent), the box taken over all bone box
/// corners in the internal frame. With neither given: skeleton.metresPerPixel (the size from
/// the weight). Throws Error when both are given, when a value is not finite and > 0, or when
/// the skeleton has no extent along that axis.
double skeletonScaleForExtent(const Skeleton& skeleton, std::optional<double> heightMetres,
                              std::optional<double> lengthMetres);

// ---- metadata --------------------------------------------------------------------------------

/// The version skeletonMetadataJson writes and readSkeletonMetadata accepts.
inline constexpr int kSkeletonMetadataVersion = 1;

/// The metadata JSON of a skeleton (docs/skeleton.md "Metadata format"): the design, the name
/// and seed, and the bones of `skeleton` (pass buildSkeleton(design); an empty Skeleton gives an
/// empty bone list). Numbers are written in their shortest form that reads back to the same
/// double; the two seeds as decimal strings (exact for every uint64). Deterministic: equal
/// inputs give identical bytes.
std::string skeletonMetadataJson(const SkeletonDesign& design, const Skeleton& skeleton,
                                 std::string_view name, std::uint64_t seed);

/// Writes skeletonMetadataJson(…) to `path` atomically (writeFileAtomic). Throws Error when the
/// file cannot be written.
void writeSkeletonMetadata(const std::string& path, const SkeletonDesign& design,
                           const Skeleton& skeleton, std::string_view name, std::uint64_t seed);

/// What loading a metadata file gives: enough to rebuild the skeleton (buildSkeleton(design)).
struct LoadedSkeleton {
    SkeletonDesign design;
    std::string name;
    std::uint64_t seed = 0;
};

/// Parses metadata text. `fileName` is used in error messages. Reads "format", "version",
/// "name", "seed" and "design"; "skeleton" (the bones) and "design.features" are informative and
/// ignored. Throws Error for malformed JSON (with line and column), another format, an
/// unsupported version, missing or unknown fields, and any value of the wrong type or outside
/// its range (the grammar's constraints on the counts, limb kinds their attachment does not
/// accept, wing angles outside their intervals, heel_draw outside [0, 1), non-finite numbers),
/// naming the field: "FILE: field 'design.limbs.hip': expected one of …; got \"tail\"".
LoadedSkeleton parseSkeletonMetadata(std::string_view text, const std::string& fileName);

/// readFile(path) + parseSkeletonMetadata.
LoadedSkeleton readSkeletonMetadata(const std::string& path);

}  // namespace ramus
