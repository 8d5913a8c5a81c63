// Silhouette comparison of welded and tube meshes (welded_silhouette.hpp).
#include "welded_silhouette.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

#include "ramus/render.hpp"
#include "welded_checks.hpp"

namespace ramus::test {
namespace {

constexpr int kResolution = 512;  // pixels on the longer side of each view
constexpr double kMargin = 0.03;  // frame around the tube mesh's bounds, of its longer side

// The local branch radius (world units) at every pixel: of the thickest branch whose projected
// axis passes within twice its radius (plus a pixel, for twigs thinner than one) there, at the
// axis point nearest to the pixel — at a junction the thickest branch meeting there, as
// CapsuleUnion's scale. 0 = none. The orthographic projection of a capsule is exactly
// the 2-d capsule of its projected axis.
std::vector<double> branchRadii(const std::vector<Capsule>& capsules, const Camera& camera) {
    std::vector<double> radii(std::size_t(camera.width) * camera.height, 0.0);
    double* radius = radii.data();
    for (const Capsule& capsule : capsules) {
        const Vec2 a = camera.project(capsule.a), b = camera.project(capsule.b);
        const double ax = a.x(), ay = a.y(), abx = b.x() - ax, aby = b.y() - ay;
        const double ra = capsule.ra / camera.pixel, rb = capsule.rb / camera.pixel;
        const double reach = 2.0 * std::max(ra, rb) + 1.0;
        const double length2 = abx * abx + aby * aby;
        const int x0 = std::max(0, int(std::ceil(std::min(ax, b.x()) - reach - 0.5)));
        const int x1 =
            std::min(camera.width - 1, int(std::floor(std::max(ax, b.x()) + reach - 0.5)));
        const int y0 = std::max(0, int(std::ceil(std::min(ay, b.y()) - reach - 0.5)));
        const int y1 =
            std::min(camera.height - 1, int(std::floor(std::max(ay, b.y()) + reach - 0.5)));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5 - ax, py = y + 0.5 - ay;
                double s = length2 > 0.0 ? (px * abx + py * aby) / length2 : 0.0;
                s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
                const double r = ra + s * (rb - ra);
                const double dx = px - s * abx, dy = py - s * aby;
                if (dx * dx + dy * dy > (2.0 * r + 1.0) * (2.0 * r + 1.0)) continue;
                double& here = radius[std::size_t(y) * camera.width + x];
                if (r * camera.pixel > here) here = r * camera.pixel;
            }
        }
    }
    return radii;
}

// The `fraction` quantile of `values` (0 when empty).
double quantile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    const auto k = static_cast<std::size_t>(fraction * double(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + k, values.end());
    return values[k];
}

// The images of one view and what the measures need of them.
struct ViewMasks {
    const Mask& covered;       // centres covered by one mesh
    const Mask& otherTouched;  // pixels the other mesh touches
    const DistanceField& toOther;
    const DistanceField& toTube;  // to the pixels the tube mesh touches
};

SilhouetteDifference measure(const ViewMasks& masks, const double* radii, const Camera& camera,
                             std::size_t tubePixels, double& smallestRadius) {
    constexpr double kHalfDiagonal = 0.7071067811865476;
    std::vector<double> distances;
    std::vector<std::size_t> pixels;
    const std::uint8_t* covered = masks.covered.covered.data();
    const std::uint8_t* otherTouched = masks.otherTouched.covered.data();
    const double* toOther = masks.toOther.squared.data();
    const int* nearestTube = masks.toTube.nearest.data();
    for (std::size_t i = 0; i < masks.covered.covered.size(); ++i) {
        if (!covered[i] || otherTouched[i]) continue;
        const double radius = std::max(radii[i], radii[nearestTube[i]]);
        smallestRadius = std::min(smallestRadius, radius);
        const double apart = std::sqrt(toOther[i]) - kHalfDiagonal;
        // No branch near (not on a tube pixel's silhouette): infinitely far, fails every bound.
        distances.push_back(radius > 0.0 ? apart * camera.pixel / radius
                                         : std::numeric_limits<double>::infinity());
        pixels.push_back(i);
    }
    SilhouetteDifference difference;
    difference.area = double(distances.size()) / double(std::max<std::size_t>(tubePixels, 1));
    if (!distances.empty()) {
        const auto worst = std::max_element(distances.begin(), distances.end());
        difference.maxDistance = *worst;
        const std::size_t i = pixels[worst - distances.begin()];
        difference.worst = camera.worldAt(i % camera.width, i / camera.width);
    }
    difference.p99Distance = quantile(distances, 0.99);
    return difference;
}

// What a tree gives every view: both meshes, their bounds (computed once) and the branch
// capsules.
struct TreeMeshes {
    Mesh tube, welded;
    Aabb tubeBounds, weldedBounds;
    std::vector<Capsule> capsules;
};

ViewComparison compareView(const TreeMeshes& meshes, int axis) {
    const Camera camera = fitCamera(meshes.tubeBounds, axis, kResolution, kMargin);
    ViewComparison view;
    view.tube = rasterize(meshes.tube, camera);
    view.welded = rasterize(meshes.welded, camera);
    view.weldedInFrame = insideFrame(camera, meshes.weldedBounds);
    view.tubePixels = view.tube.centres.area();
    const DistanceField toTube = distanceTo(view.tube.touched);
    const DistanceField toWelded = distanceTo(view.welded.touched);
    const std::vector<double> radii = branchRadii(meshes.capsules, camera);
    double smallestRadius = std::numeric_limits<double>::infinity();
    view.lost = measure({view.tube.centres, view.welded.touched, toWelded, toTube}, radii.data(),
                        camera, view.tubePixels, smallestRadius);
    view.gained = measure({view.welded.centres, view.tube.touched, toTube, toTube}, radii.data(),
                          camera, view.tubePixels, smallestRadius);
    view.pixelInRadii = std::isfinite(smallestRadius) ? camera.pixel / smallestRadius : 0.0;
    return view;
}

using Rgb = std::array<std::uint8_t, 3>;

// Lost red, gained blue, covered by both grey, covered by one and touched by the other
// (aliasing of thin twigs, not counted) light grey, neither white.
Rgb pixelColour(const ViewComparison& view, std::size_t i) {
    const bool tube = view.tube.centres.covered[i], welded = view.welded.centres.covered[i];
    if (tube && welded) return {120, 120, 120};
    if (tube) return view.welded.touched.covered[i] ? Rgb{190, 190, 190} : Rgb{230, 20, 20};
    if (welded) return view.tube.touched.covered[i] ? Rgb{190, 190, 190} : Rgb{20, 60, 240};
    return {255, 255, 255};
}

// The three views side by side, 8 white pixels apart.
void writePicture(const std::array<ViewComparison, 3>& views, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir == nullptr || *dir == '\0') return;
    constexpr int kGap = 8;
    Image image;
    for (const ViewComparison& view : views) {
        image.width += view.tube.centres.width + kGap;
        image.height = std::max(image.height, view.tube.centres.height);
    }
    image.rgba.assign(std::size_t(image.width) * image.height * 4, 255);
    int left = 0;
    for (const ViewComparison& view : views) {
        const int width = view.tube.centres.width;
        for (int y = 0; y < view.tube.centres.height; ++y) {
            for (int x = 0; x < width; ++x) {
                const Rgb colour = pixelColour(view, std::size_t(y) * width + x);
                std::copy(colour.begin(), colour.end(),
                          image.rgba.begin() + (std::size_t(y) * image.width + left + x) * 4);
            }
        }
        left += width + kGap;
    }
    writePng(image, std::string(dir) + "/silhouette_" + name + ".png");
}

// The examples beyond those tolerances, bounded at their values measured on 2026-12-04 after
// session 18 shrank webbed junction hulls onto their branches and session 19 shrank those at
// crossings too (the largest of the three views, docs/welded.md "Quality and limits") plus
// 15 %, rounded up: they must not grow. Nothing the tubes show is missing in any of them (the
// hedges lost 0.11–0.18 % of their area within 0.24 radii until session 24 added the tube
// mesher's ring at a branch node where the branch bends there: the hull had cut its outer
// corner; 0.01–0.02 % within 0.19 since). They gain silhouette where junction hulls still span
// more than the crotch:
// - ABOP 1.27 and 1.31a were exceptions until session 47: junctions over clusters of tips,
//   not star-shaped from any centre tried, so some moves were halved (1.27 4.0 % of the area
//   and 5.4 radii, 1.31a 1.2 %, after sessions 19–22; 12 % and 30 % before). All the junctions
//   that kept such webs there were at crossings, and since session 47 those are capped tubes
//   when welding alone (WeldedMeshParams::tubesAtCrossings): both gain nothing now. Shrinking
//   the junctions at crossings had brought 1.24a (1.6 % / 1.0 radius → 0.3 % / 0.72) and
//   conifer (a bump beside the trunk, 11.8 radii → 0.26) within the tolerances before.
// - hedge_0 and 2–4 (0.52–0.82 % of the area, within 0.73 radii): what is left of the base
//   junctions where several main branches leave the trunk at once; before the shrinking they
//   were one convex hull over the whole crotch (hedge_4: 2.2 % of the area, 6.9 radii;
//   hedge_0–3 1.5–2.3 %, 2.4–3.8 radii). hedge_1 was 1.3 % and 3.8 radii until session 19 moved the
//   rays' centre of a junction whose corners' mean lies outside the branches onto a branch axis,
//   and 0.72 % and 2.3 until session 20 tried more centres. fig3_2_ring (1.3 radii) was one until
//   session 22: the surface pulled into the crotch of a junction of three branches 2° and 30° apart
//   turned nearly edge-on to its rays, and the check that each triangle faces away from the centre
//   asked for more than that.
// Before the solver change (the rings of slow pairs leapfrogged out along their limbs) every
// dense ABOP plant and every colonization tree was an exception here, e.g. 2.8a with 78 % of
// the tube silhouette's area added up to 30 radii from it, 2.6d 90 % and 41 radii.
const std::vector<std::pair<std::string, SilhouetteBounds>>& exceptions() {
    static const std::vector<std::pair<std::string, SilhouetteBounds>> kExceptions = {
        {"hedge_0", {.gainedArea = 0.0095}},
        {"hedge_2", {.gainedArea = 0.006}},
        {"hedge_3", {.gainedArea = 0.0079}},
        {"hedge_4", {.gainedArea = 0.0074}},
    };
    return kExceptions;
}

}  // namespace

SilhouetteViews compareSilhouettes(const BranchTree& tree, const TubeMeshParams& tube,
                                   const Mesh& welded, const std::string& name) {
    // The welded mesh is always closed; the tubes must be too (capped tips and bases), or a
    // branch seen end-on would show a hole.
    TubeMeshParams tubeParams = tube;
    tubeParams.capTips = true;
    TreeMeshes meshes{buildTubeMesh(tree, tubeParams), welded};
    meshes.tubeBounds = meshes.tube.bounds();
    meshes.weldedBounds = meshes.welded.bounds();
    const std::vector<double> radii = computeEdgeRadii(tree, tube);
    meshes.capsules = branchCapsules(tree, radii, tube.trunkMultiplier * radii[0]);
    SilhouetteViews views;
    for (int axis = 0; axis < 3; ++axis) views[axis] = compareView(meshes, axis);
    writePicture(views, name);
    for (int axis = 0; axis < 3; ++axis) {
        const ViewComparison& v = views[axis];
        std::printf(
            "%-22s %c %7zu  lost %.4f max %6.2f p99 %5.2f  gained %.4f max %6.2f p99 %5.2f  "
            "px %.3f  worst lost (%.1f, %.1f) gained (%.1f, %.1f)\n",
            name.c_str(), "xyz"[axis], v.tubePixels, v.lost.area, v.lost.maxDistance,
            v.lost.p99Distance, v.gained.area, v.gained.maxDistance, v.gained.p99Distance,
            v.pixelInRadii, v.lost.worst.x(), v.lost.worst.y(), v.gained.worst.x(),
            v.gained.worst.y());
    }
    return views;
}

void expectSilhouetteWithinBounds(const SilhouetteViews& views, const SilhouetteBounds& bounds) {
    for (int axis = 0; axis < 3; ++axis) {
        SCOPED_TRACE(std::string("view along ") + "xyz"[axis]);
        const ViewComparison& view = views[axis];
        EXPECT_TRUE(view.weldedInFrame);
        EXPECT_LE(view.lost.maxDistance, bounds.lostDistance);
        EXPECT_LE(view.lost.area, bounds.lostArea);
        EXPECT_LE(view.gained.maxDistance, bounds.gainedDistance);
        EXPECT_LE(view.gained.area, bounds.gainedArea);
    }
}

SilhouetteBounds silhouetteBounds(const std::string& example, bool united) {
    // United, the junctions whose shrunk faces stay more than a local radius outside the
    // branches are tubes (WeldReport::tubedForUnion, session 24): every example is within the
    // global bounds.
    if (united) return {};
    for (const auto& [name, exception] : exceptions()) {
        if (name == example) return exception;
    }
    return {};
}

}  // namespace ramus::test
