// Batch manifests (docs/batch.md): a seed and a list of jobs, each making `count` items of one
// kind (skeleton, lsystem, colonize) from the inputs of the matching command.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ramus::cli {

enum class BatchKind { Skeleton, Lsystem, Colonize };

/// One job of a manifest.
struct BatchJob {
    BatchKind kind = BatchKind::Skeleton;
    int count = 1;
    nlohmann::json inputs = nlohmann::json::object();
    /// Output path pattern relative to the output directory: "{index}" is the item's index in
    /// the whole manifest, "{n}" its index within the job. The extension picks the format
    /// (.glb or .obj).
    std::string output;
    std::string png;  ///< optional preview pattern (same placeholders); empty = none
};

struct BatchManifest {
    std::string path;  ///< the manifest file (relative input files are resolved from its folder)
    std::uint64_t seed = 0;
    std::vector<BatchJob> jobs;

    std::size_t itemCount() const;
};

/// One item to make: its global index, its job, and its index within the job.
struct BatchItem {
    std::size_t index = 0;
    std::size_t job = 0;
    std::size_t n = 0;
};

/// Default largest number of items in one manifest (`ramus batch --max-items`): a typo like
/// 1e9 fails at once, not after hours.
inline constexpr std::size_t kMaxBatchItems = 10'000'000;

/// Parses a manifest; every error names the file and the JSON path (and line:col for syntax
/// errors). Outputs must stay inside the output directory (no absolute paths, no "..") and
/// every output pattern must contain "{index}" or "{n}" when its job makes several items.
/// More than `maxItems` items in all (or in one job) is an error naming the count and limit.
BatchManifest parseBatchManifest(const std::string& text, const std::string& path,
                                 std::size_t maxItems = kMaxBatchItems);
BatchManifest loadBatchManifest(const std::string& path, std::size_t maxItems = kMaxBatchItems);

/// The items of shard `shard` of `shards` (every shards-th item, starting at shard), in order.
std::vector<BatchItem> shardItems(const BatchManifest& manifest, std::size_t shard,
                                  std::size_t shards);

/// `pattern` with {index} and {n} replaced.
std::string expandOutput(const std::string& pattern, const BatchItem& item);

}  // namespace ramus::cli
