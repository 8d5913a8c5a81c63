// Internal: SVG path data and transform lists (SVG 1.1 §8.3, §7.6), as needed to read the
// annotated skeleton side views.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ramus/math.hpp"

namespace ramus::detail {

/// An affine map x' = a·x + c·y + e, y' = b·x + d·y + f (SVG's matrix(a b c d e f)).
struct Affine2 {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

    Vec2 apply(const Vec2& p) const {
        return {a * p.x() + c * p.y() + e, b * p.x() + d * p.y() + f};
    }
    /// this ∘ other (apply `other` first).
    Affine2 operator*(const Affine2& o) const {
        return {a * o.a + c * o.b, b * o.a + d * o.b,     a * o.c + c * o.d,
                b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
    }
    /// The uniform scale factor when the linear part is a similarity (rotation/reflection
    /// times a uniform scale), else a negative value.
    double similarityScale() const;
};

/// Parses an SVG transform list ("translate(10,20) scale(2) rotate(30 5 5) matrix(…)",
/// skewX, skewY); empty text = identity. Throws std::invalid_argument with a message.
Affine2 parseTransform(std::string_view text);

enum class SegmentKind { Line, Quadratic, Cubic, Arc };

/// One drawn segment in absolute coordinates. Lines use p0, p3; quadratics p0, p1 (control),
/// p3; cubics p0..p3; arcs only their end points p0, p3.
struct PathSegment {
    SegmentKind kind = SegmentKind::Line;
    Vec2 p0{0, 0}, p1{0, 0}, p2{0, 0}, p3{0, 0};
    int subpath = 0;  ///< index of the subpath (each M starts one)
};

/// Parses SVG path data with all commands (M L H V C S Q T A Z, absolute and relative, implicit
/// repetition, numbers run together like "1-2.5.5"). Z adds the closing line when it has
/// length. Throws std::invalid_argument("at character N: expected …") on bad data. A path
/// with only a moveto gives no segments.
std::vector<PathSegment> parsePathData(std::string_view d);

}  // namespace ramus::detail
