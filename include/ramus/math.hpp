// Small math vocabulary over Eigen shared by every module.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ramus {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using Vec2f = Eigen::Vector2f;
using Vec3f = Eigen::Vector3f;
using Vec4f = Eigen::Vector4f;

inline constexpr double kPi = 3.14159265358979323846;

/// Degrees to radians.
constexpr double degToRad(double degrees) { return degrees * (kPi / 180.0); }
/// Radians to degrees.
constexpr double radToDeg(double radians) { return radians * (180.0 / kPi); }

/// Axis-aligned bounding box; empty() until a point is added.
struct Aabb {
    Vec3 min{Vec3::Constant(std::numeric_limits<double>::infinity())};
    Vec3 max{Vec3::Constant(-std::numeric_limits<double>::infinity())};

    bool empty() const { return min.x() > max.x(); }
    void add(const Vec3& p) {
        min = min.cwiseMin(p);
        max = max.cwiseMax(p);
    }
    Vec3 center() const { return (min + max) * 0.5; }
    Vec3 extent() const { return max - min; }
};

}  // namespace ramus
