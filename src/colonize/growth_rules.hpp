// Based on: seed 002 §3.3 eq 3.1–3.3 (new node position), §3.5 (max_grad, max_Z, weighted
// growth). The arithmetic every colonization implementation must share bit for bit (the fast
// one in colonize.cpp and the brute-force reference in the tests), so they can be compared
// node by node: squared distances, the direction sum and the child proposal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ramus/colonize.hpp"
#include "ramus/envelope.hpp"

namespace ramus::colonize_detail {

/// Squared distance between an attraction point (single precision) and a node.
inline double squaredDistance(const Vec3f& point, const Vec3& node) {
    const double dx = static_cast<double>(point.x()) - node.x();
    const double dy = static_cast<double>(point.y()) - node.y();
    const double dz = static_cast<double>(point.z()) - node.z();
    return dx * dx + dy * dy + dz * dz;
}

/// Adds normalize(s − v) to `sum` (eq 3.3). s ≠ v is guaranteed by the kill radius.
inline void addUnitDirection(Vec3& sum, const Vec3f& point, const Vec3& node) {
    const double dx = static_cast<double>(point.x()) - node.x();
    const double dy = static_cast<double>(point.y()) - node.y();
    const double dz = static_cast<double>(point.z()) - node.z();
    const double inv = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz);
    sum.x() += dx * inv;
    sum.y() += dy * inv;
    sum.z() += dz * inv;
}

/// Branch depth Z of the next child of a node (eq 3.7 at creation time).
inline std::uint32_t childBranchDepth(std::uint32_t parentZ, std::uint32_t parentChildCount) {
    return parentChildCount == 0 ? parentZ : parentZ + 1;
}

/// Step length for a child of a node with branch depth `parentZ` (weighted growth: 2·D at
/// Z = 0, falling linearly to D at max_Z).
inline double stepLength(const ColonizeParams& p, std::uint32_t parentZ) {
    if (!p.weightedGrowth || p.maxBranchDepth <= 0) return p.step;
    const double z = std::min<double>(parentZ, p.maxBranchDepth);
    return p.step * (2.0 - z / p.maxBranchDepth);
}

/// Directions shorter than this (n + T with n a sum of unit vectors) count as zero: no growth.
inline constexpr double kMinDirectionLength = 1e-9;

/// Position of the child a node would get when growing along `direction` (not normalised),
/// or false when it must not grow: max degree reached, branch depth too deep, direction
/// (numerically) zero, or the edge would enter an obstacle. Duplicates are checked by callers.
inline bool proposeChild(const ColonizeParams& p, std::span<const Shape> obstacles,
                         const Vec3& parentPos, std::uint32_t parentZ,
                         std::uint32_t parentChildCount, const Vec3& direction, Vec3& child) {
    if (p.maxDegree > 0 && parentChildCount >= static_cast<std::uint32_t>(p.maxDegree)) {
        return false;
    }
    if (p.maxBranchDepth > 0 && childBranchDepth(parentZ, parentChildCount) >
                                    static_cast<std::uint32_t>(p.maxBranchDepth)) {
        return false;
    }
    const double length = std::sqrt(direction.x() * direction.x() + direction.y() * direction.y() +
                                    direction.z() * direction.z());
    if (!(length > kMinDirectionLength)) return false;
    child = parentPos + (stepLength(p, parentZ) / length) * direction;
    for (const Shape& obstacle : obstacles) {
        if (segmentHitsShape(obstacle, parentPos, child)) return false;
    }
    return true;
}

/// Squared distance between two nodes.
inline double squaredDistance(const Vec3& a, const Vec3& b) {
    const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
    return dx * dx + dy * dy + dz * dz;
}

/// Smallest allowed distance between two nodes, squared.
inline double minNodeSpacingSquared(const ColonizeParams& p) {
    const double d = kMinNodeSpacing * p.step;
    return d * d;
}

/// Warnings for the user about parameters and inputs (d_k < 2·D, no points, a root inside an
/// obstacle). `pointCount` counts the points left after obstacle removal.
std::vector<std::string> colonizeWarnings(const ColonizeParams& params, std::size_t pointCount,
                                          std::span<const Shape> obstacles);

}  // namespace ramus::colonize_detail
