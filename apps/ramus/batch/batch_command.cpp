// `ramus batch MANIFEST.json [-o DIR] [--jobs N] [--shard I/N] [--resume]`: many skeletons and
// trees from one manifest, on N threads, with a progress bar, per-item seeds, shards for
// clusters, resumption and a summary (docs/batch.md).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "batch/batch_items.hpp"
#include "batch/batch_manifest.hpp"
#include "commands.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"

namespace ramus::cli {
namespace {

namespace fs = std::filesystem;

struct BatchOptions {
    std::string manifest;
    std::string outputDirectory = ".";
    int jobs = 0;
    std::string shard = "0/1";
    bool resume = false;
    std::size_t maxItems = kMaxBatchItems;
};

// Set by SIGINT/SIGTERM: no new items start; running items finish their atomic writes. A signal
// handler can only reach a static flag, hence this one piece of process-wide state.
volatile std::sig_atomic_t gStopRequested = 0;

extern "C" void requestStop(int) { gStopRequested = 1; }

struct Shard {
    std::size_t index = 0, count = 1;
};

Shard parseShard(const std::string& text) {
    const std::size_t slash = text.find('/');
    try {
        if (slash != std::string::npos) {
            std::size_t used = 0;
            const unsigned long i = std::stoul(text.substr(0, slash), &used);
            const bool iOk = used == slash;
            const unsigned long n = std::stoul(text.substr(slash + 1), &used);
            if (iOk && used == text.size() - slash - 1 && n >= 1 && i < n) return {i, n};
        }
    } catch (const std::exception&) {
    }
    throw Error("--shard: expected I/N with 0 <= I < N (e.g. 0/4), got \"" + text + "\"");
}

/// Progress on stderr: a bar redrawn in place on a terminal, plain lines otherwise.
class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), tty_(isatty(STDERR_FILENO) != 0) {}

    void done(std::size_t index, const std::string& what, bool ok) {
        std::lock_guard lock(mutex_);
        ++finished_;
        if (!tty_) {
            std::fprintf(stderr, "[%zu/%zu] item %zu %s %s\n", finished_, total_, index,
                         ok ? "ok" : "FAILED", what.c_str());
            return;
        }
        constexpr std::size_t kWidth = 30;
        const std::size_t filled = total_ == 0 ? kWidth : finished_ * kWidth / total_;
        std::fprintf(stderr, "\r[%s%s] %zu/%zu", std::string(filled, '#').c_str(),
                     std::string(kWidth - filled, '.').c_str(), finished_, total_);
        if (finished_ == total_) std::fprintf(stderr, "\n");
    }
    void end() {
        std::lock_guard lock(mutex_);
        if (tty_ && finished_ != total_) std::fprintf(stderr, "\n");
    }

private:
    std::mutex mutex_;
    std::size_t total_, finished_ = 0;
    bool tty_;
};

bool complete(const fs::path& dir, const std::vector<std::string>& outputs) {
    for (const std::string& out : outputs) {
        std::error_code ec;
        if (!fs::is_regular_file(dir / out, ec) || fs::file_size(dir / out, ec) == 0) return false;
    }
    return true;
}

/// Temp files of writeFileAtomic ("NAME.tmp-xxxxxxxx") that a killed run (SIGKILL, power loss)
/// left behind; --resume removes them.
std::size_t removeStaleTempFiles(const fs::path& dir) {
    std::size_t removed = 0;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
         it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const std::size_t at = name.rfind(".tmp-");
        if (at != std::string::npos && name.size() == at + 13 && it->is_regular_file()) {
            removed += fs::remove(it->path(), ec) ? 1 : 0;
        }
    }
    return removed;
}

struct Outcome {
    enum State { Pending, Done, Skipped, Failed } state = Pending;
    std::string error;
};

nlohmann::ordered_json summary(const BatchManifest& manifest, const std::vector<BatchItem>& items,
                               const std::vector<Outcome>& outcomes, const Shard& shard,
                               double seconds, bool interrupted) {
    std::size_t done = 0, skipped = 0, pending = 0;
    nlohmann::json failed = nlohmann::json::array();
    for (std::size_t k = 0; k < items.size(); ++k) {
        switch (outcomes[k].state) {
            case Outcome::Done:
                ++done;
                break;
            case Outcome::Skipped:
                ++skipped;
                break;
            case Outcome::Pending:
                ++pending;
                break;
            case Outcome::Failed:
                failed.push_back({{"index", items[k].index},
                                  {"output", itemOutputs(manifest, items[k]).front()},
                                  {"error", outcomes[k].error}});
                break;
        }
    }
    return {{"manifest", manifest.path},
            {"shard", std::to_string(shard.index) + "/" + std::to_string(shard.count)},
            {"items", items.size()},
            {"done", done},
            {"skipped", skipped},
            {"failed", failed.size()},
            {"not_started", pending},
            {"interrupted", interrupted},
            {"seconds", seconds},
            {"failures", failed}};
}

void run(const BatchOptions& o) {
    const Shard shard = parseShard(o.shard);
    const BatchManifest manifest = loadBatchManifest(o.manifest, o.maxItems);
    checkJobInputs(manifest);
    const JobBoneLibraries bones = loadJobBoneLibraries(manifest);
    const std::vector<BatchItem> items = shardItems(manifest, shard.index, shard.count);
    const SkeletonStats stats = SkeletonStats::builtin();
    const fs::path dir(o.outputDirectory);
    fs::create_directories(dir);

    std::vector<Outcome> outcomes(items.size());
    if (o.resume) {
        removeStaleTempFiles(dir);
        for (std::size_t k = 0; k < items.size(); ++k) {
            if (complete(dir, itemOutputs(manifest, items[k])))
                outcomes[k].state = Outcome::Skipped;
        }
    }
    gStopRequested = 0;
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
    const auto start = std::chrono::steady_clock::now();
    Progress progress(items.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t k = next++; k < items.size() && !gStopRequested; k = next++) {
            const std::string name = itemOutputs(manifest, items[k]).front();
            if (outcomes[k].state == Outcome::Skipped) {
                progress.done(items[k].index, name + " (exists)", true);
                continue;
            }
            try {
                makeItem(manifest, items[k], stats, bones, o.outputDirectory);
                outcomes[k].state = Outcome::Done;
            } catch (const std::exception& e) {
                outcomes[k] = {Outcome::Failed, e.what()};
            }
            progress.done(items[k].index, name, outcomes[k].state == Outcome::Done);
        }
    };
    const unsigned threads = o.jobs > 0 ? static_cast<unsigned>(o.jobs)
                                        : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    progress.end();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);

    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool interrupted = gStopRequested != 0;
    const auto report = summary(manifest, items, outcomes, shard, seconds, interrupted);
    const std::string name = shard.count == 1 ? "batch_summary.json"
                                              : "batch_summary_" + std::to_string(shard.index) +
                                                    "_of_" + std::to_string(shard.count) + ".json";
    writeFileAtomic((dir / name).string(), report.dump(2) + "\n");
    std::printf("%s\n", report.dump().c_str());
    if (interrupted)
        throw Error("interrupted; finished items are complete, run again with --resume");
    if (report["failed"].get<std::size_t>() > 0) {
        throw Error(std::to_string(report["failed"].get<std::size_t>()) + " item(s) failed; see " +
                    (dir / name).string());
    }
}

}  // namespace

void addBatchCommand(CLI::App& app) {
    auto o = std::make_shared<BatchOptions>();
    CLI::App* cmd =
        app.add_subcommand("batch", "make many skeletons and trees from a manifest (.json)");
    cmd->add_option("MANIFEST", o->manifest, "the batch manifest (docs/batch.md)")->required();
    cmd->add_option("-o,--output", o->outputDirectory, "output directory")->capture_default_str();
    cmd->add_option("--jobs", o->jobs, "threads (default: one per core)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--shard", o->shard,
                    "I/N: make every N-th item starting at item I (cluster array jobs)")
        ->capture_default_str();
    cmd->add_flag("--resume", o->resume, "skip items whose outputs already exist");
    cmd->add_option("--max-items", o->maxItems,
                    "stop with an error when the manifest has more items")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->callback([o] { run(*o); });
}

}  // namespace ramus::cli
