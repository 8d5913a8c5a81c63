// The PCA over the thesis's 44 species must reproduce the figures seed 000 §4.3–4.4 reports
// (SPEC §E), and the model's sampling, projection and variation must behave as specified.
#include "ramus/skeleton_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ramus/error.hpp"
#include "skeleton/thesis_model.hpp"

namespace ramus {
namespace {

using test::thesisModel;

TEST(SkeletonStats, BuiltinDataHas44SpeciesAnd29Dimensions) {
    const SkeletonStats& s = thesisModel();
    EXPECT_EQ(s.species().size(), 44u);
    EXPECT_EQ(s.data().rows(), 44);
    EXPECT_EQ(s.data().cols(), kFeatureCount);
}

TEST(SkeletonStats, ReproducesTheThesisEigenvalueCounts) {
    const SkeletonStats& s = thesisModel();
    EXPECT_EQ(s.countEigenvaluesAbove(0.01), 7);
    EXPECT_EQ(s.countEigenvaluesAbove(0.001), 17);
    EXPECT_NEAR(s.eigenvalues()[0], 0.34922, 0.000005);
    // "29 eigenvalues greater than 0; the smallest is 0.000001" (seed 000 §4.4).
    EXPECT_GT(s.eigenvalues()[28], 0.0);
    EXPECT_NEAR(s.eigenvalues()[28], 0.000001, 0.0000005);
}

TEST(SkeletonStats, ReproducesTheThesisExplainedVariance) {
    const SkeletonStats& s = thesisModel();
    EXPECT_NEAR(s.explainedVariance(6), 0.9224, 0.00005);
    EXPECT_NEAR(s.explainedVariance(10), 0.9693, 0.00005);
    EXPECT_NEAR(s.explainedVariance(20), 0.9980, 0.00005);
    EXPECT_DOUBLE_EQ(s.explainedVariance(29), 1.0);
    EXPECT_DOUBLE_EQ(s.explainedVariance(0), 0.0);
}

TEST(SkeletonStats, ReproducesTheThesisMean) {
    const SkeletonFeatures mean = fromFeaturePoint(thesisModel().mean());
    EXPECT_NEAR(mean.wings, 0.159, 0.0005);  // 7 of 44 species have wings
    EXPECT_NEAR(mean.wings, 7.0 / 44.0, 1e-12);
    EXPECT_NEAR(mean.legs, 1.39, 0.005);
    EXPECT_NEAR(mean.weightKg, 92.9, 0.05);  // the thesis rounds to 93 kg
}

TEST(SkeletonStats, RockHyraxIsNearestAndSnakeThenSwanFarthest) {
    const PcaReport report = makePcaReport(thesisModel());
    EXPECT_EQ(report.nearest, "Rock hyrax");
    EXPECT_EQ(report.farthest, "Snake");
    EXPECT_EQ(report.secondFarthest, "Swan");
}

TEST(SkeletonStats, FirstEigenvectorIsDominatedByTheNeckYCoordinates) {
    // Seed 000 §4.4: the largest entries of the first eigenvector are the y coordinates of the
    // neck curve's first three control points.
    const PcaReport report = makePcaReport(thesisModel());
    ASSERT_EQ(report.topEntries.size(), 7u);
    std::vector<int> top;
    for (int i = 0; i < 3; ++i) top.push_back(report.topEntries[0][i].feature);
    std::sort(top.begin(), top.end());
    EXPECT_EQ(top, (std::vector<int>{1, 3, 5}));
}

// The thesis's implementation maps a point back to a weight by adding, per eigenvector,
// 10^(Δᵢ·k) − 1 kg to the mean's weight (Δᵢ = that eigenvector's scaled weight offset), instead
// of inverting the log scaling of the sum. Its figure captions use that mapping; ramus inverts
// properly. This reproduces the captions' weights to show where they come from.
double thesisCaptionWeight(const SkeletonStats& s, const Eigen::VectorXd& q) {
    const double k = 100 * std::log10(kMaxWeightKg + 1);
    double weight = fromFeaturePoint(s.mean()).weightKg;
    for (Eigen::Index i = 0; i < q.size(); ++i) {
        weight += std::pow(10.0, q[i] * s.eigenvectors()(kFeatureWeight, i) * k) - 1;
    }
    return weight;
}

TEST(SkeletonStats, ReproducesTheThesisFigureA6Captions) {
    // Seed 000 fig. A.6: wings, legs and weight at −σ and +σ along the first six axes, as
    // printed. Eigenvector signs are arbitrary: ramus makes each one's largest entry positive,
    // which flips axes 1–5 relative to the thesis, so the thesis's "−" is our "+" there.
    // Two captions (2−, 4+ wings: 0.014, 0.022) are matched only to 0.002 (ours: 0.0154,
    // 0.0204); every other number matches to its printed digits.
    struct Caption {
        double wings, wingsTolerance, legs, legsTolerance, weight;
    };
    const Caption thesis[6][2] = {
        {{0.38, 0.005, 1.6, 0.05, 92}, {-0.057, 0.0005, 1.2, 0.05, 94}},
        {{0.014, 0.002, 1.4, 0.05, 94}, {0.3, 0.05, 1.3, 0.05, 93}},
        {{0.11, 0.005, 1.6, 0.05, 93}, {0.21, 0.005, 1.2, 0.05, 93}},
        {{0.3, 0.05, 1.0, 0.5, 92}, {0.022, 0.002, 1.8, 0.05, 94}},
        {{0.08, 0.005, 1.6, 0.05, 93}, {0.24, 0.005, 1.2, 0.05, 93}},
        {{0.21, 0.005, 1.5, 0.05, 92}, {0.11, 0.005, 1.3, 0.05, 98}},
    };
    const SkeletonStats& s = thesisModel();
    for (int axis = 0; axis < 6; ++axis) {
        const double flip = axis < 5 ? -1.0 : 1.0;
        for (int side = 0; side < 2; ++side) {
            const double sigmas = (side == 0 ? -1.0 : 1.0) * flip;
            const SkeletonFeatures f = fromFeaturePoint(s.axisPoint(axis, sigmas));
            const Caption& c = thesis[axis][side];
            EXPECT_NEAR(f.wings, c.wings, c.wingsTolerance) << "axis " << axis + 1;
            EXPECT_NEAR(f.legs, c.legs, c.legsTolerance) << "axis " << axis + 1;
            Eigen::VectorXd q = Eigen::VectorXd::Zero(axis + 1);
            q[axis] = sigmas * std::sqrt(s.eigenvalues()[axis]);
            EXPECT_NEAR(thesisCaptionWeight(s, q), c.weight, 0.5) << "axis " << axis + 1;
        }
    }
}

TEST(SkeletonStats, ReproducesTheThesisFigure411Point) {
    // Seed 000 fig. 4.11: the point −0.4 on the first axis and 0.2 on the second (thesis signs)
    // has wings 0.402, legs 1.46, weight 92.2 kg (the thesis's weight mapping).
    const SkeletonStats& s = thesisModel();
    Eigen::VectorXd q(2);
    q << 0.4, -0.2;  // axes 1 and 2 have the opposite sign in ramus
    const SkeletonFeatures f = fromFeaturePoint(s.reconstruct(q));
    EXPECT_NEAR(f.wings, 0.402, 0.0005);
    EXPECT_NEAR(f.legs, 1.46, 0.005);
    EXPECT_NEAR(thesisCaptionWeight(s, q), 92.2, 0.05);
}

TEST(SkeletonStats, CovarianceDividesByTheNumberOfSpecies) {
    const SkeletonStats& s = thesisModel();
    const Eigen::MatrixXd centred = s.data().rowwise() - s.mean().transpose();
    const Eigen::VectorXd legs = centred.col(kFeatureLegs);
    EXPECT_NEAR(s.covariance()(kFeatureLegs, kFeatureLegs), legs.squaredNorm() / 44.0, 1e-18);
}

TEST(SkeletonStats, EigenvectorsAreOrthonormalAndDiagonalizeTheCovariance) {
    const SkeletonStats& s = thesisModel();
    const Eigen::MatrixXd& v = s.eigenvectors();
    EXPECT_LT((v.transpose() * v - Eigen::MatrixXd::Identity(29, 29)).norm(), 1e-12);
    const Eigen::MatrixXd back = v * s.eigenvalues().asDiagonal() * v.transpose();
    EXPECT_LT((back - s.covariance()).norm(), 1e-12);
    for (int i = 1; i < 29; ++i) EXPECT_GE(s.eigenvalues()[i - 1], s.eigenvalues()[i]);
}

TEST(SkeletonStats, ReconstructionWithAllComponentsIsExact) {
    const SkeletonStats& s = thesisModel();
    for (Eigen::Index i = 0; i < s.data().rows(); ++i) {
        const Eigen::VectorXd x = s.data().row(i).transpose();
        const Eigen::VectorXd back = s.reconstruct(s.project(x));
        EXPECT_LT((back - x).cwiseAbs().maxCoeff(), 1e-13) << s.species()[i].name;
        // And in user units: the record's features come back to within 1e-9 px / kg.
        const SkeletonFeatures f = fromFeaturePoint(back);
        const SkeletonFeatures& g = s.species()[i].features;
        for (int k = 0; k < kSpinePointCount; ++k)
            EXPECT_LT((f.spine[k] - g.spine[k]).norm(), 1e-9);
        EXPECT_NEAR(f.weightKg, g.weightKg, 1e-9 * (1 + g.weightKg));
    }
}

TEST(SkeletonStats, FewerComponentsApproximateWithShrinkingError) {
    const SkeletonStats& s = thesisModel();
    const Eigen::VectorXd x = s.fromExample("Archaeopteryx");
    const Eigen::VectorXd q = s.project(x);
    double previous = 1e9;
    for (int k : {6, 10, 20, 29}) {
        const double error = (s.reconstruct(q.head(k)) - x).norm();
        EXPECT_LT(error, previous);
        previous = error;
    }
    EXPECT_LT(previous, 1e-13);
}

TEST(SkeletonStats, FeaturePointRoundTripsAndUsesTheDifferenceDimensions) {
    SkeletonFeatures f;
    for (int i = 0; i < kSpinePointCount; ++i) f.spine[i] = Vec2(100.0 * i, 50.0 + 7.0 * i);
    f.wings = 1;
    f.legs = 2;
    f.limbs = {10, 20, 30, 40, 50, 60};
    f.weightKg = 120000;
    const Eigen::VectorXd x = toFeaturePoint(f);
    EXPECT_DOUBLE_EQ(x[kFeatureNeckYLength], (50.0 - 71.0) / 1000.0);
    EXPECT_DOUBLE_EQ(x[kFeatureTailXLength], (900.0 - 600.0) / 1000.0);
    EXPECT_DOUBLE_EQ(x[kFeatureWings], 0.01);
    EXPECT_DOUBLE_EQ(x[kFeatureLegs], 0.01);
    EXPECT_DOUBLE_EQ(x[kFeatureWeight], 0.01);  // the blue whale's weight maps to 1/100
    EXPECT_DOUBLE_EQ(x[kFeatureFirstLimb + 5], 0.06);
    const SkeletonFeatures back = fromFeaturePoint(x);
    for (int i = 0; i < kSpinePointCount; ++i)
        EXPECT_LT((back.spine[i] - f.spine[i]).norm(), 1e-12);
    EXPECT_NEAR(back.weightKg, 120000, 1e-6);
    EXPECT_DOUBLE_EQ(back.legs, 2);
}

TEST(SkeletonStats, FeatureNamesRoundTrip) {
    EXPECT_EQ(featureName(0), "p0_x");
    EXPECT_EQ(featureName(7), "neck_y_length");
    EXPECT_EQ(featureName(18), "tail_x_length");
    EXPECT_EQ(featureName(19), "p9_y");
    EXPECT_EQ(featureName(kFeatureWeight), "weight");
    for (int i = 0; i < kFeatureCount; ++i) EXPECT_EQ(parseFeatureName(featureName(i)), i);
    EXPECT_FALSE(parseFeatureName("p3_y").has_value());
    EXPECT_EQ(featureUnit(kFeatureLegs), "pairs");
    EXPECT_EQ(featureUnit(kFeatureWeight), "kg");
    EXPECT_EQ(featureUnit(kFeatureNeckYLength), "px");
}

TEST(SkeletonStats, SamplesMatchTheModelMeanAndCovariance) {
    const SkeletonStats& s = thesisModel();
    Rng rng(2024);
    constexpr int kDraws = 100000;
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(29);
    Eigen::MatrixXd outer = Eigen::MatrixXd::Zero(29, 29);
    for (int i = 0; i < kDraws; ++i) {
        const Eigen::VectorXd d = s.sample(rng) - s.mean();
        sum += d;
        outer.noalias() += d * d.transpose();
    }
    const Eigen::VectorXd meanError = sum / kDraws;
    const Eigen::MatrixXd cov = outer / kDraws - meanError * meanError.transpose();
    const Eigen::MatrixXd& sigma = s.covariance();
    for (int i = 0; i < 29; ++i) {
        // 5 standard errors of the sample mean.
        EXPECT_LT(std::abs(meanError[i]), 5 * std::sqrt(sigma(i, i) / kDraws)) << featureName(i);
        for (int j = 0; j < 29; ++j) {
            const double se =
                std::sqrt((sigma(i, i) * sigma(j, j) + sigma(i, j) * sigma(i, j)) / kDraws);
            EXPECT_LT(std::abs(cov(i, j) - sigma(i, j)), 5 * se)
                << featureName(i) << ", " << featureName(j);
        }
    }
}

TEST(SkeletonStats, ThesisSpreadUsesTheEigenvalueAsStandardDeviation) {
    const SkeletonStats& s = thesisModel();
    Rng rng(99);
    constexpr int kDraws = 100000;
    Eigen::VectorXd sumSq = Eigen::VectorXd::Zero(29);
    for (int i = 0; i < kDraws; ++i) {
        const Eigen::VectorXd q = s.project(s.sample(rng, SampleSpread::Thesis));
        sumSq += q.cwiseProduct(q);
    }
    for (int i = 0; i < 7; ++i) {
        const double expected = s.eigenvalues()[i] * s.eigenvalues()[i];  // (λᵢ)² variance
        EXPECT_NEAR(sumSq[i] / kDraws, expected, 5 * expected * std::sqrt(2.0 / kDraws));
    }
}

TEST(SkeletonStats, SamplingIsDeterministicForASeed) {
    const SkeletonStats& s = thesisModel();
    Rng a(7), b(7);
    EXPECT_EQ(s.sample(a), s.sample(b));
}

TEST(SkeletonStats, AxisPointLiesOneSigmaAlongTheAxis) {
    const SkeletonStats& s = thesisModel();
    Eigen::VectorXd q = s.project(s.axisPoint(2, -1.0));
    EXPECT_NEAR(q[2], -std::sqrt(s.eigenvalues()[2]), 1e-14);
    q[2] = 0;
    EXPECT_LT(q.norm(), 1e-14);
}

TEST(SkeletonStats, FromExampleFindsEnglishAndGermanNames) {
    const SkeletonStats& s = thesisModel();
    EXPECT_EQ(s.fromExample("Rock hyrax"), s.fromExample("klippschliefer"));
    EXPECT_EQ(s.fromExample("Känguru"), s.fromExample("kangaroo"));
}

TEST(SkeletonStats, FromExampleRejectsAnUnknownSpecies) {
    try {
        thesisModel().fromExample("Unicorn");
        FAIL() << "expected an Error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("unknown species \"Unicorn\""), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("Rock hyrax"), std::string::npos);
    }
}

TEST(SkeletonStats, VariationsScatterWithHalfTheEigenvalues) {
    const SkeletonStats& s = thesisModel();
    const Eigen::VectorXd base = s.fromExample("Horse (warmblood)");
    const Eigen::VectorXd q0 = s.project(base);
    Rng rng(11);
    constexpr int kDraws = 50000;
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(29), sumSq = Eigen::VectorXd::Zero(29);
    for (int i = 0; i < kDraws; ++i) {
        const Eigen::VectorXd d = s.project(s.vary(base, rng)) - q0;
        sum += d;
        sumSq += d.cwiseProduct(d);
    }
    for (int i = 0; i < 7; ++i) {  // the axes with visible variance
        const double expected = s.eigenvalues()[i] / 2;
        EXPECT_LT(std::abs(sum[i] / kDraws), 5 * std::sqrt(expected / kDraws));
        EXPECT_NEAR(sumSq[i] / kDraws, expected, 5 * expected * std::sqrt(2.0 / kDraws));
    }
}

TEST(SkeletonStats, FitNeedsAtLeastTwoSpecies) {
    std::vector<SpeciesRecord> one(builtinSpecies().begin(), builtinSpecies().begin() + 1);
    EXPECT_THROW(SkeletonStats::fit(one), Error);
    EXPECT_THROW(SkeletonStats::fit({}), Error);
}

}  // namespace
}  // namespace ramus
