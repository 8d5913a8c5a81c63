// Based on: Runions et al. 2007 §2 and seed 002 §3.3 (attraction points, their nearest node,
// removal within d_k), with time coherence: each point remembers its nearest node, and only
// points near a new node are looked at again.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "spatial_grid.hpp"

namespace ramus::colonize_detail {

/// The attraction points of one colonization run, sorted into grid cells, each with its owner
/// (the nearest considered node within d_i, or none, or removed) and per-owner linked lists.
/// Each grid cell keeps the largest key of its points, so a query skips a whole cell when no
/// point in it can be affected.
/// Memory: 32 bytes per point plus 12 bytes per grid cell (at most one cell per 2 points).
class AttractorStore {
public:
    static constexpr std::int32_t kUnassigned = -1;  ///< alive, no node within d_i
    static constexpr std::int32_t kDead = -2;        ///< removed (a node came within d_k)

    /// Takes the points' coordinates (in point index order; rearranged into cell order).
    AttractorStore(std::vector<float> xs, std::vector<float> ys, std::vector<float> zs,
                   double influenceRadius, double killRadius, int gridSubdivision);

    /// Frees every per-point array (counts stay); nothing else may be called afterwards.
    void release();

    const SpatialGrid& grid() const { return grid_; }
    std::size_t size() const { return owner_.size(); }
    std::size_t aliveCount() const { return alive_; }
    std::size_t assignedCount() const { return assigned_; }

    Vec3f position(std::uint32_t i) const { return Vec3f(x_[i], y_[i], z_[i]); }
    std::uint32_t originalIndex(std::uint32_t i) const { return original_[i]; }
    std::int32_t owner(std::uint32_t i) const { return owner_[i]; }

    /// Makes room for the list of node `node` (ids must come in order 0, 1, 2, …).
    void addNode() { head_.push_back(-1); }
    /// First point of a node's list of attracting points (-1 = none); nextInList continues.
    std::int32_t firstOf(NodeId node) const { return head_[static_cast<std::size_t>(node)]; }
    std::int32_t nextInList(std::uint32_t i) const { return next_[i]; }

    /// For a new node `node` at `center` (newer than every other node): removes the points
    /// closer than d_k (step 3), and the other points within d_i that are strictly nearer to
    /// it than to their owner switch to it (step 1 of the next iteration). Appends every node
    /// whose set of points changed (old owners, and `node`). nodePositions gives the owners'
    /// positions. Doing this node by node gives the same points and owners as first removing
    /// for all new nodes, then claiming.
    void removeAndClaimNear(NodeId node, const Vec3& center, std::span<const Vec3> nodePositions,
                            std::vector<NodeId>& changedNodes);

    /// Gives alive point i a new owner `node` at squared distance d2 (-1 = none), e.g. when
    /// its owner retired (max_NG). The new owner may be farther than the old one.
    void moveTo(std::uint32_t i, NodeId node, double d2);

    /// True when some alive point is closer than `radius` to `center`.
    bool hasPointWithin(const Vec3& center, double radius) const;
    /// The alive point nearest to `center` (ties: lowest original index); -1 when none.
    std::int64_t nearestAlive(const Vec3& center) const;

private:
    void detach(std::uint32_t i);
    void attach(std::uint32_t i, NodeId node, double d2);
    void refreshBound(std::size_t cell);
    std::uint32_t preselect(std::uint32_t first, std::uint32_t last, float cx, float cy, float cz,
                            float killThreshold);

    SpatialGrid grid_;
    double influence2_ = 0.0, kill2_ = 0.0;
    float unassignedKey_ = 0.0f;
    // Largest error of a squared distance computed in float for distances up to d_i here.
    float floatMargin_ = 0.0f;
    // Hot, in cell order: coordinates and the key = squared distance to the owner in float
    // (d_i² when unassigned, -1 when dead), so one float comparison rejects most points.
    std::vector<float> x_, y_, z_, key_;
    // Cold: owner, original index, list links.
    std::vector<std::int32_t> owner_, next_, prev_;
    std::vector<std::uint32_t> original_;
    std::vector<std::int32_t> head_;
    // Per cell: max key of its points (-inf when all are dead): a node whose distance to the
    // cell's box is not below it cannot take any of the cell's points.
    std::vector<float> cellBound_;
    std::vector<std::uint32_t> candidates_;
    std::size_t alive_ = 0, assigned_ = 0;
};

}  // namespace ramus::colonize_detail
