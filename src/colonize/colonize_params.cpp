// Based on: seed 002 §3.2 and §4.3.1 (inputs d_i, d_k, D, T, iterations; extended parameters
// max_grad, max_Z, max_NG, weighted growth), SPEC §C (kill radius below 2·D leaves points).
#include <cmath>
#include <sstream>

#include "growth_rules.hpp"
#include "ramus/colonize.hpp"
#include "ramus/error.hpp"

namespace ramus {

namespace {

[[noreturn]] void invalid(const std::string& what, const std::string& expected, double got) {
    std::ostringstream out;
    out << what << " is invalid; expected " << expected << ", got " << got;
    throw Error(out.str());
}

}  // namespace

void validateColonizeParams(const ColonizeParams& p) {
    if (!(std::isfinite(p.influenceRadius) && p.influenceRadius > 0.0)) {
        invalid("influenceRadius (d_i)", "a finite length > 0 (model units)", p.influenceRadius);
    }
    if (!(std::isfinite(p.killRadius) && p.killRadius > 0.0)) {
        invalid("killRadius (d_k)", "a finite length > 0 (model units)", p.killRadius);
    }
    if (!(p.killRadius < p.influenceRadius)) {
        invalid("killRadius (d_k)", "a length below influenceRadius", p.killRadius);
    }
    if (!(std::isfinite(p.step) && p.step > 0.0)) {
        invalid("step (D)", "a finite length > 0 (model units)", p.step);
    }
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(p.tropism[i])) invalid("tropism (T)", "finite components", p.tropism[i]);
    }
    if (p.maxIterations < 0) invalid("maxIterations", "a count >= 0", p.maxIterations);
    if (p.maxDegree < 0)
        invalid("maxDegree (max_grad)", "a count >= 0 (0 = unlimited)", p.maxDegree);
    if (p.maxBranchDepth < 0) {
        invalid("maxBranchDepth (max_Z)", "a depth >= 0 (0 = unlimited)", p.maxBranchDepth);
    }
    if (p.maxNoGrowth < 0) invalid("maxNoGrowth (max_NG)", "a count >= 0 (0 = off)", p.maxNoGrowth);
    if (p.weightedGrowth && p.maxBranchDepth < 1) {
        invalid("maxBranchDepth (max_Z)", "a depth >= 1 when weighted growth is on",
                p.maxBranchDepth);
    }
    if (p.maxNodes < 1) invalid("maxNodes", "a count >= 1", static_cast<double>(p.maxNodes));
    if (p.roots.empty()) throw Error("roots is empty; expected at least one root position");
    for (const Vec3& r : p.roots) {
        if (!r.allFinite()) throw Error("a root position is not finite");
    }
}

namespace colonize_detail {

std::vector<std::string> colonizeWarnings(const ColonizeParams& p, std::size_t pointCount,
                                          std::span<const Shape> obstacles) {
    std::vector<std::string> warnings;
    if (p.killRadius < 2.0 * p.step) {
        std::ostringstream out;
        out << "kill radius " << p.killRadius << " is below 2 x step (" << 2.0 * p.step
            << "): nodes can pass points without removing them, so some points may stay "
               "unreached";
        warnings.push_back(out.str());
    }
    if (pointCount == 0) warnings.emplace_back("there are no attraction points: nothing grows");
    for (std::size_t r = 0; r < p.roots.size(); ++r) {
        for (const Shape& o : obstacles) {
            if (shapeContains(o, p.roots[r])) {
                warnings.push_back("root " + std::to_string(r) + " lies inside an obstacle (" +
                                   shapeKindName(o.kind) + "): it cannot grow");
                break;
            }
        }
    }
    return warnings;
}

}  // namespace colonize_detail

}  // namespace ramus
