// Silhouettes of the welded mesh against the tube mesh on every shipped example (issue 9: "its
// silhouette stays within a tolerance of the tube version"; the method in welded_silhouette.hpp).
#include "welded_silhouette.hpp"

#include <gtest/gtest.h>

#include <string>

#include "ramus/welded_mesher.hpp"
#include "welded_checks.hpp"

namespace ramus {
namespace {

// The bounds, and the examples beyond the global ones, are in welded_silhouette.cpp
// (silhouetteBounds). United (--union) every example meets the global bounds of the gained
// silhouette: SolidUnion.DenseWeldedPlantsBecomeOneSurface and make union-check.

// Every L-system example at its default derivations, the dense ones included.
TEST(WeldedSilhouette, LSystemExamplesMatchTheTubeSilhouetteWithinBounds) {
    for (const std::string& file : test::exampleFiles("/examples/lsystems", ".lsys")) {
        const std::string name = test::stem(file);
        SCOPED_TRACE(name);
        const BranchTree tree = test::growLSystem(file);
        test::expectSilhouetteWithinBounds(
            test::compareSilhouettes(tree, {}, buildWeldedTreeMesh(tree), name),
            test::silhouetteBounds(name, false));
    }
}

// Every tree of every colonization example, meshed with its config's settings.
TEST(WeldedSilhouette, ColonizationTreesMatchTheTubeSilhouetteWithinBounds) {
    test::forEachColonizationTree([](const std::string& name, const BranchTree& tree,
                                     const WeldedMeshParams& params) {
        SCOPED_TRACE(name);
        test::expectSilhouetteWithinBounds(
            test::compareSilhouettes(tree, params.tube, buildWeldedTreeMesh(tree, params), name),
            test::silhouetteBounds(name, false));
    });
}

}  // namespace
}  // namespace ramus
