// Based on: seed 000 §4.5 (conditional distributions, after Eaton, "Multivariate Statistics",
// p. 116 f.; the seed's Σ̄ formula has a typo: Σ₁₂Σ₁₂⁻¹Σ₂₁ must read Σ₁₂Σ₂₂⁻¹Σ₂₁) and §6.1 (user
// values get a random offset from [−0.5, 0.5]); SPEC §E.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ramus/error.hpp"
#include "ramus/skeleton_stats.hpp"
#include "skeleton/pca_math.hpp"

namespace ramus {

namespace {

// Directions of Σ₂₂ with an eigenvalue at most this fraction of Σ's largest are treated as
// having no variance at all: the data fixes them, so a condition must agree with the data there.
constexpr double kDegenerate = 1e-12;
// Tikhonov term (fraction of Σ's largest eigenvalue) added to the other eigenvalues of Σ₂₂, so a
// nearly singular block cannot blow the conditional mean up.
constexpr double kRidge = 1e-10;
// How far (in scaled feature units; 1e-9 = 1e-6 px) a condition may deviate from the data along
// a direction without variance before it is impossible.
constexpr double kResidualTolerance = 1e-9;

struct FixedValue {
    int feature = 0;
    double userValue = 0;  // with the random offset
    double scaled = 0;
};

std::string userValueText(int feature, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g %s", value,
                  std::string(featureUnit(feature)).c_str());
    return buffer;
}

// Validates the conditions and draws their offsets, in feature order (so the order in which
// the caller lists them does not change the result).
std::vector<FixedValue> fixValues(std::vector<Condition> conditions, Rng& rng) {
    std::sort(conditions.begin(), conditions.end(),
              [](const Condition& a, const Condition& b) { return a.feature < b.feature; });
    std::vector<FixedValue> fixed;
    for (std::size_t i = 0; i < conditions.size(); ++i) {
        const Condition& c = conditions[i];
        if (c.feature < 0 || c.feature >= kFeatureCount) {
            throw Error("condition on feature " + std::to_string(c.feature) +
                        ": expected a feature index in [0, 28]");
        }
        const std::string name = featureName(c.feature);
        if (i > 0 && conditions[i - 1].feature == c.feature) {
            throw Error("condition on " + name +
                        " given twice; expected each feature at most once");
        }
        if (!std::isfinite(c.value)) throw Error("condition on " + name + ": value is not finite");
        if (!std::isfinite(c.jitter) || c.jitter < 0) {
            throw Error("condition on " + name + ": expected a finite jitter >= 0");
        }
        double value = c.value;
        if (c.jitter > 0) value += rng.uniform(-0.5 * c.jitter, 0.5 * c.jitter);
        fixed.push_back({c.feature, value, scaleFeatureValue(c.feature, value)});
    }
    return fixed;
}

// The features involved in a direction, for the "impossible" message.
std::string describeDirection(const Eigen::VectorXd& direction,
                              const std::vector<FixedValue>& fixed) {
    std::string text;
    for (Eigen::Index k = 0; k < direction.size(); ++k) {
        if (std::abs(direction[k]) < 0.05) continue;
        text += (text.empty() ? "" : ", ") + featureName(fixed[k].feature) + " = " +
                userValueText(fixed[k].feature, fixed[k].userValue);
    }
    return text;
}

// Σ₂₂⁺: the regularized pseudo-inverse of the fixed block; throws when b contradicts a
// direction the data never varies in.
Eigen::MatrixXd regularizedInverse(const Eigen::MatrixXd& block, const Eigen::VectorXd& offset,
                                   double largestEigenvalue, const std::vector<FixedValue>& fixed) {
    const detail::SortedEigen eigen = detail::decomposeSymmetric(block);
    const Eigen::VectorXd residual = eigen.vectors.transpose() * offset;
    Eigen::VectorXd inverseValues(eigen.values.size());
    for (Eigen::Index j = 0; j < eigen.values.size(); ++j) {
        if (eigen.values[j] > kDegenerate * largestEigenvalue) {
            inverseValues[j] = 1.0 / (eigen.values[j] + kRidge * largestEigenvalue);
            continue;
        }
        inverseValues[j] = 0.0;
        if (std::abs(residual[j]) > kResidualTolerance) {
            throw Error("impossible condition: the species data never varies in the direction of " +
                        describeDirection(eigen.vectors.col(j), fixed) +
                        " (every species agrees there); expected values the data allows, e.g. "
                        "the mean, with jitter 0");
        }
    }
    return eigen.vectors * inverseValues.asDiagonal() * eigen.vectors.transpose();
}

Eigen::MatrixXd submatrix(const Eigen::MatrixXd& m, const std::vector<int>& rows,
                          const std::vector<int>& cols) {
    Eigen::MatrixXd out(rows.size(), cols.size());
    for (std::size_t r = 0; r < rows.size(); ++r) {
        for (std::size_t c = 0; c < cols.size(); ++c) out(r, c) = m(rows[r], cols[c]);
    }
    return out;
}

}  // namespace

ConditionalModel SkeletonStats::condition(const std::vector<Condition>& conditions,
                                          Rng& rng) const {
    const std::vector<FixedValue> fixed = fixValues(conditions, rng);
    ConditionalModel model;
    model.mean = mean_;
    std::vector<bool> isFixed(kFeatureCount, false);
    for (const FixedValue& f : fixed) {
        model.fixedFeatures.push_back(f.feature);
        isFixed[f.feature] = true;
    }
    for (int i = 0; i < kFeatureCount; ++i) {
        if (!isFixed[i]) model.freeFeatures.push_back(i);
    }
    const std::vector<int>& a = model.freeFeatures;
    const std::vector<int>& b = model.fixedFeatures;

    Eigen::VectorXd offset(b.size());  // b − μ₂
    for (std::size_t k = 0; k < b.size(); ++k) offset[k] = fixed[k].scaled - mean_[b[k]];
    const Eigen::MatrixXd inverse =
        regularizedInverse(submatrix(covariance_, b, b), offset, eigenvalues_[0], fixed);
    const Eigen::MatrixXd crossAB = submatrix(covariance_, a, b);  // Σ₁₂

    const Eigen::VectorXd meanShift = crossAB * (inverse * offset);
    for (std::size_t k = 0; k < a.size(); ++k) model.mean[a[k]] += meanShift[k];
    for (const FixedValue& f : fixed) model.mean[f.feature] = f.scaled;

    Eigen::MatrixXd cov = submatrix(covariance_, a, a) - crossAB * inverse * crossAB.transpose();
    model.covariance = 0.5 * (cov + cov.transpose());  // exact symmetry for the solver
    detail::SortedEigen eigen = detail::decomposeSymmetric(model.covariance);
    model.eigenvalues = std::move(eigen.values);
    model.eigenvectors = std::move(eigen.vectors);
    return model;
}

Eigen::VectorXd ConditionalModel::sample(Rng& rng) const {
    Eigen::VectorXd point = mean;
    const Eigen::Index n = eigenvalues.size();
    if (n == 0) return point;
    Eigen::VectorXd q(n);
    for (Eigen::Index i = 0; i < n; ++i) q[i] = rng.gauss(0.0, std::sqrt(eigenvalues[i]));
    const Eigen::VectorXd shift = eigenvectors * q;
    for (std::size_t k = 0; k < freeFeatures.size(); ++k) point[freeFeatures[k]] += shift[k];
    return point;
}

}  // namespace ramus
