// Which skeletons a request makes (skeleton_plan.hpp).
#include "skeleton_plan.hpp"

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
}

}  // namespace

std::vector<PlannedSkeleton> planSkeletons(const SkeletonStats& stats,
                                           const SkeletonPlanRequest& request) {
    checkRequest(request);
    const std::optional<LoadedSkeleton>& loaded = request.loaded;
    if (loaded && !request.variations) {
        const std::string name = request.name == "skeleton" ? loaded->name : request.name;
        return {{loaded->design, name, loaded->seed}};
    }
    const std::uint64_t seed = request.seed ? *request.seed : (loaded ? loaded->seed : 1);
    std::optional<SkeletonDesign> source;
    if (loaded) source = loaded->design;
    if (!source && request.variations) {
        Rng rng = Rng::forStream(seed, ~std::uint64_t{0});
        source = designSkeleton(stats, request.inputs, rng);
    }
    std::vector<PlannedSkeleton> plan;
    plan.reserve(static_cast<std::size_t>(request.count));
    for (int i = 0; i < request.count; ++i) {
        Rng rng = Rng::forStream(seed, static_cast<std::uint64_t>(i));
        SkeletonDesign design = source ? varySkeletonDesign(stats, *source, request.inputs, rng)
                                       : designSkeleton(stats, request.inputs, rng);
        plan.push_back({std::move(design), request.name + std::to_string(i), seed});
    }
    return plan;
}

}  // namespace ramus::cli
