// The ground height and the heel/wrist probability of a skeleton's legs.
//
// Based on: seed 000 §5.5.1 (0.8 of each leg's length, the heel/wrist probability
// (leg length − girdle height above 0) / foot length, averaged over front and hind legs, 0 when
// the ground was raised) and §7.5 point 1 (measure from the placed shoulder/hip joints rather
// than from the spine's Bézier points, so that every leg can reach the ground).
//
// Reading of §5.5.1: the ground starts at y = 0, the bottom edge of the annotated images
// (§7.4.1), and is "moved up" only when the legs are too short to reach it. "Take the shortest
// leg fully stretched and put the ground at its end point" is the highest of the legs' reach
// points; with the 0.8 factor the ground becomes maxᵢ(jointHeightᵢ − 0.8·lengthᵢ) when that is
// above 0, so every leg reaches the ground with at most 0.8 of its length and stays bent.
#include <algorithm>
#include <cmath>
#include <limits>

#include "skeleton/limbs.hpp"

namespace ramus::detail {
namespace {

/// Heel/wrist probability of one leg standing on y = 0.
double legHeelProbability(const LegReach& leg) {
    const double reachBelowZero = leg.length - leg.jointHeight;
    if (leg.footLength <= 0.0) return reachBelowZero >= 0.0 ? 1.0 : 0.0;
    return std::clamp(reachBelowZero / leg.footLength, 0.0, 1.0);
}

}  // namespace

GroundHeight computeGroundHeight(std::span<const LegReach> legs, double lowestPoint) {
    GroundHeight result;
    if (legs.empty()) {
        // No legs: the skeleton rests on the ground plane, nothing below it.
        result.height = lowestPoint;
        return result;
    }
    double needed = -std::numeric_limits<double>::infinity();
    for (const LegReach& leg : legs)
        needed = std::max(needed, leg.jointHeight - kGroundLegFraction * leg.length);
    if (needed > 0.0) {
        result.height = needed;
        result.raised = true;
        return result;  // raised ground: the heel/wrist probability is 0
    }
    // Mean over the front legs and over the hind legs, then the mean of the groups present.
    double sums[2] = {0.0, 0.0};
    int counts[2] = {0, 0};
    for (const LegReach& leg : legs) {
        const int group = leg.front ? 1 : 0;
        sums[group] += legHeelProbability(leg);
        ++counts[group];
    }
    double groupMeans = 0.0;
    int groups = 0;
    for (int g = 0; g < 2; ++g) {
        if (counts[g] == 0) continue;
        groupMeans += sums[g] / counts[g];
        ++groups;
    }
    result.heelProbability = groupMeans / groups;
    return result;
}

}  // namespace ramus::detail
