// The fast colonizer against the brute-force reference: same nodes, same order, on many small
// random inputs covering every extension.
#include <gtest/gtest.h>

#include "brute_force_colonize.hpp"
#include "colonize_test_util.hpp"

namespace ramus::testing {
namespace {

struct Case {
    const char* name;
    void (*setup)(ColonizeParams&, std::vector<Shape>&);
};

const Case kCases[] = {
    {"plain", [](ColonizeParams&, std::vector<Shape>&) {}},
    {"tropism", [](ColonizeParams& p, std::vector<Shape>&) { p.tropism = Vec3(0.0, -0.6, 0.2); }},
    {"max_degree_2", [](ColonizeParams& p, std::vector<Shape>&) { p.maxDegree = 2; }},
    {"max_branch_depth_3", [](ColonizeParams& p, std::vector<Shape>&) { p.maxBranchDepth = 3; }},
    {"max_no_growth_2", [](ColonizeParams& p, std::vector<Shape>&) { p.maxNoGrowth = 2; }},
    {"max_no_growth_5", [](ColonizeParams& p, std::vector<Shape>&) { p.maxNoGrowth = 5; }},
    {"weighted",
     [](ColonizeParams& p, std::vector<Shape>&) {
         p.weightedGrowth = true;
         p.maxBranchDepth = 4;
     }},
    {"three_roots",
     [](ColonizeParams& p, std::vector<Shape>&) {
         p.roots = {Vec3(0, 0, 0), Vec3(40, 0, 10), Vec3(-30, 5, -20)};
     }},
    {"far_root_trunk",
     [](ColonizeParams& p, std::vector<Shape>&) { p.roots = {Vec3(10, -120, 0)}; }},
    {"obstacle",
     [](ColonizeParams&, std::vector<Shape>& o) {
         Shape s;
         s.kind = ShapeKind::Box;
         s.offset = Vec3(0, 30, 0);
         s.size = Vec3(40, 6, 40);
         o.push_back(s);
     }},
    {"everything",
     [](ColonizeParams& p, std::vector<Shape>& o) {
         p.tropism = Vec3(0.1, 0.3, 0.0);
         p.maxDegree = 3;
         p.maxBranchDepth = 5;
         p.maxNoGrowth = 3;
         p.weightedGrowth = true;
         p.roots = {Vec3(0, -80, 0), Vec3(20, 0, 0)};
         Shape s;
         s.kind = ShapeKind::Sphere;
         s.offset = Vec3(-20, 40, 10);
         s.radius = 12;
         o.push_back(s);
     }},
};

class ColonizeEquivalence : public ::testing::TestWithParam<int> {};

TEST_P(ColonizeEquivalence, FastAndBruteForceGrowTheSameNodesInTheSameOrder) {
    const Case& c = kCases[GetParam()];
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        ColonizeParams params;
        params.influenceRadius = 30.0 + 5.0 * static_cast<double>(seed % 3);
        params.killRadius = 6.0 + static_cast<double>(seed % 2) * 4.0;
        params.step = 4.0;
        params.maxIterations = 400;
        std::vector<Shape> obstacles;
        c.setup(params, obstacles);
        const std::vector<Vec3> points = randomPoints(150 + 40 * seed, -60.0, 60.0, seed);
        SCOPED_TRACE(std::string(c.name) + " seed " + std::to_string(seed));
        const ColonizeResult fast = colonize(params, points, obstacles);
        const ColonizeResult brute = bruteForceColonize(params, points, obstacles);
        expectSameResult(fast, brute);
        EXPECT_GT(fast.nodeCount(), params.roots.size());
    }
}

INSTANTIATE_TEST_SUITE_P(Extensions, ColonizeEquivalence,
                         ::testing::Range(0, static_cast<int>(std::size(kCases))),
                         [](const ::testing::TestParamInfo<int>& param) {
                             return std::string(kCases[param.param].name);
                         });

TEST(ColonizeEquivalence, PlanarDiscGivesTheSameTreeAsBruteForce) {
    Envelope disc;
    disc.shape.kind = ShapeKind::Disc;
    disc.shape.radius = 120.0;
    disc.shape.offset = Vec3(0, 140, 0);
    disc.pointCount = 300;
    const std::vector<Vec3> points = sampleEnvelope(disc, 3);
    ColonizeParams params;
    params.influenceRadius = 40;
    params.killRadius = 8;
    params.step = 5;
    expectSameResult(colonize(params, points), bruteForceColonize(params, points));
}

TEST(ColonizeEquivalence, FarFromTheOriginFloatRoundingDoesNotChangeTheTree) {
    // Coordinates around 10^5 with steps of 1: float spacing there is ~0.008, so the float
    // preselection works near its margin; every decision must still match the reference.
    const Vec3 shift(1.0e5, -7.0e4, 3.0e4);
    std::vector<Vec3> points = randomPoints(400, -20, 20, 17);
    for (Vec3& p : points) p += shift;
    ColonizeParams params;
    params.influenceRadius = 6;
    params.killRadius = 2;
    params.step = 1;
    params.roots = {shift + Vec3(0, -25, 0), shift + Vec3(3, -22, 1)};
    params.maxNoGrowth = 3;
    const ColonizeResult fast = colonize(params, points);
    expectSameResult(fast, bruteForceColonize(params, points));
    EXPECT_GT(fast.nodeCount(), 100u);
}

TEST(ColonizeEquivalence, IterationLimitsCutBothAtTheSameNode) {
    const std::vector<Vec3> points = randomPoints(300, -50, 50, 11);
    for (int limit : {0, 1, 2, 5, 13}) {
        ColonizeParams params;
        params.influenceRadius = 25;
        params.killRadius = 5;
        params.step = 3;
        params.maxIterations = limit;
        params.maxNoGrowth = 4;
        SCOPED_TRACE(limit);
        expectSameResult(colonize(params, points), bruteForceColonize(params, points));
    }
}

}  // namespace
}  // namespace ramus::testing
