// Conditional distributions (seed 000 §4.5, §6.1): fixing features shifts the others as the
// regression on the data says, shrinks their variance by the Schur complement, and fails
// clearly when the condition is impossible.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "ramus/error.hpp"
#include "ramus/skeleton_stats.hpp"
#include "skeleton/thesis_model.hpp"

namespace ramus {
namespace {

using test::thesisModel;

// The least-squares slope of feature j on feature k over the species, computed from the data
// directly (not from the model's covariance matrix).
double regressionSlope(const Eigen::MatrixXd& data, int j, int k) {
    const Eigen::VectorXd x = data.col(k).array() - data.col(k).mean();
    const Eigen::VectorXd y = data.col(j).array() - data.col(j).mean();
    return x.dot(y) / x.dot(x);
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(StatsCondition, LegsEqualOneKeepsLegsNearOneAndShiftsTheRestAlongTheRegression) {
    const SkeletonStats& s = thesisModel();
    Rng rng(4);
    constexpr int kDraws = 100000;
    const ConditionalModel model = s.condition({Condition::legs(1.0)});
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(29), sumSq = Eigen::VectorXd::Zero(29);
    double minLegs = 1e9, maxLegs = -1e9;
    for (int i = 0; i < kDraws; ++i) {
        const Eigen::VectorXd x = model.sample(rng);
        const double legs = fromFeaturePoint(x).legs;
        minLegs = std::min(minLegs, legs);
        maxLegs = std::max(maxLegs, legs);
        sum += x;
        sumSq += x.cwiseProduct(x);
    }
    // The user value 1 pair plus a uniform offset from [−0.5, 0.5].
    EXPECT_GE(minLegs, 0.5);
    EXPECT_LE(maxLegs, 1.5);
    EXPECT_LT(minLegs, 0.51);
    EXPECT_GT(maxLegs, 1.49);
    const Eigen::VectorXd mean = sum / kDraws;
    EXPECT_NEAR(unscaleFeatureValue(kFeatureLegs, mean[kFeatureLegs]), 1.0, 0.005);

    // E[x_j | legs = b] = μ_j + slope·(b − μ_legs); the offset averages out (it is symmetric
    // and the conditional mean is linear in b).
    const double b = scaleFeatureValue(kFeatureLegs, 1.0);
    int shifted = 0;
    for (int j = 0; j < 29; ++j) {
        if (j == kFeatureLegs) continue;
        const double expected =
            s.mean()[j] + regressionSlope(s.data(), j, kFeatureLegs) * (b - s.mean()[kFeatureLegs]);
        const double sd = std::sqrt(std::max(0.0, sumSq[j] / kDraws - mean[j] * mean[j]));
        EXPECT_NEAR(mean[j], expected, 5 * sd / std::sqrt(kDraws) + 1e-12) << featureName(j);
        if (std::abs(expected - s.mean()[j]) > 10 * sd / std::sqrt(kDraws)) ++shifted;
    }
    EXPECT_GT(shifted, 10);  // conditioning on legs really moves most of the skeleton
}

TEST(StatsCondition, ExactConditionUsesTheSchurComplement) {
    const SkeletonStats& s = thesisModel();
    Rng rng(1);
    const ConditionalModel m = s.condition({{kFeatureLegs, 1.0, 0.0}});
    ASSERT_EQ(m.fixedFeatures, std::vector<int>{kFeatureLegs});
    ASSERT_EQ(m.freeFeatures.size(), 28u);
    EXPECT_DOUBLE_EQ(m.mean[kFeatureLegs], 0.005);
    const Eigen::MatrixXd& sigma = s.covariance();
    // Free feature 0 is p0_x; Σ̄₀₀ = Σ₀₀ − Σ₀L²/Σ_LL.
    const double expected = sigma(0, 0) - sigma(0, kFeatureLegs) * sigma(0, kFeatureLegs) /
                                              sigma(kFeatureLegs, kFeatureLegs);
    EXPECT_NEAR(m.covariance(0, 0), expected, 1e-12);
    const Eigen::MatrixXd back =
        m.eigenvectors * m.eigenvalues.asDiagonal() * m.eigenvectors.transpose();
    EXPECT_LT((back - m.covariance).norm(), 1e-12);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(m.sample(rng)[kFeatureLegs], 0.005);
}

TEST(StatsCondition, NeckAndTailLengthsAreConditionedInPixels) {
    const SkeletonStats& s = thesisModel();
    Rng rng(9);
    for (int i = 0; i < 200; ++i) {
        const SkeletonFeatures f = fromFeaturePoint(s.sampleConditioned(
            {Condition::neckYLength(150.0), Condition::tailXLength(300.0)}, rng));
        EXPECT_NEAR(f.neckYLength(), 150.0, 0.5 + 1e-9);
        EXPECT_NEAR(f.tailXLength(), 300.0, 0.5 + 1e-9);
    }
}

TEST(StatsCondition, FixingWingsNeverIncreasesAnyVariance) {
    // Fixing wings removes the variance the data explains by wings: every free feature's
    // conditional variance is at most its unconditional one.
    const SkeletonStats& s = thesisModel();
    Rng rng(3);
    const ConditionalModel m = s.condition({Condition::wings(0.0)});
    for (std::size_t k = 0; k < m.freeFeatures.size(); ++k) {
        const int f = m.freeFeatures[k];
        EXPECT_LE(m.covariance(k, k), s.covariance()(f, f) + 1e-15);
    }
    EXPECT_LT(m.eigenvalues.sum(), s.eigenvalues().sum());
}

TEST(StatsCondition, FixingEveryFeatureGivesExactlyThatPoint) {
    const SkeletonStats& s = thesisModel();
    const SkeletonFeatures horse = fromFeaturePoint(s.fromExample("Horse (warmblood)"));
    const Eigen::VectorXd x = s.fromExample("Horse (warmblood)");
    std::vector<Condition> all;
    for (int i = 0; i < kFeatureCount; ++i) all.push_back({i, unscaleFeatureValue(i, x[i]), 0.0});
    Rng rng(5);
    const Eigen::VectorXd sample = s.sampleConditioned(all, rng);
    EXPECT_LT((sample - x).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(fromFeaturePoint(sample).weightKg, horse.weightKg, 1e-6);
}

TEST(StatsCondition, NoConditionsGiveTheUnconditionedModel) {
    const SkeletonStats& s = thesisModel();
    Rng rng(5);
    const ConditionalModel m = s.condition({});
    EXPECT_EQ(m.mean, s.mean());
    EXPECT_LT((m.covariance - s.covariance()).norm(), 1e-15);
}

TEST(StatsCondition, ConditionOrderDoesNotChangeTheResult) {
    const SkeletonStats& s = thesisModel();
    Rng a(21), b(21);
    const Eigen::VectorXd x = s.sampleConditioned({Condition::legs(2), Condition::wings(0)}, a);
    const Eigen::VectorXd y = s.sampleConditioned({Condition::wings(0), Condition::legs(2)}, b);
    EXPECT_EQ(x, y);
}

TEST(StatsCondition, RejectsAFeatureIndexOutOfRange) {
    Rng rng(1);
    EXPECT_NE(errorOf([&] {
                  thesisModel().condition({{29, 1.0}});
              }).find("[0, 28]"),
              std::string::npos);
}

TEST(StatsCondition, RejectsAFeatureConditionedTwice) {
    Rng rng(1);
    EXPECT_NE(errorOf([&] {
                  thesisModel().condition({Condition::legs(1), Condition::legs(2)});
              }).find("legs given twice"),
              std::string::npos);
}

TEST(StatsCondition, RejectsANonFiniteValue) {
    Rng rng(1);
    EXPECT_NE(errorOf([&] {
                  thesisModel().condition({Condition::legs(std::nan(""))});
              }).find("not finite"),
              std::string::npos);
}

TEST(StatsCondition, RejectsANegativeJitter) {
    Rng rng(1);
    EXPECT_NE(errorOf([&] {
                  thesisModel().condition({{kFeatureLegs, 1.0, -1.0}});
              }).find("jitter"),
              std::string::npos);
}

TEST(StatsCondition, WingsOnDataWithoutWingedSpeciesIsImpossible) {
    std::vector<SpeciesRecord> wingless;
    for (const SpeciesRecord& r : builtinSpecies()) {
        if (r.features.wings == 0) wingless.push_back(r);
    }
    const SkeletonStats s = SkeletonStats::fit(wingless);
    Rng rng(1);
    const std::string message = errorOf([&] { s.condition({{kFeatureWings, 1.0, 0.0}}); });
    EXPECT_NE(message.find("impossible condition"), std::string::npos) << message;
    EXPECT_NE(message.find("wings = 1 pairs"), std::string::npos) << message;
    // The one value the data allows is fine, but not with a random offset.
    EXPECT_NO_THROW(s.condition({{kFeatureWings, 0.0, 0.0}}));
    EXPECT_NE(errorOf([&] { s.condition({Condition::wings(0.0)}); }).find("impossible condition"),
              std::string::npos);
}

TEST(StatsCondition, CollinearFeaturesAreRegularizedWhenConsistent) {
    // Every species with shank = thigh: Σ's (thigh, shank) block is singular.
    std::vector<SpeciesRecord> species = builtinSpecies();
    for (SpeciesRecord& r : species) r.features.limbs[4] = r.features.limbs[3];
    const SkeletonStats s = SkeletonStats::fit(species);
    Rng rng(1);
    const int thigh = kFeatureFirstLimb + 3, shank = kFeatureFirstLimb + 4;
    const ConditionalModel m = s.condition({{thigh, 150.0, 0.0}, {shank, 150.0, 0.0}});
    EXPECT_TRUE(m.mean.allFinite());
    EXPECT_TRUE(m.covariance.allFinite());
    // Same as conditioning on thigh alone.
    const ConditionalModel single = s.condition({{thigh, 150.0, 0.0}});
    for (int f : m.freeFeatures) EXPECT_NEAR(m.mean[f], single.mean[f], 1e-9) << featureName(f);
    const std::string message = errorOf([&] {
        s.condition({{thigh, 150.0, 0.0}, {shank, 90.0, 0.0}});
    });
    EXPECT_NE(message.find("impossible condition"), std::string::npos) << message;
}

}  // namespace
}  // namespace ramus
