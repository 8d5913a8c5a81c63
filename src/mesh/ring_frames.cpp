// Based on: Wang, Jüttler, Zheng, Liu 2008, "Computation of rotation minimizing frames"
// (double reflection). Shared by tube_mesher.cpp and welded_mesher.cpp.
#include "ring_frames.hpp"

#include <cmath>

namespace ramus::detail {

AngleTable makeAngleTable(int n, double rotation) {
    AngleTable table;
    const auto size = static_cast<std::size_t>(n) + 1;
    table.cosines.resize(size);
    table.sines.resize(size);
    table.us.resize(size);
    for (int i = 0; i < n; ++i) {
        const double d = rotation + 2.0 * kPi * i / n;
        table.cosines[static_cast<std::size_t>(i)] = static_cast<float>(std::cos(d));
        table.sines[static_cast<std::size_t>(i)] = static_cast<float>(std::sin(d));
        table.us[static_cast<std::size_t>(i)] = static_cast<float>(i) / static_cast<float>(n);
    }
    table.cosines[static_cast<std::size_t>(n)] = table.cosines[0];
    table.sines[static_cast<std::size_t>(n)] = table.sines[0];
    table.us[static_cast<std::size_t>(n)] = 1.0f;
    return table;
}

Vec3 initialReference(const Vec3& t) {
    const Vec3 a = t.cwiseAbs();
    int axis = 0;
    if (a.y() < a[axis]) axis = 1;
    if (a.z() < a[axis]) axis = 2;
    const Vec3 ref = Vec3::Unit(axis);
    const Vec3 perpendicular = ref - ref.dot(t) * t;  // |.|² >= 2/3 for unit t
    return perpendicular * (1.0 / perpendicular.norm());
}

// Both reflections preserve length and orthogonality, so the result is a unit vector
// perpendicular to t1 up to rounding, which one Newton step removes.
Vec3 transportReference(const Vec3& r0, const Vec3& t0, const Vec3& step, const Vec3& t1) {
    const Vec3 r = r0 - 2.0 * step.dot(r0) * step;
    const Vec3 t = t0 - 2.0 * step.dot(t0) * step;
    const Vec3 v2 = t1 - t;
    const double c2 = v2.squaredNorm();
    Vec3 r1 = c2 > 1e-24 ? Vec3(r - (2.0 / c2) * v2.dot(r) * v2) : r;
    r1 -= r1.dot(t1) * t1;
    const double length2 = r1.squaredNorm();
    if (std::abs(length2 - 1.0) < 1e-6) return r1 * (1.5 - 0.5 * length2);
    return length2 > 1e-24 ? Vec3(r1 * (1.0 / std::sqrt(length2))) : initialReference(t1);
}

}  // namespace ramus::detail
