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

using cli::choice;

nlohmann::json skeletonRequest(const nlohmann::json& request, const StudioLimits& limits) {
    const Deadline deadline(limits.timeSeconds);
    requireObject(request, "request");
    const cli::SkeletonPlanRequest plan = cli::skeletonPlanFromJson(request, limits.maxSkeletons);
    const BoneResolution resolution =
        choice(request, "resolution", BoneResolution::Box, parseBoneResolution, "box, low or high");
    const std::vector<cli::PlannedSkeleton> planned =
        withTextErrors([&] { return cli::planSkeletons(SkeletonStats::builtin(), plan); });
    nlohmann::json skeletons = nlohmann::json::array();
    std::size_t triangles = 0;
    for (const cli::PlannedSkeleton& p : planned) {
        const Skeleton skeleton = withTextErrors([&] { return buildSkeleton(p.design); });
        const Scene scene = withTextErrors(
            [&] { return skeletonSceneAt(skeleton, resolution, p.design.headKind); });
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
