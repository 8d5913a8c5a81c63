// `ramus skeleton …`: generate vertebrate skeletons from the statistics and the bone grammar,
// write NAME<i>.glb, .obj, .json (and .png) per skeleton (docs/skeleton.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/render.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"
#include "ramus/skeleton_scene.hpp"
#include "skeleton_plan.hpp"

namespace ramus::cli {

namespace {

struct SkeletonOptions {
    // Values are kept as 0-or-1-element vectors so "absent" differs from 0 (seed 000 §6.1).
    std::vector<int> legs, wings, arms, fins;
    std::vector<double> neckY, tailX, height, length;
    bool twoPerGirdle = false;
    std::string neckShoulder = "allowed";
    std::string head;
    std::string example;
    std::string load;
    std::string species;
    bool variations = false;
    int count = 1;
    int maxCount = kDefaultMaxSkeletons;
    std::string name = "skeleton";
    std::string resolution = "box";
    std::string bones;  // user bone library directory; empty = the default library
    std::vector<std::uint64_t> seed;
    std::string spacing = "arc_length";
    std::string spread = "thesis";
    bool png = false;
    std::string view = "side";
    std::string size = "800x800";
    std::string outputDirectory;
};

template <typename T>
std::optional<T> optionalOf(const std::vector<T>& values) {
    if (values.empty()) return std::nullopt;
    return values.front();
}

SkeletonInputs inputsFrom(const SkeletonOptions& o) {
    SkeletonInputs inputs;
    inputs.legs = optionalOf(o.legs);
    inputs.wings = optionalOf(o.wings);
    inputs.arms = optionalOf(o.arms);
    inputs.fins = optionalOf(o.fins);
    inputs.neckYLength = optionalOf(o.neckY);
    inputs.tailXLength = optionalOf(o.tailX);
    inputs.heightMetres = optionalOf(o.height);
    inputs.lengthMetres = optionalOf(o.length);
    inputs.twoPerGirdle = o.twoPerGirdle;
    inputs.neckShoulder = *parseNeckShoulder(o.neckShoulder);
    inputs.headKind = o.head;
    if (!o.example.empty()) inputs.example = o.example;
    inputs.spacing = *parseSpineSpacing(o.spacing);
    inputs.spread = o.spread == "thesis" ? SampleSpread::Thesis : SampleSpread::Model;
    return inputs;
}

/// One skeleton's files: NAME<i>.glb, .obj, .json and optionally .png in the output directory.
void writeSkeletonFiles(const SkeletonOptions& o, const SkeletonDesign& design,
                        const std::string& name, std::uint64_t seed, const BoneLibrary* bones) {
    const Skeleton skeleton = buildSkeleton(design);
    const Scene scene =
        skeletonSceneAt(skeleton, *parseBoneResolution(o.resolution), design.headKind, bones);
    const std::filesystem::path base = std::filesystem::path(o.outputDirectory) / name;
    writeGlb(scene, base.string() + ".glb");
    writeObj(scene, base.string() + ".obj");
    writeSkeletonMetadata(base.string() + ".json", design, skeleton, name, seed);
    if (o.png) {
        const ImageSize size = parseImageSize(o.size);
        RenderParams params;
        params.width = size.width;
        params.height = size.height;
        params.view = parseView(o.view);
        writePng(renderScene(scene, params), base.string() + ".png");
    }
}

void printProgress(int done, int total) {
    if (total < 2) return;
    constexpr int kWidth = 30;
    const int filled = done * kWidth / total;
    std::fprintf(stderr, "\r[%s%s] %d/%d", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), done, total);
    if (done == total) std::fprintf(stderr, "\n");
}

void checkOptions(const SkeletonOptions& o) {
    if (o.count < 1) throw Error("--count: expected at least 1, got " + std::to_string(o.count));
    if (o.count > o.maxCount) {
        throw Error("--count: " + std::to_string(o.count) + " skeletons are above the limit of " +
                    std::to_string(o.maxCount) +
                    "; expected fewer, or raise the limit with --max-count (or use ramus batch)");
    }
    if (o.variations && o.load.empty() && o.example.empty()) {
        throw Error("--variations: needs a skeleton to vary; give --load FILE.json or --example");
    }
    if (!o.load.empty() && !o.variations && o.count != 1) {
        throw Error("--load without --variations regenerates the one saved skeleton; --count " +
                    std::to_string(o.count) + " needs --variations");
    }
    if (!o.load.empty() && !o.example.empty()) {
        throw Error("--load and --example: expected at most one source skeleton, got both");
    }
    if (!o.bones.empty() && o.resolution == "box") {
        throw Error(
            "--bones: the box resolution draws boxes, not bone models; give --resolution "
            "low or high");
    }
}

void run(const SkeletonOptions& o) {
    checkOptions(o);
    const SkeletonInputs inputs = inputsFrom(o);
    const SkeletonStats stats =
        o.species.empty() ? SkeletonStats::builtin() : SkeletonStats::load(o.species);
    std::filesystem::create_directories(o.outputDirectory);

    SkeletonPlanRequest request;
    request.inputs = inputs;
    if (!o.load.empty()) request.loaded = readSkeletonMetadata(o.load);
    request.variations = o.variations;
    request.count = o.count;
    if (!o.seed.empty()) request.seed = o.seed.front();
    request.name = o.name;
    const std::vector<PlannedSkeleton> plan = planSkeletons(stats, request);
    // Loaded once, before any file is written, and shared by every skeleton of the run.
    std::optional<BoneLibrary> bones;
    if (!o.bones.empty()) bones = loadBoneLibrary(o.bones, *parseBoneResolution(o.resolution));
    for (std::size_t i = 0; i < plan.size(); ++i) {
        writeSkeletonFiles(o, plan[i].design, plan[i].name, plan[i].seed,
                           bones ? &*bones : nullptr);
        printProgress(static_cast<int>(i + 1), static_cast<int>(plan.size()));
    }
}

void addInputOptions(CLI::App& cmd, SkeletonOptions& o) {
    cmd.add_option("--legs", o.legs, "legs with ground contact (even, 0-8)")->expected(1);
    cmd.add_option("--wings", o.wings, "wings (even)")->expected(1);
    cmd.add_option("--arms", o.arms, "arms (even)")->expected(1);
    cmd.add_option("--fins", o.fins, "fins (even)")->expected(1);
    // The same ranges as the studio's and the batch manifests' inputs (skeleton_plan.cpp).
    cmd.add_option("--neck-y", o.neckY, "neck y length in px of the 1000 px frame")
        ->expected(1)
        ->check(finiteIn(-kMaxFrameLength, kMaxFrameLength));
    cmd.add_option("--tail-x", o.tailX, "tail x length in px of the 1000 px frame")
        ->expected(1)
        ->check(finiteIn(-kMaxFrameLength, kMaxFrameLength));
    cmd.add_flag("--two-per-girdle", o.twoPerGirdle, "allow two limb pairs per girdle (G')");
    cmd.add_option("--neck-shoulder", o.neckShoulder, "second shoulder girdle on the neck (G'')")
        ->check(CLI::IsMember({"allowed", "forced", "forbidden"}));
    cmd.add_option("--head", o.head, "skull kind of the bone library");
    cmd.add_option("--example", o.example, "construct from this species (English or German)");
    cmd.add_option("--height", o.height, "scale to this standing height in metres")
        ->expected(1)
        ->check(finiteIn(kMinBodyMetres, kMaxBodyMetres));
    cmd.add_option("--length", o.length, "scale to this body length in metres")
        ->expected(1)
        ->check(finiteIn(kMinBodyMetres, kMaxBodyMetres));
    cmd.add_option("--spacing", o.spacing, "vertebra spacing along the spine curves")
        ->check(CLI::IsMember({"arc_length", "parameter"}));
    cmd.add_option("--spread", o.spread,
                   "PCA sampling: thesis = lambda*N(0, 1) (default, plausible), model = N(0, "
                   "lambda) (wilder)")
        ->check(CLI::IsMember({"model", "thesis"}));
    cmd.add_option("--species", o.species, "species data file instead of the built-in 44");
}

}  // namespace

void addSkeletonCommand(CLI::App& app) {
    auto o = std::make_shared<SkeletonOptions>();
    CLI::App* cmd = app.add_subcommand("skeleton", "generate vertebrate skeletons");
    addInputOptions(*cmd, *o);
    cmd->add_option("--load", o->load, "regenerate (or vary) a saved skeleton (.json)");
    cmd->add_flag("--variations", o->variations, "make variations of --load or --example");
    cmd->add_option("--count", o->count, "number of skeletons");
    cmd->add_option("--max-count", o->maxCount,
                    "stop with an error when --count asks for more skeletons")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--name", o->name, "file name stem; files are NAME<i>.glb/.obj/.json");
    cmd->add_option("--resolution", o->resolution,
                    "bone meshes: box, low or high (the default bone library)")
        ->check(CLI::IsMember({"box", "low", "high"}))
        ->capture_default_str();
    cmd->add_option("--bones", o->bones,
                    "user bone library directory (bones.json; docs/bones.md) instead of the "
                    "default library; needs --resolution low or high");
    cmd->add_option("--seed", o->seed, "seed (non-negative integer)")->expected(1);
    cmd->add_flag("--png", o->png, "also write a PNG preview per skeleton");
    cmd->add_option("--view", o->view, "preview camera: side, front, top, three-quarter");
    cmd->add_option("--size", o->size, "preview size WxH");
    cmd->add_option("-o,--output", o->outputDirectory, "output directory")->required();
    cmd->callback([o] { run(*o); });
}

}  // namespace ramus::cli
