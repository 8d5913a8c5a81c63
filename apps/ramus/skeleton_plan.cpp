// Which skeletons a request makes (skeleton_plan.hpp).
#include "skeleton_plan.hpp"

#include "json_inputs.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"
#include "ramus/rng.hpp"

namespace ramus::cli {
namespace {

void checkRequest(const SkeletonPlanRequest& r) {
    if (r.count < 1) throw Error("count: expected at least 1, got " + std::to_string(r.count));
    if (r.variations && !r.loaded && !r.inputs.example) {
        throw Error("variations: needs a skeleton to vary; give a saved skeleton or an example");
    }
    if (r.loaded && !r.variations && r.count != 1) {
        throw Error("a saved skeleton without variations regenerates that one skeleton; count " +
                    std::to_string(r.count) + " needs variations");
    }
    if (r.loaded && r.inputs.example) {
        throw Error("a saved skeleton and an example: expected at most one source skeleton");
    }
    // Checked here too, not only when bones are drawn: a box skeleton saves its head kind.
    try {
        (void)skullModelForHeadKind(r.inputs.headKind);
    } catch (const Error& e) {
        throw Error("head: " + e.message());
    }
}

/// The inputs with the head kind an example species implies when none is given (the skull of
/// its class, defaultHeadKind). It lands in the design, so saved metadata keeps it.
SkeletonInputs withExampleHead(const SkeletonStats& stats, SkeletonInputs inputs) {
    if (!inputs.example || !inputs.headKind.empty()) return inputs;
    if (const SpeciesRecord* species = findSpecies(stats.species(), *inputs.example)) {
        inputs.headKind = std::string(defaultHeadKind(species->animalClass));
    }
    return inputs;  // an unknown species fails in designSkeleton, naming the known ones
}

using Type = nlohmann::json::value_t;

/// An even count 0…max, absent = no influence.
std::optional<int> limbCount(const nlohmann::json& request, const std::string& key, int max) {
    if (!request.contains(key) || request[key].is_null()) return std::nullopt;
    const int n = integerIn(request[key], key, 0, max);
    if (n % 2 != 0) throw Error(key + ": expected an even number, got " + std::to_string(n));
    return n;
}

std::optional<double> optionalNumber(const nlohmann::json& request, const std::string& key,
                                     double lo, double hi) {
    if (!request.contains(key) || request[key].is_null()) return std::nullopt;
    return numberIn(request[key], key, lo, hi);
}

SkeletonInputs inputsFrom(const nlohmann::json& r) {
    SkeletonInputs in;
    in.legs = limbCount(r, "legs", 8);
    in.wings = limbCount(r, "wings", 8);
    in.arms = limbCount(r, "arms", 8);
    in.fins = limbCount(r, "fins", 8);
    in.neckYLength = optionalNumber(r, "neck_y", -kMaxFrameLength, kMaxFrameLength);
    in.tailXLength = optionalNumber(r, "tail_x", -kMaxFrameLength, kMaxFrameLength);
    in.heightMetres = optionalNumber(r, "height_m", kMinBodyMetres, kMaxBodyMetres);
    in.lengthMetres = optionalNumber(r, "length_m", kMinBodyMetres, kMaxBodyMetres);
    if (const auto* v = optionalMember(r, "two_per_girdle", Type::boolean)) {
        in.twoPerGirdle = v->get<bool>();
    }
    in.neckShoulder = choice(r, "neck_shoulder", NeckShoulder::Allowed, parseNeckShoulder,
                             "allowed, forced or forbidden");
    if (const auto* v = optionalMember(r, "head", Type::string))
        in.headKind = v->get<std::string>();
    if (const auto* v = optionalMember(r, "example", Type::string)) {
        if (!v->get<std::string>().empty()) in.example = v->get<std::string>();
    }
    in.spacing =
        choice(r, "spacing", SpineSpacing::ArcLength, parseSpineSpacing, "arc_length or parameter");
    const std::string spread =
        optionalMember(r, "spread", Type::string) ? r["spread"].get<std::string>() : "thesis";
    if (spread != "thesis" && spread != "model") {
        throw Error("spread: expected thesis or model, got \"" + spread + "\"");
    }
    in.spread = spread == "thesis" ? SampleSpread::Thesis : SampleSpread::Model;
    return in;
}

}  // namespace

SkeletonPlanRequest skeletonPlanFromJson(const nlohmann::json& r, int maxCount) {
    requireObject(r, "inputs");
    SkeletonPlanRequest plan;
    plan.inputs = inputsFrom(r);
    if (const auto* saved = optionalMember(r, "saved", Type::object)) {
        plan.loaded = parseSkeletonMetadata(saved->dump(), "saved");
    }
    if (const auto* v = optionalMember(r, "variations", Type::boolean)) {
        plan.variations = v->get<bool>();
    }
    if (r.contains("count")) plan.count = integerIn(r["count"], "count", 1, maxCount);
    if (r.contains("seed")) plan.seed = seedFrom(r["seed"], "seed");
    if (const auto* v = optionalMember(r, "name", Type::string)) {
        if (!v->get<std::string>().empty()) plan.name = v->get<std::string>();
    }
    return plan;
}

bool isSkeletonInputKey(const std::string& key) {
    static constexpr std::string_view kKeys[] = {
        "legs",     "wings",          "arms",          "fins", "neck_y",  "tail_x",  "height_m",
        "length_m", "two_per_girdle", "neck_shoulder", "head", "example", "spacing", "spread",
        "saved",    "variations",     "count",         "seed", "name"};
    for (std::string_view k : kKeys) {
        if (k == key) return true;
    }
    return false;
}

std::vector<PlannedSkeleton> planSkeletons(const SkeletonStats& stats,
                                           const SkeletonPlanRequest& request) {
    checkRequest(request);
    const std::optional<LoadedSkeleton>& loaded = request.loaded;
    if (loaded && !request.variations) {
        const std::string name = request.name == "skeleton" ? loaded->name : request.name;
        return {{loaded->design, name, loaded->seed}};
    }
    const std::uint64_t seed = request.seed ? *request.seed : (loaded ? loaded->seed : 1);
    const SkeletonInputs inputs = withExampleHead(stats, request.inputs);
    std::optional<SkeletonDesign> source;
    if (loaded) source = loaded->design;
    if (!source && request.variations) {
        Rng rng = Rng::forStream(seed, ~std::uint64_t{0});
        source = designSkeleton(stats, inputs, rng);
    }
    std::vector<PlannedSkeleton> plan;
    plan.reserve(static_cast<std::size_t>(request.count));
    for (int i = 0; i < request.count; ++i) {
        Rng rng = Rng::forStream(seed, static_cast<std::uint64_t>(i));
        SkeletonDesign design = source ? varySkeletonDesign(stats, *source, inputs, rng)
                                       : designSkeleton(stats, inputs, rng);
        plan.push_back({std::move(design), request.name + std::to_string(i), seed});
    }
    return plan;
}

}  // namespace ramus::cli
