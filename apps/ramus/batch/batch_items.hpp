// Making one batch item: the model (and metadata, preview) of one skeleton, L-system plant or
// colonized tree, written atomically into the output directory (docs/batch.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "batch/batch_manifest.hpp"
#include "ramus/bones.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus::cli {

/// The seed of an item: hashCombine(manifest seed, item index), so any subset of a manifest
/// (a shard, a resumed run) regenerates the same bytes.
std::uint64_t itemSeed(const BatchManifest& manifest, const BatchItem& item);

/// Every file the item writes, relative to the output directory: the model, the skeleton
/// metadata (.json next to a skeleton's model) and the preview when asked for.
std::vector<std::string> itemOutputs(const BatchManifest& manifest, const BatchItem& item);

/// Checks the job inputs of every job once, before any item runs (unknown keys, values of the
/// wrong type, missing files), so a typo fails at once rather than in every item.
void checkJobInputs(const BatchManifest& manifest);

/// Per job: the user bone library its inputs name ("bones"), or nullopt for the default one.
using JobBoneLibraries = std::vector<std::optional<BoneLibrary>>;

/// Loads the bone libraries of the skeleton jobs once (a directory named by several jobs at one
/// resolution once), before any item runs. Throws Error naming the library file and the job.
JobBoneLibraries loadJobBoneLibraries(const BatchManifest& manifest);

/// Makes one item and writes its files under `outputDirectory` (each atomically); `bones` is
/// loadJobBoneLibraries(manifest). Throws Error with the reason when the item cannot be made.
void makeItem(const BatchManifest& manifest, const BatchItem& item, const SkeletonStats& stats,
              const JobBoneLibraries& bones, const std::string& outputDirectory);

}  // namespace ramus::cli
