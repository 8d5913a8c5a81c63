// Ring geometry shared by the tube mesher and the welded mesher: the angle table of a ring and
// the rotation-minimizing frames that carry a ring's orientation along a chain.
//
// Based on: Wang, Jüttler, Zheng, Liu 2008, "Computation of rotation minimizing frames"
// (double reflection).
#pragma once

#include <vector>

#include "ramus/math.hpp"

namespace ramus::detail {

/// cos/sin of rot_z + i·2π/n and u = i/n for i = 0..n; entry n repeats entry 0 exactly, so the
/// seam vertex lands bit-identically on the first one.
struct AngleTable {
    std::vector<float> cosines, sines, us;
};

/// The table of a ring of `n` (≥ 3) vertices whose first vertex sits at `rotation` radians.
AngleTable makeAngleTable(int n, double rotation);

/// A unit vector perpendicular to unit `t`: the world axis least aligned with t (ties to the
/// lower axis), made orthogonal. Deterministic start of every chain's frame.
Vec3 initialReference(const Vec3& t);

/// Double reflection (Wang et al. 2008): carries reference vector `r0` of the frame with unit
/// tangent `t0` along a step of unit direction `step` to the frame with unit tangent `t1`,
/// without twist. Returns a unit vector perpendicular to t1.
Vec3 transportReference(const Vec3& r0, const Vec3& t0, const Vec3& step, const Vec3& t1);

}  // namespace ramus::detail
