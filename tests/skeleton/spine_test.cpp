// The spine Béziers (seed 000 §5.3, §7.4.2): points, arc lengths against closed forms and fine
// polylines, the C1 fix at shoulder and hip, and the vertebra sample points.
#include <gtest/gtest.h>

#include <cmath>

#include "ramus/skeleton_stats.hpp"
#include "skeleton/skeleton_build.hpp"
#include "skeleton/thesis_model.hpp"

namespace ramus::detail {
namespace {

using test::thesisModel;

// A spine whose back is the given cubic; neck and tail collapse onto P3 and P6.
Spine backOnly(const Vec2& p0, const Vec2& p1, const Vec2& p2, const Vec2& p3) {
    Spine s;
    for (int i = 0; i <= 3; ++i) s.points[i] = p0;
    s.points[4] = p1;
    s.points[5] = p2;
    for (int i = 6; i < kSpinePointCount; ++i) s.points[i] = p3;
    return s;
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Length of the polyline through `segments` + 1 evenly spaced parameters.
double polylineLength(const Spine& s, SpinePart part, int segments) {
    double sum = 0.0;
    Vec2 previous = spinePoint(s, part, 0.0);
    for (int i = 1; i <= segments; ++i) {
        const Vec2 p = spinePoint(s, part, static_cast<double>(i) / segments);
        sum += (p - previous).norm();
        previous = p;
    }
    return sum;
}

SkeletonFeatures kinkedFeatures() {
    SkeletonFeatures f;
    f.spine = {Vec2(100, 600), Vec2(150, 560), Vec2(200, 540), Vec2(300, 500), Vec2(400, 560),
               Vec2(600, 580), Vec2(700, 500), Vec2(760, 480), Vec2(820, 380), Vec2(900, 300)};
    return f;
}

TEST(Spine, BezierPassesThroughItsEndpointsAndItsKnownMidpoint) {
    const Spine s = backOnly(Vec2(0, 0), Vec2(10, 30), Vec2(50, 30), Vec2(60, 0));
    EXPECT_EQ(spinePoint(s, SpinePart::Back, 0.0), Vec2(0, 0));
    EXPECT_EQ(spinePoint(s, SpinePart::Back, 1.0), Vec2(60, 0));
    // B(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8
    const Vec2 mid = spinePoint(s, SpinePart::Back, 0.5);
    EXPECT_NEAR(mid.x(), (0 + 30 + 150 + 60) / 8.0, 1e-12);
    EXPECT_NEAR(mid.y(), (0 + 90 + 90 + 0) / 8.0, 1e-12);
    // B'(0) = 3 (P1 − P0)
    EXPECT_NEAR((spineDerivative(s, SpinePart::Back, 0.0) - Vec2(30, 90)).norm(), 0.0, 1e-12);
}

TEST(Spine, PartsUseTheirOwnControlPoints) {
    const Spine s = makeSpine(kinkedFeatures());
    EXPECT_EQ(spinePoint(s, SpinePart::Neck, 0.0), s.points[0]);
    EXPECT_EQ(spinePoint(s, SpinePart::Neck, 1.0), s.points[3]);
    EXPECT_EQ(spinePoint(s, SpinePart::Back, 0.0), s.points[3]);
    EXPECT_EQ(spinePoint(s, SpinePart::Tail, 0.0), s.points[6]);
    EXPECT_EQ(spinePoint(s, SpinePart::Tail, 1.0), s.points[9]);
}

TEST(Spine, StraightBezierIsAsLongAsTheDistanceEvenWithUnevenSpeed) {
    // Control points on a line, bunched at the start: the speed varies strongly along t.
    const Vec2 d = Vec2(3, 4).normalized();
    const Spine s =
        backOnly(Vec2(5, 7), Vec2(5, 7) + 1.0 * d, Vec2(5, 7) + 2.0 * d, Vec2(5, 7) + 250.0 * d);
    EXPECT_NEAR(spineLength(s, SpinePart::Back), 250.0, 250.0 * 1e-12);
    // Partial length = distance between the two points.
    const double partial =
        (spinePoint(s, SpinePart::Back, 0.7) - spinePoint(s, SpinePart::Back, 0.2)).norm();
    EXPECT_NEAR(spineLength(s, SpinePart::Back, 0.2, 0.7), partial, partial * 1e-12);
    EXPECT_NEAR(spineLength(s, SpinePart::Back, 0.7, 0.2), -partial, partial * 1e-12);
}

TEST(Spine, ArcLengthMatchesAFinePolylineToNineDigits) {
    const Spine s = makeSpine(kinkedFeatures());
    for (SpinePart part : {SpinePart::Neck, SpinePart::Back, SpinePart::Tail}) {
        // The polyline error shrinks as 1/n²: 2·10⁶ segments are good to ~1e-12.
        const double reference = polylineLength(s, part, 2000000);
        EXPECT_NEAR(spineLength(s, part), reference, reference * 1e-9);
    }
}

TEST(Spine, ArcLengthThroughACuspMatchesAFinePolyline) {
    // B'(t) = 3((1 − 2t)², 1 − 2t) vanishes at t = 1/2: a cusp.
    const Spine s = backOnly(Vec2(0, 0), Vec2(100, 100), Vec2(0, 100), Vec2(100, 0));
    EXPECT_NEAR(spineDerivative(s, SpinePart::Back, 0.5).norm(), 0.0, 1e-12);
    const double reference = polylineLength(s, SpinePart::Back, 2000000);
    EXPECT_NEAR(spineLength(s, SpinePart::Back), reference, reference * 1e-9);
}

TEST(Spine, ArcLengthIsAdditive) {
    const Spine s = makeSpine(kinkedFeatures());
    const double whole = spineLength(s, SpinePart::Back);
    const double sum =
        spineLength(s, SpinePart::Back, 0.0, 0.37) + spineLength(s, SpinePart::Back, 0.37, 1.0);
    EXPECT_NEAR(sum, whole, whole * 1e-12);
}

TEST(Spine, C1FixMakesTheTangentsAgreeAtShoulderAndHip) {
    const SkeletonFeatures f = kinkedFeatures();
    // Before: the curves meet at an angle.
    const Spine raw = [&] {
        Spine r;
        r.points = f.spine;
        return r;
    }();
    EXPECT_GT(std::abs(cross(spineDerivative(raw, SpinePart::Neck, 1.0).normalized(),
                             spineDerivative(raw, SpinePart::Back, 0.0).normalized())),
              0.1);
    const Spine s = makeSpine(f);
    for (auto [before, after] : {std::pair{SpinePart::Neck, SpinePart::Back},
                                 std::pair{SpinePart::Back, SpinePart::Tail}}) {
        const Vec2 in = spineDerivative(s, before, 1.0).normalized();
        const Vec2 out = spineDerivative(s, after, 0.0).normalized();
        EXPECT_NEAR(cross(in, out), 0.0, 1e-12);
        EXPECT_GT(in.dot(out), 0.0);
    }
    // The joints stay, the curves' other control points stay.
    for (int i : {0, 1, 3, 6, 8, 9}) EXPECT_EQ(s.points[i], f.spine[i]) << i;
    for (int i : {2, 4, 5, 7}) EXPECT_NE(s.points[i], f.spine[i]) << i;
}

TEST(Spine, C1FixRotatesBothNeighboursByEqualAndOppositeAngles) {
    const SkeletonFeatures f = kinkedFeatures();
    const Spine s = makeSpine(f);
    auto angle = [](const Vec2& from, const Vec2& to) {
        return std::atan2(cross(from, to), from.dot(to));
    };
    const Vec2 joint = f.spine[3];
    const double turnBefore = angle(f.spine[2] - joint, s.points[2] - joint);
    const double turnAfter = angle(f.spine[4] - joint, s.points[4] - joint);
    EXPECT_GT(std::abs(turnBefore), 1e-3);
    EXPECT_NEAR(turnBefore, -turnAfter, 1e-12);
    EXPECT_NEAR((s.points[2] - joint).norm(), (f.spine[2] - joint).norm(), 1e-9);
    EXPECT_NEAR((s.points[4] - joint).norm(), (f.spine[4] - joint).norm(), 1e-9);
}

TEST(Spine, C1FixLeavesASmoothJointAlone) {
    SkeletonFeatures f = kinkedFeatures();
    f.spine[2] = Vec2(250, 500);
    f.spine[4] = Vec2(380, 500);  // P2, P3, P4 on y = 500
    f.spine[5] = Vec2(600, 500);
    f.spine[6] = Vec2(700, 500);
    f.spine[7] = Vec2(800, 500);  // P5, P6, P7 on y = 500
    const Spine s = makeSpine(f);
    for (int i = 0; i < kSpinePointCount; ++i) {
        EXPECT_NEAR((s.points[i] - f.spine[i]).norm(), 0.0, 1e-12) << i;
    }
}

TEST(Spine, C1FixSkipsAMissingNeckAndUsesTheNextDistinctPoint) {
    SkeletonFeatures f = kinkedFeatures();
    for (int i = 0; i < 3; ++i) f.spine[i] = f.spine[3];  // no neck
    f.spine[7] = f.spine[6];                              // tail's P7 on the hip
    const Spine s = makeSpine(f);
    for (int i = 0; i <= 4; ++i) EXPECT_EQ(s.points[i], f.spine[i]) << i;
    EXPECT_FALSE(s.hasNeck);
    EXPECT_TRUE(s.hasTail);
    EXPECT_EQ(s.points[7], f.spine[6]);
    // The tail's tangent at the hip comes from P8 now; it agrees with the back's.
    const Vec2 in = spineDerivative(s, SpinePart::Back, 1.0).normalized();
    const Vec2 out = (s.points[8] - s.points[6]).normalized();
    EXPECT_NEAR(cross(in, out), 0.0, 1e-12);
    EXPECT_GT(in.dot(out), 0.0);
}

TEST(Spine, SpeciesWithoutNeckOrTailHaveNone) {
    const Spine trout = makeSpine(fromFeaturePoint(thesisModel().fromExample("Trout")));
    EXPECT_FALSE(trout.hasNeck);
    EXPECT_TRUE(trout.hasTail);
    const Spine frog = makeSpine(fromFeaturePoint(thesisModel().fromExample("Frog")));
    EXPECT_TRUE(frog.hasNeck);
    EXPECT_FALSE(frog.hasTail);
    const Spine snake = makeSpine(fromFeaturePoint(thesisModel().fromExample("Snake")));
    EXPECT_FALSE(snake.hasNeck);
    EXPECT_FALSE(snake.hasTail);
}

TEST(Spine, EveryMeasuredNeckAndTailIsLongEnoughToCarryVertebrae) {
    for (const SpeciesRecord& species : thesisModel().species()) {
        const auto& p = species.features.spine;
        const Spine s = makeSpine(species.features);
        EXPECT_EQ(s.hasNeck, p[0] != p[3]) << species.name;
        EXPECT_EQ(s.hasTail, p[9] != p[6]) << species.name;
    }
}

TEST(Spine, ArcLengthSamplesCutEqualLengths) {
    const Spine s = makeSpine(kinkedFeatures());
    const double total = spineLength(s, SpinePart::Back, 0.1, 0.9);
    const std::vector<double> t =
        spineSamples(s, SpinePart::Back, 0.1, 0.9, 12, SpineSpacing::ArcLength);
    ASSERT_EQ(t.size(), 13u);
    EXPECT_EQ(t.front(), 0.1);
    EXPECT_EQ(t.back(), 0.9);
    for (std::size_t i = 1; i < t.size(); ++i) {
        EXPECT_GT(t[i], t[i - 1]);
        EXPECT_NEAR(spineLength(s, SpinePart::Back, t[i - 1], t[i]), total / 12, total * 1e-10);
        // Short pieces of a gentle curve: chord ≈ arc.
        const double chord =
            (spinePoint(s, SpinePart::Back, t[i]) - spinePoint(s, SpinePart::Back, t[i - 1]))
                .norm();
        EXPECT_NEAR(chord, total / 12, 0.01 * total / 12);
    }
}

TEST(Spine, ArcLengthSamplesRunBackwardsWhenAsked) {
    const Spine s = makeSpine(kinkedFeatures());
    const std::vector<double> down =
        spineSamples(s, SpinePart::Neck, 1.0, 0.0, 7, SpineSpacing::ArcLength);
    const std::vector<double> up =
        spineSamples(s, SpinePart::Neck, 0.0, 1.0, 7, SpineSpacing::ArcLength);
    ASSERT_EQ(down.size(), 8u);
    for (std::size_t i = 0; i < down.size(); ++i) EXPECT_EQ(down[i], up[up.size() - 1 - i]);
}

TEST(Spine, ParameterSamplesAreAtIOverN) {
    const Spine s = makeSpine(kinkedFeatures());
    const std::vector<double> t =
        spineSamples(s, SpinePart::Back, 0.5, 0.0, 4, SpineSpacing::Parameter);
    EXPECT_EQ(t, (std::vector<double>{0.5, 0.375, 0.25, 0.125, 0.0}));
}

TEST(Spine, ZeroLengthPartFallsBackToParameterSteps) {
    const Spine s = makeSpine(fromFeaturePoint(thesisModel().fromExample("Snake")));
    const std::vector<double> t =
        spineSamples(s, SpinePart::Neck, 0.0, 1.0, 4, SpineSpacing::ArcLength);
    EXPECT_EQ(t, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
    EXPECT_EQ(spineLength(s, SpinePart::Neck), 0.0);
}

TEST(Spine, RootSitsAtHalfTheBackByParameterOrByArcLength) {
    const Spine s = makeSpine(kinkedFeatures());
    EXPECT_EQ(spineRootParameter(s, SpineSpacing::Parameter), 0.5);
    const double t = spineRootParameter(s, SpineSpacing::ArcLength);
    const double total = spineLength(s, SpinePart::Back);
    EXPECT_NEAR(spineLength(s, SpinePart::Back, 0.0, t), 0.5 * total, total * 1e-11);
    EXPECT_NE(t, 0.5);  // the back's speed varies, so the two differ
}

TEST(Spine, ParameterAtLengthClampsToTheCurve) {
    const Spine s = makeSpine(kinkedFeatures());
    EXPECT_EQ(spineParameterAtLength(s, SpinePart::Tail, 0.3, 0.0), 0.3);
    EXPECT_EQ(spineParameterAtLength(s, SpinePart::Tail, 0.3, -5.0), 0.3);
    EXPECT_EQ(spineParameterAtLength(s, SpinePart::Tail, 0.3, 1e6), 1.0);
    const double t = spineParameterAtLength(s, SpinePart::Tail, 0.3, 40.0);
    EXPECT_NEAR(spineLength(s, SpinePart::Tail, 0.3, t), 40.0, 1e-9);
}

}  // namespace
}  // namespace ramus::detail
