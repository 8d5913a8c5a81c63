// The studio's skeleton endpoint (studio_api.hpp, docs/studio.md): the inputs of
// `ramus skeleton` (seed 000 fig. 6.1) as JSON → skinned GLB and metadata per skeleton.
#include <optional>

#include "ramus/bones.hpp"
#include "ramus/export.hpp"
#include "ramus/skeleton_io.hpp"
#include "ramus/skeleton_scene.hpp"
#include "serve/studio_api.hpp"
#include "serve/studio_request.hpp"
#include "skeleton_plan.hpp"

namespace ramus::studio {
namespace {

using Type = nlohmann::json::value_t;

/// An even count 0…max, absent = no influence.
std::optional<int> limbCount(const nlohmann::json& request, const std::string& key, int max) {
    if (!request.contains(key) || request[key].is_null()) return std::nullopt;
    const int n = integerIn(request[key], key, 0, max);
    if (n % 2 != 0)
        throw ApiError(400, key + ": expected an even number, got " + std::to_string(n));
    return n;
}

std::optional<double> optionalNumber(const nlohmann::json& request, const std::string& key,
                                     double lo, double hi) {
    if (!request.contains(key) || request[key].is_null()) return std::nullopt;
    return numberIn(request[key], key, lo, hi);
}

template <typename Enum, typename Parse>
Enum choice(const nlohmann::json& request, const std::string& key, Enum fallback, Parse parse,
            const std::string& expected) {
    const auto* value = optionalMember(request, key, Type::string);
    if (!value) return fallback;
    const auto parsed = parse(value->get<std::string>());
    if (!parsed) throw ApiError(400, key + ": expected " + expected + ", got " + value->dump());
    return *parsed;
}

SkeletonInputs inputsFrom(const nlohmann::json& r) {
    SkeletonInputs in;
    in.legs = limbCount(r, "legs", 8);
    in.wings = limbCount(r, "wings", 8);
    in.arms = limbCount(r, "arms", 8);
    in.fins = limbCount(r, "fins", 8);
    in.neckYLength = optionalNumber(r, "neck_y", -2000.0, 2000.0);
    in.tailXLength = optionalNumber(r, "tail_x", -2000.0, 2000.0);
    in.heightMetres = optionalNumber(r, "height_m", 1e-3, 1e3);
    in.lengthMetres = optionalNumber(r, "length_m", 1e-3, 1e3);
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
        throw ApiError(400, "spread: expected thesis or model, got \"" + spread + "\"");
    }
    in.spread = spread == "thesis" ? SampleSpread::Thesis : SampleSpread::Model;
    return in;
}

cli::SkeletonPlanRequest planFrom(const nlohmann::json& r, const StudioLimits& limits) {
    cli::SkeletonPlanRequest plan;
    plan.inputs = inputsFrom(r);
    if (const auto* saved = optionalMember(r, "saved", Type::object)) {
        plan.loaded = withTextErrors([&] { return parseSkeletonMetadata(saved->dump(), "saved"); });
    }
    if (const auto* v = optionalMember(r, "variations", Type::boolean)) {
        plan.variations = v->get<bool>();
    }
    if (r.contains("count")) plan.count = integerIn(r["count"], "count", 1, limits.maxSkeletons);
    if (r.contains("seed")) plan.seed = seedFrom(r["seed"], "seed");
    if (const auto* v = optionalMember(r, "name", Type::string)) {
        if (!v->get<std::string>().empty()) plan.name = v->get<std::string>();
    }
    return plan;
}

}  // namespace

nlohmann::json skeletonRequest(const nlohmann::json& request, const StudioLimits& limits) {
    const Deadline deadline(limits.timeSeconds);
    requireObject(request, "request");
    const cli::SkeletonPlanRequest plan = planFrom(request, limits);
    const BoneResolution resolution =
        choice(request, "resolution", BoneResolution::Box, parseBoneResolution, "box, low or high");
    const std::vector<cli::PlannedSkeleton> planned =
        withTextErrors([&] { return cli::planSkeletons(SkeletonStats::builtin(), plan); });
    if (resolution != BoneResolution::Box) {
        throw ApiError(400,
                       "resolution: bone models (low, high) are not in the studio yet; "
                       "expected box");
    }
    nlohmann::json skeletons = nlohmann::json::array();
    std::size_t triangles = 0;
    for (const cli::PlannedSkeleton& p : planned) {
        const Skeleton skeleton = withTextErrors([&] { return buildSkeleton(p.design); });
        const SkeletonSceneParams params;
        const Scene scene = withTextErrors([&] { return skeletonToScene(skeleton, params); });
        for (const Mesh& mesh : scene.meshes) triangles += mesh.triangleCount();
        checkTriangles(triangles, limits);
        skeletons.push_back({{"name", p.name},
                             {"glb", base64(encodeGlb(scene))},
                             {"metadata", nlohmann::json::parse(skeletonMetadataJson(
                                              p.design, skeleton, p.name, p.seed))}});
        deadline.check("skeleton " + p.name);
    }
    return {{"skeletons", std::move(skeletons)}};
}

nlohmann::json headKindNames() {
    nlohmann::json names = nlohmann::json::array();
    for (std::string_view kind : kHeadKinds) names.push_back(std::string(kind));
    return names;
}

}  // namespace ramus::studio
