// GLB encoding speed: a skeleton-sized scene (101 joint nodes with extras, one skin, one
// skinned mesh with one primitive per bone kind) — where the JSON document dominates — and a
// large single tree-like mesh — where the binary chunk dominates. Also skeletonToScene on the
// same skeleton. Counters: scenes/s (items) and bytes/s of GLB output.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench_trees.hpp"
#include "ramus/export.hpp"
#include "ramus/rng.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_scene.hpp"
#include "ramus/tube_mesher.hpp"

namespace {

using ramus::Bone;
using ramus::BoneKind;
using ramus::Mat3;
using ramus::Side;
using ramus::SpineRegion;
using ramus::Vec3;

Mat3 turn(const Vec3& axis, double degrees) {
    return Eigen::AngleAxisd(degrees * M_PI / 180.0, axis).toRotationMatrix();
}

Bone bone(BoneKind kind, int parent, const Vec3& position, const Mat3& rest, const Vec3& extents) {
    Bone b;
    b.kind = kind;
    b.parent = parent;
    b.joint.position = position;
    b.joint.rest = rest;
    b.extents = extents;
    return b;
}

void addDof(Bone& b, const Vec3& axis, double angle, double lo, double hi) {
    b.joint.dofs[b.joint.dofCount++] = ramus::JointDof{axis, angle, lo, hi};
}

// A chain of `count` vertebrae of `region` from bone `parent`, bending slightly; returns the
// indices of the new bones.
std::vector<int> addSpine(ramus::Skeleton& s, int parent, SpineRegion region, int count,
                          double bendDeg, ramus::Rng& rng) {
    std::vector<int> chain;
    for (int i = 1; i <= count; ++i) {
        const bool first = chain.empty();
        Bone v = bone(BoneKind::Vertebra, first ? parent : chain.back(),
                      first ? Vec3::Zero() : Vec3(rng.uniform(18.0, 24.0), 0.0, 0.0),
                      turn(Vec3::UnitZ(), first && region == SpineRegion::Neck ? 180.0 : bendDeg),
                      Vec3(rng.uniform(18.0, 24.0), rng.uniform(14.0, 20.0), 16.0));
        v.region = region;
        v.index = i;
        addDof(v, Vec3::UnitZ(), rng.uniform(-3.0, 3.0), -10.0, 10.0);
        addDof(v, Vec3::UnitY(), 0.0, -5.0, 5.0);
        s.bones.push_back(v);
        chain.push_back(static_cast<int>(s.bones.size()) - 1);
    }
    return chain;
}

// A leg (girdle, upper, lower, foot) on `parent`, on the left (+z) or right side.
void addLeg(ramus::Skeleton& s, int parent, bool front, Side side, ramus::Rng& rng) {
    const double z = side == Side::Left ? 12.0 : -12.0;
    const BoneKind kinds[4] = {
        front ? BoneKind::Scapula : BoneKind::Pelvis, front ? BoneKind::UpperArm : BoneKind::Thigh,
        front ? BoneKind::Forearm : BoneKind::Shank, front ? BoneKind::Hand : BoneKind::Foot};
    int p = parent;
    for (int k = 0; k < 4; ++k) {
        Bone b = bone(kinds[k], p, k == 0 ? Vec3(10.0, 0.0, z) : Vec3(rng.uniform(40, 60), 0, 0),
                      turn(Vec3::UnitZ(), k == 0 ? -90.0 : rng.uniform(-40.0, 40.0)),
                      Vec3(rng.uniform(40.0, 60.0), 8.0, 8.0));
        b.side = side;
        b.limb = ramus::LimbKind::Leg;
        b.attachment = front ? ramus::Attachment::Shoulder : ramus::Attachment::Hip;
        if (k > 0) addDof(b, Vec3::UnitZ(), rng.uniform(-20.0, 20.0), -60.0, 60.0);
        if (k == 1) addDof(b, Vec3::UnitY(), 5.0, -15.0, 15.0);
        s.bones.push_back(b);
        p = static_cast<int>(s.bones.size()) - 1;
    }
}

// 101 bones, like a generated quadruped: root, 24 back, 13 neck and 16 tail vertebrae, a
// skull, 15 rib pairs and four legs.
ramus::Skeleton quadruped() {
    ramus::Rng rng(7);
    ramus::Skeleton s;
    s.metresPerPixel = 0.0035;
    s.groundHeight = -260.0;
    s.bones.push_back(bone(BoneKind::Root, -1, {500, 300, 0}, Mat3::Identity(), Vec3::Zero()));
    const std::vector<int> back = addSpine(s, 0, SpineRegion::Back, 24, 1.5, rng);
    const std::vector<int> neck = addSpine(s, 0, SpineRegion::Neck, 13, -4.0, rng);
    s.bones.push_back(
        bone(BoneKind::Skull, neck.back(), {22, 0, 0}, turn(Vec3::UnitZ(), 30.0), {60, 30, 30}));
    addSpine(s, back.back(), SpineRegion::Tail, 16, 3.0, rng);
    for (int r = 0; r < 15; ++r) {
        for (Side side : {Side::Left, Side::Right}) {
            Bone rib = bone(BoneKind::Rib, back[r], {10, 0, side == Side::Left ? 8.0 : -8.0},
                            turn(Vec3::UnitY(), side == Side::Left ? -90.0 : 90.0), {50, 4, 3});
            rib.region = SpineRegion::Back;
            rib.index = r + 1;
            rib.side = side;
            s.bones.push_back(rib);
        }
    }
    for (Side side : {Side::Left, Side::Right}) {
        addLeg(s, neck.front(), true, side, rng);
        addLeg(s, back.back(), false, side, rng);
    }
    return s;
}

void BM_SkeletonToScene(benchmark::State& state) {
    const ramus::Skeleton skeleton = quadruped();
    for (auto _ : state) {
        ramus::Scene scene = ramus::skeletonToScene(skeleton);
        benchmark::DoNotOptimize(scene.nodes.data());
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["bones"] = static_cast<double>(skeleton.bones.size());
}
BENCHMARK(BM_SkeletonToScene)->Unit(benchmark::kMicrosecond);

void BM_EncodeGlbSkeletonScene(benchmark::State& state) {
    const ramus::Scene scene = ramus::skeletonToScene(quadruped());
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::string glb = ramus::encodeGlb(scene);
        bytes = glb.size();
        benchmark::DoNotOptimize(glb.data());
    }
    state.SetItemsProcessed(state.iterations());
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
    state.counters["nodes"] = static_cast<double>(scene.nodes.size());
    state.counters["glb_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_EncodeGlbSkeletonScene)->Unit(benchmark::kMicrosecond);

// A random monopodial branch tree of `edges` edges meshed as tubes: ~edges × 8 vertices.
ramus::Mesh treeMesh(std::int64_t edges) {
    return ramus::buildTubeMesh(ramus::bench::monopodialTree(edges, 3), ramus::TubeMeshParams{});
}

void BM_EncodeGlbTreeMesh(benchmark::State& state) {
    const ramus::Scene scene = ramus::makeSingleMeshScene(treeMesh(state.range(0)), "tree");
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::string glb = ramus::encodeGlb(scene);
        bytes = glb.size();
        benchmark::DoNotOptimize(glb.data());
    }
    state.SetItemsProcessed(state.iterations());
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
    state.counters["vertices"] = static_cast<double>(scene.meshes[0].positions.size());
}
BENCHMARK(BM_EncodeGlbTreeMesh)->Arg(1 << 14)->Unit(benchmark::kMillisecond);

}  // namespace
