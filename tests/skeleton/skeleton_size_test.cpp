// Real size: the allometric rule (recomputed from data/species/sizes.csv and the species
// weights) and the height/length overrides.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ramus/error.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"
#include "ramus/species.hpp"

namespace ramus {
namespace {

const std::string kSizesFile = std::string(RAMUS_SOURCE_DIR) + "/data/species/sizes.csv";

struct SizeRow {
    std::string name;
    std::string basis;
    double extentMetres = 0.0;
};

// data/species/sizes.csv: '#' comment lines, a header, then name,basis,extent_m,note.
std::vector<SizeRow> readSizes() {
    std::ifstream in(kSizesFile);
    EXPECT_TRUE(in) << kSizesFile;
    std::vector<SizeRow> rows;
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> fields;
        std::stringstream ss(line);
        std::string field;
        while (std::getline(ss, field, ',')) fields.push_back(field);
        if (header) {
            EXPECT_EQ(line, "name,basis,extent_m,note");
            header = false;
            continue;
        }
        EXPECT_GE(fields.size(), 3u) << line;
        EXPECT_LE(fields.size(), 4u) << "a comma in the note: " << line;
        if (fields.size() < 3) continue;
        rows.push_back({fields[0], fields[1], std::stod(fields[2])});
    }
    return rows;
}

double roundToSignificant(double value, int digits) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    return std::stod(buffer);
}

TEST(SkeletonSize, SizesFileHasEverySpeciesOnce) {
    const std::vector<SizeRow> rows = readSizes();
    std::set<std::string> names;
    for (const SizeRow& row : rows) {
        EXPECT_TRUE(names.insert(row.name).second) << "twice: " << row.name;
        EXPECT_TRUE(row.basis == "length" || row.basis == "head_body" || row.basis == "height")
            << row.name << ": " << row.basis;
        EXPECT_GT(row.extentMetres, 0.0) << row.name;
    }
    std::set<std::string> species;
    for (const SpeciesRecord& record : builtinSpecies()) species.insert(record.name);
    EXPECT_EQ(names, species);
    EXPECT_EQ(rows.size(), 44u);
}

TEST(SkeletonSize, RuleConstantsMatchTheFit) {
    std::map<std::string, double> weight;
    for (const SpeciesRecord& record : builtinSpecies()) {
        weight[record.name] = record.features.weightKg;
    }
    const std::vector<SizeRow> rows = readSizes();
    ASSERT_EQ(rows.size(), 44u);
    // Least squares of log(extent) = log(a) + b·log(W).
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const SizeRow& row : rows) {
        const double x = std::log(weight.at(row.name));
        const double y = std::log(row.extentMetres);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double n = static_cast<double>(rows.size());
    const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double a = std::exp((sy - b * sx) / n);
    EXPECT_EQ(roundToSignificant(a, 4), kSizeRuleCoefficient) << a;
    EXPECT_EQ(roundToSignificant(b, 4), kSizeRuleExponent) << b;
    double squares = 0;
    for (const SizeRow& row : rows) {
        const double residual =
            std::log(row.extentMetres) - std::log(a) - b * std::log(weight.at(row.name));
        squares += residual * residual;
    }
    // The typical error the header and docs quote.
    EXPECT_EQ(roundToSignificant(std::exp(std::sqrt(squares / n)), 3), 1.36);
}

TEST(SkeletonSize, ElephantIsMetresAndShrewCentimetres) {
    const double elephant = skeletonExtentFromWeight(4000.0);
    EXPECT_GT(elephant, 3.0);
    EXPECT_LT(elephant, 10.0);
    const double shrew = skeletonExtentFromWeight(0.005);  // a 5 g shrew
    EXPECT_GT(shrew, 0.01);
    EXPECT_LT(shrew, 0.1);
    const double whale = skeletonExtentFromWeight(kMaxWeightKg);
    EXPECT_GT(whale, 15.0);
    EXPECT_LT(whale, 40.0);
}

TEST(SkeletonSize, ExtentFollowsTheRuleAndGrowsWithWeight) {
    EXPECT_DOUBLE_EQ(skeletonExtentFromWeight(1.0), kSizeRuleCoefficient);
    EXPECT_DOUBLE_EQ(skeletonExtentFromWeight(1000.0),
                     kSizeRuleCoefficient * std::pow(1000.0, kSizeRuleExponent));
    double previous = 0.0;
    for (double w = kSizeRuleMinWeightKg; w <= kMaxWeightKg; w *= 1.5) {
        const double extent = skeletonExtentFromWeight(w);
        EXPECT_GT(extent, previous) << w;
        previous = extent;
    }
}

TEST(SkeletonSize, ScaleIsTheExtentPerThousandPixels) {
    for (double w : {0.01, 1.0, 93.0, 50000.0}) {
        EXPECT_DOUBLE_EQ(skeletonScaleFromWeight(w), skeletonExtentFromWeight(w) / 1000.0);
    }
}

TEST(SkeletonSize, WeightsOutsideTheRangeAreClamped) {
    const double smallest = skeletonExtentFromWeight(kSizeRuleMinWeightKg);
    EXPECT_EQ(skeletonExtentFromWeight(0.0), smallest);
    EXPECT_EQ(skeletonExtentFromWeight(-3.0), smallest);
    EXPECT_EQ(skeletonExtentFromWeight(std::numeric_limits<double>::quiet_NaN()), smallest);
    const double largest = skeletonExtentFromWeight(kMaxWeightKg);
    EXPECT_EQ(skeletonExtentFromWeight(1e9), largest);
    EXPECT_EQ(skeletonExtentFromWeight(std::numeric_limits<double>::infinity()), largest);
}

// A root at the origin and one bone 100 px long, 10 px high, 4 px wide, turned 90° about z at
// (10, 20, 0): it spans x ∈ [5, 15], y ∈ [20, 120], so the box is x ∈ [0, 15], y ∈ [0, 120].
Skeleton uprightBone() {
    Skeleton skeleton;
    skeleton.bones.resize(2);
    skeleton.bones[1].kind = BoneKind::Vertebra;
    skeleton.bones[1].parent = 0;
    skeleton.bones[1].extents = Vec3(100, 10, 4);
    skeleton.bones[1].joint.position = Vec3(10, 20, 0);
    skeleton.bones[1].joint.rest << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    skeleton.metresPerPixel = 0.0042;
    return skeleton;
}

TEST(SkeletonSize, HeightOverrideScalesTheBoundingBoxHeight) {
    EXPECT_DOUBLE_EQ(skeletonScaleForExtent(uprightBone(), 2.4, std::nullopt), 2.4 / 120.0);
}

TEST(SkeletonSize, LengthOverrideScalesTheBoundingBoxLength) {
    EXPECT_DOUBLE_EQ(skeletonScaleForExtent(uprightBone(), std::nullopt, 0.3), 0.3 / 15.0);
}

TEST(SkeletonSize, NoOverrideKeepsTheSkeletonsScale) {
    EXPECT_EQ(skeletonScaleForExtent(uprightBone(), std::nullopt, std::nullopt), 0.0042);
}

TEST(SkeletonSize, HeightAndLengthTogetherAreAnError) {
    EXPECT_THROW(skeletonScaleForExtent(uprightBone(), 1.0, 2.0), Error);
}

TEST(SkeletonSize, NonPositiveOrNonFiniteOverrideIsAnError) {
    EXPECT_THROW(skeletonScaleForExtent(uprightBone(), 0.0, std::nullopt), Error);
    EXPECT_THROW(skeletonScaleForExtent(uprightBone(), std::nullopt, -1.0), Error);
    EXPECT_THROW(skeletonScaleForExtent(uprightBone(), std::numeric_limits<double>::infinity(),
                                        std::nullopt),
                 Error);
}

TEST(SkeletonSize, SkeletonWithoutExtentCannotBeScaled) {
    Skeleton empty;
    EXPECT_THROW(skeletonScaleForExtent(empty, 1.0, std::nullopt), Error);
    Skeleton rootOnly;
    rootOnly.bones.resize(1);
    EXPECT_THROW(skeletonScaleForExtent(rootOnly, std::nullopt, 1.0), Error);
}

}  // namespace
}  // namespace ramus
