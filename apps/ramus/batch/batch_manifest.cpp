// Batch manifests (batch_manifest.hpp, docs/batch.md).
#include "batch/batch_manifest.hpp"

#include <filesystem>
#include <limits>

#include "core/json_text.hpp"
#include "json_inputs.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"

namespace ramus::cli {
namespace {

BatchKind parseKind(const nlohmann::json& job, const std::string& path) {
    const std::string kind = requiredString(job, "kind");
    if (kind == "skeleton") return BatchKind::Skeleton;
    if (kind == "lsystem") return BatchKind::Lsystem;
    if (kind == "colonize") return BatchKind::Colonize;
    throw Error(path + ".kind: expected skeleton, lsystem or colonize, got \"" + kind + "\"");
}

/// An output pattern: relative, inside the output directory, with a known extension.
std::string outputPattern(const nlohmann::json& job, const char* key, const std::string& path,
                          int count, const std::vector<std::string>& extensions) {
    const std::string pattern = requiredString(job, key);
    const std::filesystem::path p(pattern);
    if (p.is_absolute() || pattern.find("..") != std::string::npos || pattern.empty()) {
        throw Error(path + "." + key + ": expected a path inside the output directory, got \"" +
                    pattern + "\"");
    }
    bool known = false;
    for (const std::string& ext : extensions) known = known || p.extension() == ext;
    if (!known) {
        std::string list;
        for (const std::string& ext : extensions) list += (list.empty() ? "" : ", ") + ext;
        throw Error(path + "." + key + ": expected a file name ending in " + list + ", got \"" +
                    pattern + "\"");
    }
    if (count > 1 && pattern.find("{index}") == std::string::npos &&
        pattern.find("{n}") == std::string::npos) {
        throw Error(path + "." + key + ": " + std::to_string(count) +
                    " items would share one file; expected {index} or {n} in \"" + pattern + "\"");
    }
    return pattern;
}

BatchJob parseJob(const nlohmann::json& job, const std::string& path, std::size_t maxItems) {
    requireObject(job, path);
    for (const auto& [key, value] : job.items()) {
        if (key != "kind" && key != "count" && key != "inputs" && key != "output" && key != "png") {
            throw Error(path + "." + key +
                        ": unknown key; expected kind, count, inputs, output "
                        "or png");
        }
    }
    BatchJob result;
    result.kind = parseKind(job, path);
    if (job.contains("count")) {
        const nlohmann::json& count = job["count"];
        if (count.is_number_integer() && count.get<std::int64_t>() > 0 &&
            static_cast<std::uint64_t>(count.get<std::int64_t>()) > maxItems) {
            throw Error(path + ".count: " + count.dump() + " items are above the limit of " +
                        std::to_string(maxItems) +
                        "; expected fewer, or raise the limit with --max-items");
        }
        result.count = integerIn(count, path + ".count", 1, std::numeric_limits<int>::max());
    }
    if (const auto* inputs = optionalMember(job, "inputs", nlohmann::json::value_t::object)) {
        result.inputs = *inputs;
    }
    result.output = outputPattern(job, "output", path, result.count, {".glb", ".obj"});
    if (job.contains("png")) result.png = outputPattern(job, "png", path, result.count, {".png"});
    return result;
}

}  // namespace

std::size_t BatchManifest::itemCount() const {
    std::size_t n = 0;
    for (const BatchJob& job : jobs) n += static_cast<std::size_t>(job.count);
    return n;
}

BatchManifest parseBatchManifest(const std::string& text, const std::string& path,
                                 std::size_t maxItems) {
    const nlohmann::json root = detail::parseJsonText(text, path);
    BatchManifest manifest;
    manifest.path = path;
    try {
        requireObject(root, "manifest");
        for (const auto& [key, value] : root.items()) {
            if (key != "seed" && key != "jobs" && key != "description") {
                throw Error(key + ": unknown key; expected seed, jobs or description");
            }
        }
        if (root.contains("seed")) manifest.seed = seedFrom(root["seed"], "seed");
        const auto* jobs = optionalMember(root, "jobs", nlohmann::json::value_t::array);
        if (!jobs || jobs->empty()) throw Error("jobs: expected a non-empty list of jobs");
        for (std::size_t j = 0; j < jobs->size(); ++j) {
            const std::string jobPath = "jobs[" + std::to_string(j) + "]";
            try {
                manifest.jobs.push_back(parseJob((*jobs)[j], jobPath, maxItems));
            } catch (const Error& e) {
                // Messages of the typed readers start with the key; give the whole path.
                if (e.message().rfind(jobPath, 0) == 0) throw;
                throw Error(jobPath + "." + e.message());
            }
            if (manifest.itemCount() > maxItems) {
                throw Error("jobs: " + std::to_string(manifest.itemCount()) + " items in jobs[0.." +
                            std::to_string(j) + "] are above the limit of " +
                            std::to_string(maxItems) +
                            "; expected fewer, or raise the limit with --max-items");
            }
        }
    } catch (const Error& e) {
        if (!e.loc().file.empty()) throw;
        throw Error(path + ": " + e.message());
    }
    return manifest;
}

BatchManifest loadBatchManifest(const std::string& path, std::size_t maxItems) {
    return parseBatchManifest(readFile(path), path, maxItems);
}

std::vector<BatchItem> shardItems(const BatchManifest& manifest, std::size_t shard,
                                  std::size_t shards) {
    std::vector<BatchItem> items;
    std::size_t index = 0;
    for (std::size_t j = 0; j < manifest.jobs.size(); ++j) {
        for (std::size_t n = 0; n < static_cast<std::size_t>(manifest.jobs[j].count); ++n) {
            if (index % shards == shard) items.push_back({index, j, n});
            ++index;
        }
    }
    return items;
}

std::string expandOutput(const std::string& pattern, const BatchItem& item) {
    std::string out;
    for (std::size_t i = 0; i < pattern.size();) {
        if (pattern.compare(i, 7, "{index}") == 0) {
            out += std::to_string(item.index);
            i += 7;
        } else if (pattern.compare(i, 3, "{n}") == 0) {
            out += std::to_string(item.n);
            i += 3;
        } else {
            out += pattern[i++];
        }
    }
    return out;
}

}  // namespace ramus::cli
