// Tree assets (issue 9): one mesh of bark and leaves, and levels of detail. The LOD reduction
// is tree-aware rather than a generic simplifier (e.g. Garland & Heckbert's edge collapse):
// trees are many thin disconnected tubes and cards, which collapse badly, while the tree
// structure says directly what to drop first — fewer ring segments, then the thinnest twigs,
// and fewer but larger leaves (as foliage LODs in game pipelines do). Vertices that remain are
// exactly those of the full mesh, so UVs and wind data never drift between levels.
#include "ramus/tree_asset.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <future>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>

#include "on_cores.hpp"
#include "ramus/error.hpp"
#include "ramus/welded_mesher.hpp"

namespace ramus {

namespace {

// `total` and then `more`: counts add up, the first failure stays the first.
void addReport(TreeMeshReport& total, const TreeMeshReport& more) {
    if (total.unionsFailed == 0) total.firstFailure = more.firstFailure;
    total.weldedMeshes += more.weldedMeshes;
    total.weldFallbacks += more.weldFallbacks;
    total.weldCrossings += more.weldCrossings;
    total.weldCrossingTubes += more.weldCrossingTubes;
    total.weldSharedRings += more.weldSharedRings;
    total.shrunkJunctions += more.shrunkJunctions;
    total.unionsApplied += more.unionsApplied;
    total.unionsFailed += more.unionsFailed;
    total.unionsOfHulls += more.unionsOfHulls;
    total.tubedForUnion += more.tubedForUnion;
    total.crossingsLeft += more.crossingsLeft;
    total.pinchedEdges += more.pinchedEdges;
    total.touchingPoints += more.touchingPoints;
    total.crossingMoves += more.crossingMoves;
    total.collapsedEdges += more.collapsedEdges;
    total.unionAttempts += more.unionAttempts;
    total.postponedMoves += more.postponedMoves;
    total.reunions += more.reunions;
}

// What one level draws.
struct Detail {
    int minSegments = 4, maxSegments = 16;
    std::size_t prune = 0;  // entries of the prune order left out
    bool cards = false;
    double keep = 1.0;
    bool solidUnion = false;  // unite each tree's welded bark (final meshes, not LOD trials)
    bool reported = false;    // a final mesh: how its welding went goes into the report
};

class TreeMesher {
public:
    TreeMesher(std::span<const TreeMeshInput> trees, const TreeMeshParams& params)
        : trees_(trees), params_(params) {
        for (const TreeMeshInput& in : trees)
            radii_.push_back(computeEdgeRadii(*in.tree, params.tube));
    }

    // The trees' bark, each tree's on a thread of its own where there are several: a forest's
    // trees are meshed (and united) independently, and much of a union runs on one core
    // (its bookkeeping over the whole surface). Appended, and added to `report` (where given),
    // in the trees' order.
    Mesh bark(const Detail& d, TreeMeshReport* report = nullptr) const {
        std::vector<Mesh> meshes(trees_.size());
        std::vector<TreeMeshReport> reports(trees_.size());
        detail::forEachOnThreads(
            trees_.size(), std::min(trees_.size(), treeThreads_),
            [&](std::size_t t) {
                forTree(t, d, [&](const BranchTree& tree, const TubeMeshParams& tube) {
                    meshes[t] = branches(tree, tube, d, reports[t]);
                });
            },
            1);
        Mesh mesh;
        mesh.name = "tree";
        for (std::size_t t = 0; t < trees_.size(); ++t) {
            appendMesh(mesh, std::move(meshes[t]));  // the first tree's arrays are taken
            if (report != nullptr) addReport(*report, reports[t]);
        }
        return mesh;
    }

    // The bark's triangles at detail d: tubes are counted without being built (the LOD
    // planning tries up to a few dozen details per level), welded bark is meshed, each detail
    // once: the levels (on threads of their own) bisect the same segment steps, and a united
    // level plans its bark again each round, near the details it tried before (ABOP 1.24a,
    // `--union --lods 1,0.4,0.15`: the levels' bark planning had taken 4.2 s on their two
    // threads, their unions 1.4 s).
    std::size_t barkTriangles(const Detail& d) const {
        if (params_.weldJunctions) {
            std::promise<std::size_t> counting;
            std::shared_future<std::size_t> count;
            {
                const std::lock_guard lock(weldedCountsMutex_);
                const auto [at, added] = weldedCounts_.try_emplace(
                    std::tuple{d.minSegments, d.maxSegments, d.prune, d.solidUnion});
                if (added) at->second = counting.get_future().share();
                count = at->second;
                if (!added) return count.get();  // counted, or being counted by another level
            }
            try {
                counting.set_value(bark(d).triangleCount());
            } catch (...) {
                counting.set_exception(std::current_exception());
            }
            return count.get();
        }
        std::size_t count = 0;
        forEachBark(d, [&](const BranchTree& tree, const TubeMeshParams& tube) {
            count += countTubeTriangles(tree, tube);
        });
        return count;
    }

    // One tree's bark: tubes, or one welded surface (united when d.solidUnion); how its welding
    // and union went goes into `report` (of this tree alone).
    Mesh branches(const BranchTree& tree, const TubeMeshParams& tube, const Detail& d,
                  TreeMeshReport& report) const {
        if (!params_.weldJunctions) return buildTubeMesh(tree, tube);
        WeldedMeshParams welded;
        welded.tube = tube;
        welded.solidUnion = d.solidUnion;
        welded.shrinkJunctions = !params_.convexJunctions;
        WeldReport weld;
        Mesh mesh = buildWeldedTreeMesh(tree, welded, &weld);
        if (d.reported) {
            ++report.weldedMeshes;
            report.weldFallbacks += weld.fallbacks;
            report.weldCrossings += weld.crossings;
            report.weldCrossingTubes += weld.crossingTubes;
            report.weldSharedRings += weld.sharedRings;
            report.shrunkJunctions += weld.refinedJunctions;
        }
        if (d.solidUnion) {
            if (weld.solidUnion.applied) {
                ++report.unionsApplied;
                if (weld.convexForUnion) ++report.unionsOfHulls;
                report.tubedForUnion += weld.tubedForUnion;
                report.crossingsLeft += weld.solidUnion.remainingIntersections;
                report.pinchedEdges += weld.solidUnion.pinchedEdges;
                report.touchingPoints += weld.solidUnion.touchingPoints;
                report.crossingMoves += weld.solidUnion.crossingMoves;
                report.collapsedEdges += weld.solidUnion.collapsedEdges;
                report.unionAttempts += weld.solidUnion.attempts;
                report.postponedMoves += weld.solidUnion.postponedMoves;
                report.reunions += weld.solidUnion.reunions;
            } else if (!mesh.primitives.empty()) {
                if (report.unionsFailed++ == 0) report.firstFailure = weld.solidUnion.failure;
            }
        }
        return mesh;
    }

    Mesh leaves(const Detail& d) const {
        LeafParams leaf = params_.leaf;
        leaf.keep = d.keep;
        if (d.cards) leaf.shape = LeafShape::Card;
        LeafParams polygons = leaf;
        polygons.material = params_.polygonMaterial;
        Mesh mesh;
        mesh.name = "tree";
        for (const TreeMeshInput& in : trees_) {
            if (in.polygonOffsets.size() > 1) {
                appendMesh(mesh, buildLeafPolygons(*in.tree, in.polygonVertices, in.polygonOffsets,
                                                   in.polygonNodes, polygons, params_.tube));
            }
            if (params_.leaves) appendMesh(mesh, buildLeafMesh(*in.tree, leaf, params_.tube));
        }
        return mesh;
    }

    Mesh both(const Detail& d, TreeMeshReport* report) const {
        Mesh mesh = bark(d, report);
        appendMesh(mesh, leaves(d));
        mergePrimitivesByMaterial(mesh);
        return mesh;
    }

    // Meshing `ways` details at once (LOD levels on threads of their own): each meshes its
    // trees on its share of the cores, so that a forest's levels do not run levels × trees
    // unions at once (memory) on a machine with many cores.
    void shareCores(std::size_t ways) {
        treeThreads_ = std::max<std::size_t>(1, threads() / std::max<std::size_t>(1, ways));
    }
    // How many details, or trees, are meshed at once (TreeMeshParams::threads).
    std::size_t threads() const {
        return params_.threads > 0 ? params_.threads : detail::machineCores();
    }
    // The order the LOD levels prune edges by (buildPruneOrder), made before they share it.
    void preparePruning() { buildPruneOrder(); }
    std::size_t pruneOrderSize() const { return order_.size(); }
    // Whether barkTriangles meshes the bark (welded) rather than counting tubes.
    bool trialsAreMeshes() const { return params_.weldJunctions; }

private:
    // barkTriangles of welded bark, by segments, pruned edges and union (each meshed by the
    // first level to ask for it; the others wait for it).
    mutable std::mutex weldedCountsMutex_;
    mutable std::map<std::tuple<int, int, std::size_t, bool>, std::shared_future<std::size_t>>
        weldedCounts_;

    // Calls f(tree, its tube parameters) for the bark of every tree at detail d: pruned trees
    // keep the whole tree's radii (as widths), so hiding changes nothing else.
    template <class F>
    void forEachBark(const Detail& d, F f) const {
        for (std::size_t t = 0; t < trees_.size(); ++t) forTree(t, d, f);
    }
    // f(tree, its tube parameters) for tree t at detail d (forEachBark).
    template <class F>
    void forTree(std::size_t t, const Detail& d, F f) const {
        TubeMeshParams tube = params_.tube;
        tube.minSegments = d.minSegments;
        tube.maxSegments = d.maxSegments;
        if (d.prune == 0) {
            f(*trees_[t].tree, tube);
        } else {
            TubeMeshParams widths = tube;
            widths.radiusMode = RadiusMode::Widths;
            f(prunedTree(t, d.prune), widths);
        }
    }

    // Edges thinnest first (ties: the newest node first, so outer twigs go before inner ones)
    // over all trees.
    void buildPruneOrder() {
        if (!order_.empty()) return;
        for (std::size_t t = 0; t < trees_.size(); ++t) {
            for (std::size_t i = 1; i < trees_[t].tree->size(); ++i) order_.emplace_back(t, i);
        }
        std::sort(order_.begin(), order_.end(), [&](const auto& a, const auto& b) {
            const double ra = radii_[a.first][a.second], rb = radii_[b.first][b.second];
            if (ra != rb) return ra < rb;
            if (a.second != b.second) return a.second > b.second;
            return a.first < b.first;
        });
    }

    // Tree t with the first `prune` edges of the order (and everything above them) hidden and
    // every radius fixed to the whole tree's, so hiding changes nothing else.
    BranchTree prunedTree(std::size_t t, std::size_t prune) const {
        BranchTree tree = *trees_[t].tree;
        std::vector<std::uint8_t> cut(tree.size(), 0);
        for (std::size_t k = 0; k < prune && k < order_.size(); ++k) {
            if (order_[k].first == t) cut[order_[k].second] = 1;
        }
        for (std::size_t i = 0; i < tree.size(); ++i) {
            BranchNode& node = tree.node(static_cast<NodeId>(i));
            node.radius = radii_[t][i];
            if (i == 0) continue;
            cut[i] = cut[i] | cut[static_cast<std::size_t>(node.parent)];
            if (cut[i]) node.hidden = true;
        }
        return tree;
    }

    std::span<const TreeMeshInput> trees_;
    const TreeMeshParams& params_;
    std::vector<std::vector<double>> radii_;
    std::size_t treeThreads_ = threads();  // trees meshed at once (bark)
    std::vector<std::pair<std::size_t, std::size_t>> order_;
};

std::size_t triangles(const Mesh& mesh) { return mesh.triangleCount(); }

// Leaf share of a level: `target` leaf triangles from `blade` (all leaves at full detail) and
// `card` (all leaves with generated blades as cards) triangles. Preferring coverage keeps all
// leaves as cards when even they are under the target (the bark then gets the rest).
void planLeaves(double target, double blade, double card, bool preferCoverage, Detail& d) {
    d.cards = false;
    d.keep = 1.0;
    if (blade <= 0.0) return;
    const double keepBlade = std::clamp(target / blade, 1e-9, 1.0);
    const double keepCard = std::clamp(target / card, 1e-9, 1.0);
    const bool useCards =
        card < blade && target < 0.5 * blade && (preferCoverage || keepCard * card >= 0.9 * target);
    d.cards = useCards;
    d.keep = useCards ? keepCard : keepBlade;
}

// Ring segment pairs from the full (min, max) down to (3, 3): max first, then both.
std::vector<std::pair<int, int>> segmentSteps(int minSegments, int maxSegments) {
    std::vector<std::pair<int, int>> steps;
    for (int m = maxSegments; m >= minSegments; --m) steps.emplace_back(minSegments, m);
    for (int m = minSegments - 1; m >= 3; --m) steps.emplace_back(m, m);
    return steps;
}

// A number of pruned edges strictly between `lo` and `hi` (hi − lo > 1; triangle counts countLo
// > target ≥ countHi) to mesh next: where `interpolate`, where the target lies between the two
// counts on the line through them (the count falls nearly in proportion to the edges pruned
// where thin twigs go), else halfway (uneven stretches, where the line would creep along).
std::size_t prunedProbe(std::size_t lo, double countLo, std::size_t hi, double countHi,
                        double target, bool interpolate) {
    if (!interpolate || !(countLo > countHi)) return lo + (hi - lo) / 2;
    const double share = std::clamp((countLo - target) / (countLo - countHi), 0.0, 1.0);
    const auto offset =
        static_cast<std::size_t>(std::llround(share * static_cast<double>(hi - lo)));
    return std::clamp(lo + offset, lo + 1, hi - 1);
}

// Where each trial of planBark is a mesh (welded bark), a number of pruned edges whose count is
// this close to the target ends the search: the last probes of a bisection down to neighbouring
// counts had cost ABOP 1.24a's 40 % level a quarter of a second (717–720 pruned edges, 51 674 to
// 51 188 welded triangles for 51 229), and a level that is later united misses its target by
// more than that anyway.
constexpr double kMeshedPlanTolerance = 0.01;

// The bark detail closest to `target` triangles (within kMeshedPlanTolerance where trials are
// meshes): the first segment step at or below it when
// that is within 3 %, else pruning from the step before it (the last step where none is). Each
// trial meshes the bark (welded bark as slowly as the final mesh), so the searches take few:
// the step by bisection (fewer segments never give more triangles), the number of pruned edges
// (the count falls with it, nearly in proportion where the thin twigs go) by probes
// interpolated between the bracket's counts, every other one halving the bracket so that
// uneven stretches cannot slow it much (tree_3d: 28 trials a level by a scan of the 14 steps and
// plain bisection, 11 now).
void planBark(const TreeMesher& mesher, double target, Detail& d) {
    const auto steps = segmentSteps(d.minSegments, d.maxSegments);
    std::vector<double> stepCounts(steps.size(), -1.0);
    auto stepCount = [&](std::size_t j) {
        if (stepCounts[j] < 0.0) {
            Detail trial = d;
            std::tie(trial.minSegments, trial.maxSegments) = steps[j];
            stepCounts[j] = static_cast<double>(mesher.barkTriangles(trial));
        }
        return stepCounts[j];
    };
    // The first step at or below the target: steps.size() where none is.
    std::size_t below = steps.size();
    if (stepCount(0) <= target) {
        below = 0;
    } else {
        std::size_t above = 0;  // stepCount(above) > target
        while (below - above > 1) {
            const std::size_t mid = above + (below - above) / 2;
            (stepCount(mid) > target ? above : below) = mid;
        }
    }
    if (below < steps.size() && (below == 0 || stepCount(below) >= 0.97 * target)) {
        std::tie(d.minSegments, d.maxSegments) = steps[below];
        return;
    }
    const std::size_t step = below == steps.size() ? steps.size() - 1 : below - 1;
    std::tie(d.minSegments, d.maxSegments) = steps[step];
    std::size_t lo = 0, hi = mesher.pruneOrderSize();             // count(lo) > target
    std::map<std::size_t, double> counted{{0, stepCount(step)}};  // each detail meshed once
    auto count = [&](std::size_t prune) {
        const auto [at, added] = counted.try_emplace(prune, 0.0);
        if (added) {
            Detail trial = d;
            trial.prune = prune;
            at->second = static_cast<double>(mesher.barkTriangles(trial));
        }
        return at->second;
    };
    if (count(hi) > target) {
        d.prune = hi;
        return;
    }
    const double close = mesher.trialsAreMeshes() ? kMeshedPlanTolerance * target : 0.0;
    for (bool interpolate = true; hi - lo > 1; interpolate = !interpolate) {
        const std::size_t probe = prunedProbe(lo, count(lo), hi, count(hi), target, interpolate);
        if (std::abs(count(probe) - target) <= close) {
            d.prune = probe;
            return;
        }
        (count(probe) > target ? lo : hi) = probe;
    }
    d.prune = std::abs(count(lo) - target) < std::abs(count(hi) - target) ? lo : hi;
}

}  // namespace

std::size_t primitiveTriangles(const Mesh& mesh, std::string_view name) {
    std::size_t total = 0;
    for (const MeshPrimitive& p : mesh.primitives) {
        if (p.name == name) total += p.indexCount / 3;
    }
    return total;
}

Mesh buildTreeMesh(std::span<const TreeMeshInput> trees, const TreeMeshParams& params,
                   TreeMeshReport* report) {
    if (params.leaves) validateLeafParams(params.leaf);
    Detail full;
    full.minSegments = params.tube.minSegments;
    full.maxSegments = std::max(params.tube.maxSegments, params.tube.minSegments);
    full.solidUnion = params.solidUnion;
    full.reported = true;
    return TreeMesher(trees, params).both(full, report);
}

namespace {

// A united level whose triangles miss its target by more than this share is planned again
// (meshLevel), up to kUnitedRounds unions in all; the LOD check allows 10 %. Planned on the
// welded count alone, 8 of the 35 shipped examples had a level off by more than that (ABOP
// 1.24a–c, 1.24f, 1.27, 1.31a, conifer: up to 35 %); scaled by the last union alone, in 3
// rounds, four of the dense ABOP plants' coarsest levels still missed by 16–42 %; now every
// example lands within 4 % (docs/BENCHMARKS.md).
constexpr double kUnitedTolerance = 0.05;
constexpr int kUnitedRounds = 5;

// A level's mesh at detail `d` (its leaves planned; d.solidUnion: united), its bark planned
// (planBark, on welded bark) for `plan` triangles at first; where the mesh misses `target` by
// more than kUnitedTolerance, meshed again, up to `rounds` meshes in all: planned for a count
// scaled by what the last mesh's bark gave against `barkTarget`, or, once meshes
// above and below are known, interpolated between the closest of them; where those two differ
// only in the edges pruned, the number pruned is interpolated between their counts, every
// other time halved (prunedProbe; bisected until session 42: ABOP 1.24a's and 1.24c's coarsest
// levels took 5 unions, now 3), on the meshes themselves. A union's
// count grows faster than its input where dense branches stay and jumps where one pruned edge
// takes a crowded cluster with it: ABOP 1.27's coarsest level 3 136 welded → 3 924 united,
// 5 336 → 12 712, and 249 pruned edges gave 7 794 united triangles, 295 gave 5 892, for
// plans a few dozen triangles apart. The closest mesh is kept; `d` and `report` get its
// detail and report.
Mesh meshLevel(const TreeMesher& mesher, double target, double barkTarget, double plan, int rounds,
               Detail& d, TreeMeshReport& report) {
    const Detail leavesPlanned = d;
    std::optional<double> leaves;  // the level's leaf triangles, the same in every mesh
    Mesh kept;
    double missed = std::numeric_limits<double>::infinity();
    struct Meshed {
        Detail detail;
        double plan, bark;
    };
    std::optional<Meshed> under, over;  // the closest below and above the target
    int bracketed = 0;                  // rounds that had both
    int prunedRounds = 0;               // rounds between two meshes that differ in pruning alone
    for (int round = 0; round < rounds; ++round) {
        Detail trial = leavesPlanned;
        const bool prunesApart = under && over &&
                                 under->detail.minSegments == over->detail.minSegments &&
                                 under->detail.maxSegments == over->detail.maxSegments &&
                                 over->detail.prune + 1 < under->detail.prune;
        if (prunesApart) {
            trial = over->detail;
            trial.prune = prunedProbe(over->detail.prune, over->bark, under->detail.prune,
                                      under->bark, barkTarget, ++prunedRounds % 2 == 1);
        } else {
            trial.solidUnion = false;
            planBark(mesher, plan, trial);
        }
        trial.solidUnion = leavesPlanned.solidUnion;
        trial.reported = true;
        TreeMeshReport trialReport;
        Mesh mesh = mesher.both(trial, &trialReport);
        const double count = static_cast<double>(triangles(mesh));
        if (std::abs(count - target) < missed) {
            missed = std::abs(count - target);
            kept = std::move(mesh);
            report = trialReport;
            d = trial;
        }
        if (missed <= kUnitedTolerance * target) break;
        if (!leaves) leaves = static_cast<double>(triangles(mesher.leaves(leavesPlanned)));
        const double bark = count - *leaves;
        auto& side = bark < barkTarget ? under : over;
        if (!side || std::abs(bark - barkTarget) < std::abs(side->bark - barkTarget)) {
            side = Meshed{trial, plan, bark};
        }
        if (prunesApart) continue;
        double next = bark > 0.0 ? plan * barkTarget / bark : plan;
        if (under && over) {  // interpolated, every other time halfway (steep stretches)
            const double share = ++bracketed % 2 == 1
                                     ? (barkTarget - under->bark) / (over->bark - under->bark)
                                     : 0.5;
            next = under->plan + share * (over->plan - under->plan);
        }
        const bool adjacent = under && over && under->detail.prune <= over->detail.prune + 1 &&
                              under->detail.minSegments == over->detail.minSegments &&
                              under->detail.maxSegments == over->detail.maxSegments;
        if (std::abs(next - plan) < 1.0 || adjacent) break;  // nothing else to try
        plan = next;
    }
    return kept;
}

// Level i, meshed at detail d: its mesh named and its detail recorded.
TreeLod namedLevel(TreeLod lod, std::size_t i, const Detail& d) {
    lod.mesh.name = "tree_LOD" + std::to_string(i);
    lod.minSegments = d.minSegments;
    lod.maxSegments = d.maxSegments;
    lod.prunedNodes = d.prune;
    lod.leafKeep = d.keep;
    lod.leafCards = d.cards;
    return lod;
}

}  // namespace

std::vector<TreeLod> buildTreeLods(std::span<const TreeMeshInput> trees,
                                   const TreeMeshParams& params, std::span<const double> ratios,
                                   TreeMeshReport* report) {
    if (ratios.empty()) throw Error("LOD ratios: expected at least one ratio in (0, 1]");
    for (double r : ratios) {
        if (!(r > 0.0 && r <= 1.0)) {
            throw Error("LOD ratio " + std::to_string(r) + " is out of range; expected (0, 1]");
        }
    }
    if (params.leaves) validateLeafParams(params.leaf);
    TreeMesher mesher(trees, params);
    Detail full;
    full.minSegments = std::clamp(params.tube.minSegments, 3, 4096);
    full.maxSegments = std::clamp(params.tube.maxSegments, full.minSegments, 4096);
    const double bark0 = static_cast<double>(mesher.barkTriangles(full));
    const double leaves0 = static_cast<double>(triangles(mesher.leaves(full)));
    Detail cards = full;
    cards.cards = true;
    const double cards0 =
        params.leaves ? static_cast<double>(triangles(mesher.leaves(cards))) : leaves0;
    // United levels aim at their share of the united full detail, in united triangles: a union
    // changes its welded input's count by a factor that depends on the dense branches a level
    // keeps (cut triangles, junctions meshed as tubes for it: ABOP 1.24c 65 270 welded, 192 862
    // united), so each level's bark is planned for a welded count found by meshLevel.
    Mesh unitedFull;
    TreeMeshReport unitedFullReport;
    double barkFull = bark0;  // at full detail, united where the levels are
    const bool united = params.weldJunctions && params.solidUnion;
    full.solidUnion = params.solidUnion;  // of the levels' meshes; planned on welded bark

    // The levels are planned and meshed on threads of their own (each plans by meshing trial
    // details, the finer ones are united), and reported in their order.
    mesher.preparePruning();
    const std::size_t levelThreads = std::min(ratios.size(), mesher.threads());
    mesher.shareCores(levelThreads);
    // The full detail is united on a thread of its own while the levels plan their bark on the
    // welded counts (a level without leaves plans the same welded count either way; the trial
    // meshes are kept, TreeMesher::barkTriangles), so the plans made once the united count is
    // known find their trials meshed (ABOP 1.24a: its union took 0.8 s before any level began).
    // The last reference to a std::async future waits for its task, so unitedFull outlives it.
    // On one thread (TreeMeshParams::threads = 1, as `ramus batch` meshes its items) the union
    // is made where the first level waits for it.
    std::shared_future<void> unitedReady;
    const bool unitedAside = united && mesher.threads() > 1;
    if (united) {
        const auto policy = unitedAside ? std::launch::async : std::launch::deferred;
        unitedReady = std::async(policy, [&] {
                          Detail d = full;
                          d.solidUnion = true;
                          d.reported = true;
                          unitedFull = mesher.both(d, &unitedFullReport);
                          barkFull = static_cast<double>(triangles(unitedFull)) - leaves0;
                      }).share();
    }
    std::vector<TreeLod> lods(ratios.size());
    std::vector<TreeMeshReport> reports(ratios.size());
    detail::forEachOnThreads(
        ratios.size(), levelThreads,
        [&](std::size_t i) {
            Detail d = full;
            TreeLod lod;
            lod.ratio = ratios[i];
            if (united && ratios[i] == 1.0) return;  // the full detail itself, below
            if (ratios[i] < 1.0) planLeaves(ratios[i] * leaves0, leaves0, cards0, true, d);
            const double leafShare = d.keep * (d.cards ? cards0 : leaves0);
            if (unitedAside) {  // its trial meshes, while the full detail is united
                Detail early = d;
                early.solidUnion = false;
                planBark(mesher, std::max(0.0, ratios[i] * (bark0 + leaves0) - leafShare), early);
            }
            if (united) unitedReady.get();
            const double target = std::round(ratios[i] * (barkFull + leaves0));
            lod.targetTriangles = static_cast<std::size_t>(target);
            if (ratios[i] < 1.0) {
                double barkTarget = target - leafShare;
                if (barkTarget > barkFull) {  // the bark cannot take the rest: the leaves must
                    barkTarget = barkFull;
                    planLeaves(target - barkFull, leaves0, cards0, false, d);
                }
                lod.mesh = meshLevel(mesher, target, barkTarget, barkTarget * bark0 / barkFull,
                                     united ? kUnitedRounds : 1, d, reports[i]);
            } else {
                d.reported = true;
                lod.mesh = mesher.both(d, &reports[i]);
            }
            lods[i] = namedLevel(std::move(lod), i, d);
        },
        1);
    if (united) {
        unitedReady.get();
        for (std::size_t i = 0; i < ratios.size(); ++i) {
            if (ratios[i] != 1.0) continue;
            TreeLod lod;
            lod.ratio = 1.0;
            lod.targetTriangles = triangles(unitedFull);
            lod.mesh = unitedFull;
            reports[i] = unitedFullReport;
            lods[i] = namedLevel(std::move(lod), i, full);
        }
    }
    if (report != nullptr) {
        for (const TreeMeshReport& r : reports) addReport(*report, r);
    }
    return lods;
}

}  // namespace ramus
