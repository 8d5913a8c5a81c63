// Making one batch item (batch_items.hpp, docs/batch.md).
#include "batch/batch_items.hpp"

#include <filesystem>
#include <map>

#include "json_inputs.hpp"
#include "ramus/bones.hpp"
#include "ramus/colonize.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/render.hpp"
#include "ramus/rng.hpp"
#include "ramus/skeleton_io.hpp"
#include "ramus/skeleton_scene.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/turtle.hpp"
#include "skeleton_plan.hpp"
#include "tree_output.hpp"

namespace ramus::cli {
namespace {

namespace fs = std::filesystem;

const BatchJob& jobOf(const BatchManifest& manifest, const BatchItem& item) {
    return manifest.jobs[item.job];
}

/// A file named in a job's inputs, relative to the manifest's folder.
std::string inputFile(const BatchManifest& manifest, const nlohmann::json& inputs,
                      const std::string& key) {
    const fs::path file(requiredString(inputs, key));
    return file.is_absolute() ? file.string()
                              : (fs::path(manifest.path).parent_path() / file).string();
}

void rejectKeys(const nlohmann::json& inputs, std::initializer_list<const char*> keys,
                const std::string& why) {
    for (const char* key : keys) {
        if (inputs.contains(key)) throw Error(std::string("inputs.") + key + ": " + why);
    }
}

void onlyKeys(const nlohmann::json& inputs, std::initializer_list<const char*> keys) {
    for (const auto& [key, value] : inputs.items()) {
        bool known = false;
        std::string list;
        for (const char* k : keys) {
            known = known || key == k;
            list += (list.empty() ? "" : ", ") + std::string(k);
        }
        if (!known) throw Error("inputs." + key + ": unknown key; expected " + list);
    }
}

BoneResolution skeletonResolution(const nlohmann::json& inputs) {
    return choice(inputs, "resolution", BoneResolution::Box, parseBoneResolution,
                  "box, low or high");
}

/// The skeleton inputs without the keys the batch decides itself.
SkeletonPlanRequest skeletonPlan(const BatchManifest& manifest, const nlohmann::json& inputs) {
    rejectKeys(inputs, {"count", "seed", "name"},
               "set by the batch (the job's count, the item's seed, the output's name)");
    for (const auto& [key, value] : inputs.items()) {
        if (key != "resolution" && key != "bones" && !isSkeletonInputKey(key)) {
            throw Error("inputs." + key +
                        ": unknown key; expected one of the skeleton inputs of "
                        "docs/batch.md (legs, wings, arms, fins, …)");
        }
    }
    const BoneResolution resolution = skeletonResolution(inputs);
    if (inputs.contains("bones")) {
        (void)inputFile(manifest, inputs, "bones");
        if (resolution == BoneResolution::Box) {
            throw Error(
                "inputs.bones: the box resolution draws boxes, not bone models; expected "
                "resolution low or high");
        }
    }
    nlohmann::json plain = inputs;
    plain.erase("resolution");
    plain.erase("bones");
    return skeletonPlanFromJson(plain, 1);
}

LSystem lsystemOf(const BatchManifest& manifest, const nlohmann::json& inputs) {
    onlyKeys(inputs, {"file", "derivations", "set"});
    ParseOptions options;
    if (const auto* set = optionalMember(inputs, "set", nlohmann::json::value_t::object)) {
        for (const auto& [name, value] : set->items()) {
            options.constantOverrides.emplace_back(
                name, numberIn(value, "inputs.set." + name, -1e300, 1e300));
        }
    }
    return loadLSystem(inputFile(manifest, inputs, "file"), options);
}

ColonizeConfig colonizeConfigOf(const BatchManifest& manifest, const nlohmann::json& inputs) {
    onlyKeys(inputs, {"config"});
    const std::string file = inputFile(manifest, inputs, "config");
    ColonizeConfig config = loadColonizeConfig(file);
    checkIterationLimit(config, kDefaultMaxIterations, file);
    return config;
}

void writeModel(const Scene& scene, const fs::path& dir, const BatchJob& job,
                const BatchItem& item) {
    const fs::path model = dir / expandOutput(job.output, item);
    fs::create_directories(model.parent_path());
    writeScene(scene, model.string());
    if (!job.png.empty()) {
        const fs::path png = dir / expandOutput(job.png, item);
        fs::create_directories(png.parent_path());
        RenderParams params;
        params.width = params.height = 256;
        writePng(renderScene(scene, params), png.string());
    }
}

void makeSkeleton(const BatchManifest& manifest, const BatchItem& item, const SkeletonStats& stats,
                  const JobBoneLibraries& bones, const fs::path& dir) {
    const BatchJob& job = jobOf(manifest, item);
    SkeletonPlanRequest plan = skeletonPlan(manifest, job.inputs);
    plan.count = 1;
    plan.seed = itemSeed(manifest, item);
    const std::string name = fs::path(expandOutput(job.output, item)).stem().string();
    plan.name = name;
    const PlannedSkeleton planned = planSkeletons(stats, plan).front();
    const Skeleton skeleton = buildSkeleton(planned.design);
    const std::optional<BoneLibrary>& library = bones.at(item.job);
    writeModel(skeletonSceneAt(skeleton, skeletonResolution(job.inputs), planned.design.headKind,
                               library ? &*library : nullptr),
               dir, job, item);
    const fs::path metadata = (dir / expandOutput(job.output, item)).replace_extension(".json");
    writeSkeletonMetadata(metadata.string(), planned.design, skeleton, name, planned.seed);
}

void makeLsystem(const BatchManifest& manifest, const BatchItem& item, const fs::path& dir) {
    const BatchJob& job = jobOf(manifest, item);
    const LSystem system = lsystemOf(manifest, job.inputs);
    DeriveOptions derive;
    if (job.inputs.contains("derivations")) {
        derive.derivations = integerIn(job.inputs["derivations"], "inputs.derivations", 0, 1000);
    }
    derive.overrideSeed = true;
    derive.seed = itemSeed(manifest, item);
    const ModuleString word = deriveLSystem(system, derive);
    const TurtleResult shape =
        interpretTurtle(word, system.symbols, turtleParamsFrom(system.settings));
    AssetSettings assets = finishAssets(AssetSettings{});  // as `ramus lsystem FILE`
    assets.mesh.threads = 1;                               // the batch runs an item per core
    writeModel(plantModel(shape, assets.mesh, assets.lods).scene(), dir, job, item);
}

void makeColonize(const BatchManifest& manifest, const BatchItem& item, const fs::path& dir) {
    const BatchJob& job = jobOf(manifest, item);
    ColonizeConfig config = colonizeConfigOf(manifest, job.inputs);
    config.seed = itemSeed(manifest, item);
    const ColonizeResult result = growFromConfig(config, configAttractionPoints(config));
    AssetSettings assets = colonizeAssets(config);  // as `ramus colonize CONFIG`
    assets.mesh.threads = 1;                        // the batch runs an item per core
    writeModel(forestModel(result.trees, assets.mesh, assets.lods).scene(), dir, job, item);
}

}  // namespace

std::uint64_t itemSeed(const BatchManifest& manifest, const BatchItem& item) {
    return hashCombine(manifest.seed, item.index);
}

std::vector<std::string> itemOutputs(const BatchManifest& manifest, const BatchItem& item) {
    const BatchJob& job = jobOf(manifest, item);
    std::vector<std::string> outputs = {expandOutput(job.output, item)};
    if (fs::path(outputs.front()).extension() == ".obj") {
        outputs.push_back(fs::path(outputs.front()).replace_extension(".mtl").string());
    }
    if (job.kind == BatchKind::Skeleton) {
        outputs.push_back(fs::path(outputs.front()).replace_extension(".json").string());
    }
    if (!job.png.empty()) outputs.push_back(expandOutput(job.png, item));
    return outputs;
}

void checkJobInputs(const BatchManifest& manifest) {
    for (std::size_t j = 0; j < manifest.jobs.size(); ++j) {
        const BatchJob& job = manifest.jobs[j];
        try {
            switch (job.kind) {
                case BatchKind::Skeleton:
                    (void)skeletonPlan(manifest, job.inputs);
                    break;
                case BatchKind::Lsystem:
                    (void)lsystemOf(manifest, job.inputs);
                    break;
                case BatchKind::Colonize:
                    (void)colonizeConfigOf(manifest, job.inputs);
                    break;
            }
        } catch (const Error& e) {
            // The typed readers name the key alone; give the whole path in the manifest.
            const std::string what = e.what();
            const bool located = !e.loc().file.empty() || what.rfind("inputs.", 0) == 0;
            throw Error(manifest.path + ": jobs[" + std::to_string(j) + "]." +
                        (located ? "" : "inputs.") + what);
        }
    }
}

JobBoneLibraries loadJobBoneLibraries(const BatchManifest& manifest) {
    JobBoneLibraries libraries(manifest.jobs.size());
    std::map<std::pair<std::string, BoneResolution>, BoneLibrary> loaded;
    for (std::size_t j = 0; j < manifest.jobs.size(); ++j) {
        const BatchJob& job = manifest.jobs[j];
        if (job.kind != BatchKind::Skeleton || !job.inputs.contains("bones")) continue;
        const std::pair key(inputFile(manifest, job.inputs, "bones"),
                            skeletonResolution(job.inputs));
        auto it = loaded.find(key);
        if (it == loaded.end()) {
            try {
                it = loaded.emplace(key, loadBoneLibrary(key.first, key.second)).first;
            } catch (const Error& e) {
                throw Error(e.loc(), e.message() + " (" + manifest.path + ": jobs[" +
                                         std::to_string(j) + "].inputs.bones)");
            }
        }
        libraries[j] = it->second;
    }
    return libraries;
}

void makeItem(const BatchManifest& manifest, const BatchItem& item, const SkeletonStats& stats,
              const JobBoneLibraries& bones, const std::string& outputDirectory) {
    const fs::path dir(outputDirectory);
    switch (jobOf(manifest, item).kind) {
        case BatchKind::Skeleton:
            makeSkeleton(manifest, item, stats, bones, dir);
            break;
        case BatchKind::Lsystem:
            makeLsystem(manifest, item, dir);
            break;
        case BatchKind::Colonize:
            makeColonize(manifest, item, dir);
            break;
    }
}

}  // namespace ramus::cli
