// Space colonization (seed 002 ch. 3, §4.3; Runions, Lane, Prusinkiewicz 2007; SPEC §C): trees
// grow from roots towards attraction points, which are removed once a node comes close.
// Axes as in glTF (+Y up); lengths in model units (the seed uses cm).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/envelope.hpp"
#include "ramus/leaves.hpp"
#include "ramus/math.hpp"
#include "ramus/tube_mesher.hpp"

namespace ramus {

/// Growth parameters. Names follow SPEC §C; the seed's symbols are given in brackets.
struct ColonizeParams {
    /// d_i: a point attracts its nearest node only when that node is closer than this
    /// (model units, > 0, > killRadius).
    double influenceRadius = 100.0;
    /// d_k: a point is removed as soon as a node is closer than this (model units, > 0).
    /// Below 2 × step some points are never reached (a warning says so).
    double killRadius = 20.0;
    /// D: distance of a new node from its parent (model units, > 0).
    double step = 15.0;
    /// T: added to the sum of unit directions before normalising (seed eq 3.2); unitless,
    /// compare with the number of attracting points. Zero = none.
    Vec3 tropism = Vec3::Zero();
    /// Upper bound on growth iterations (≥ 0); 0 grows nothing.
    int maxIterations = 1000;
    /// max_grad: no node gets more than this many children (≥ 0; 0 = unlimited).
    int maxDegree = 0;
    /// max_Z: no node is created whose branch depth Z (eq 3.7) would exceed this
    /// (≥ 0; 0 = unlimited).
    int maxBranchDepth = 0;
    /// max_NG: a node that got no child for this many consecutive iterations is no longer
    /// considered in step 1 (≥ 0; 0 = off).
    int maxNoGrowth = 0;
    /// Weighted growth: the step is 2·D at branch depth 0 falling linearly to D at
    /// maxBranchDepth (which must then be ≥ 1). Z of the parent decides.
    bool weightedGrowth = false;
    /// Limit on the nodes of all trees (≥ 1): growth that would exceed it stops with an Error
    /// (a runaway config fails clearly instead of exhausting memory; ~100 bytes per node).
    std::size_t maxNodes = 10'000'000;
    /// Start of each tree (at least one). Several roots compete for the same points; a root
    /// farther than d_i from every point first grows a straight trunk towards the nearest one.
    std::vector<Vec3> roots{Vec3::Zero()};
};

/// Throws Error naming the first invalid field, its valid range and units.
void validateColonizeParams(const ColonizeParams& params);

/// Two nodes are never closer than this fraction of `step`: a new node that would be is not
/// created (this is how the oscillation of seed 002 §5.2.3 is stopped).
inline constexpr double kMinNodeSpacing = 1e-3;

/// The grown trees and what happened.
struct ColonizeResult {
    std::vector<BranchTree> trees;      ///< one per root, in the order of ColonizeParams::roots
    std::size_t attractors = 0;         ///< points used (those inside obstacles are not counted)
    std::size_t attractorsLeft = 0;     ///< points not removed when growth stopped
    int iterations = 0;                 ///< growth iterations run (trunk steps included)
    std::vector<std::string> warnings;  ///< sentences for the user (e.g. d_k < 2·D)

    std::size_t nodeCount() const;
};

/// Grows trees (seed 002 §3.3 with the extensions of §3.5). Each iteration:
///  1. every remaining point s attracts its nearest considered node v (ties: lowest node id)
///     when ‖s − v‖ < d_i;
///  2. in increasing id order, every node v with attracting points S(v) (summed in increasing
///     point index order) gets the child v + D·ñ, ñ = normalize(Σ normalize(s − v) + T) —
///     unless v has maxDegree children, Z would exceed maxBranchDepth, the direction is zero,
///     the edge would enter an obstacle, or a node within kMinNodeSpacing·D exists there;
///  3. every point closer than d_k to a new node is removed.
/// Before iteration 1 the roots remove their points. A tree none of whose nodes was ever
/// within d_i of a point grows its trunk tip D towards the nearest point instead. Stops when no
/// points remain, none attracts a node (and no trunk can grow), an iteration changed nothing,
/// or after maxIterations. Points inside an obstacle are dropped first.
/// Runs in about O((points + nodes) · local density) using a uniform grid, not
/// O(points × nodes) per iteration. Points are rounded to single precision internally.
/// Deterministic. Throws Error for invalid params or non-finite points.
ColonizeResult colonize(const ColonizeParams& params, std::span<const Vec3> points,
                        std::span<const Shape> obstacles = {});

/// Branch-angle reduction (seed 002 §3.4, eq 3.4–3.5): the m ≥ 2 children v_i of every node v
/// move halfway to their mean m⃗ = p_v + Σ(p_vi − p_v)/m: p_vi += (m⃗ − p_vi)/2, with all means
/// taken from the original positions. Grandchildren do not move. Same topology and ids.
BranchTree reduceBranchAngles(const BranchTree& tree);

/// Curve reduction (seed 002 §3.5, eq 3.8; §4.4.3): walking from the root, a node v with
/// exactly one child v_n and a parent v' is removed (v_n becomes a child of v') when
/// ⟨R1, R2⟩ > maxDot, R1 = unit(p_v − p_v'), R2 = unit(p_vn − p_v), where v' is v's parent in
/// the reduced tree. Builds a new tree (depth-first order, children in their original order, so
/// branch depths Z are unchanged). maxDot ≤ -1 removes every such node; ≥ 1 none.
BranchTree reduceCurves(const BranchTree& tree, double maxDot);

/// Everything a colonization config file (.json, docs/colonize.md) describes.
struct ColonizeConfig {
    ColonizeParams params;
    std::vector<Envelope> envelopes;
    std::vector<Shape> obstacles;
    std::uint64_t seed = 0;           ///< base seed mixed into every envelope's seed
    bool reduceBranchAngles = false;  ///< apply reduceBranchAngles after growth
    double curveReduction = 0.0;      ///< max_K in (0, 1) for reduceCurves; 0 = off
    std::string pointsFile;           ///< extra attraction points (path relative to the config)
    /// Size limit (bytes) of the files the config names: its mesh shapes' files (read while
    /// parsing) and pointsFile (read by configAttractionPoints).
    std::size_t maxFileBytes = kMaxInputFileBytes;

    /// Tube mesher settings from the "mesh" object; only the keys present are set.
    struct MeshOverrides {
        bool hasLeafRadius = false, hasRadiusExponent = false, hasTrunkMultiplier = false;
        bool hasMinSegments = false, hasMaxSegments = false, hasCapTips = false;
        bool hasUvAspect = false, hasWind = false, hasTextures = false, hasWeld = false;
        bool hasSolidUnion = false, hasConvexJunctions = false;
        double leafRadius = 0.0, radiusExponent = 2.0, trunkMultiplier = 1.0;
        int minSegments = 4, maxSegments = 16;
        bool capTips = true;
        double uvAspect = 1.0;    ///< "uv_aspect": bark texture height / width
        bool wind = false;        ///< "wind": write the wind attributes
        bool textures = true;     ///< "textures": embed the procedural bark and leaf textures
        bool weld = false;        ///< "weld": welded junctions (one closed surface per tree)
        bool solidUnion = false;  ///< "union": united welded bark (implies weld)
        /// "convex_junctions": welded junctions kept as convex hulls (not shrunk)
        bool convexJunctions = false;
        std::vector<double> lods;  ///< "lods": triangle ratios of the levels; empty = no LODs
    } mesh;

    /// The "leaves" object: generate leaves with these settings (docs/colonize.md).
    bool hasLeaves = false;
    LeafParams leaves;

    /// "ground": points below this height (y, model units) grow each tree's root system from
    /// its root node instead of its crown; with "root_growth" settings (the crown's growth keys
    /// by default, with tropism [0, 0, 0]). Not given: every point feeds the crown.
    bool hasGround = false;
    double ground = 0.0;
    ColonizeParams rootGrowth;
};

/// Applies the config's "mesh" object to `params`: only the keys the config has are set.
void applyMeshOverrides(const ColonizeConfig& config, TubeMeshParams& params);

/// Parses a config from JSON text. Every value is checked; errors read
/// "FILE: KEY.PATH: what; expected …, got …" (e.g. "tree.json: envelopes[2].radius: …").
/// Unknown keys are errors (they are usually typos). The files of "mesh" shapes are read here
/// (readMeshVolume), relative to the folder of `fileName`; their errors are reported under the
/// shape's "file" key. Files larger than `maxFileBytes` are errors (readFile); the limit is
/// kept in ColonizeConfig::maxFileBytes for the points file.
ColonizeConfig parseColonizeConfig(const std::string& jsonText, const std::string& fileName,
                                   std::size_t maxFileBytes = kMaxInputFileBytes);

/// Reads and parses a config file (at most `maxFileBytes`, like the files it names); pointsFile
/// is resolved relative to the file's folder.
ColonizeConfig loadColonizeConfig(const std::string& path,
                                  std::size_t maxFileBytes = kMaxInputFileBytes);

/// The config's attraction points: its envelopes sampled with `seed`, plus its points file,
/// minus points inside obstacles.
std::vector<Vec3> configAttractionPoints(const ColonizeConfig& config);

/// Grows the config's trees and applies its post-processing (angle then curve reduction).
/// With a ground height, the points below it grow root systems from the same roots (a second
/// colonize run with config.rootGrowth), which are joined into each tree as further children of
/// its root node (so a root system is a side branch of branch depth 1); the counts of `result`
/// then cover both runs.
ColonizeResult growFromConfig(const ColonizeConfig& config, std::span<const Vec3> points);

}  // namespace ramus
