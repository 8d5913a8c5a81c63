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

// Regularization by truncation: directions of Σ₂₂ whose eigenvalue is at most this fraction of
// Σ's largest are treated as fixed by the data (dropped from the inverse — a truncated
// pseudo-inverse — and checked for consistency instead). 1e-9 lies three orders of magnitude
// below the thesis data's smallest eigenvalue (1e-6 of 0.35) and the variances of wings and
// legs (~1e-5), so well-posed conditions are computed exactly.
constexpr double kDegenerate = 1e-9;
// A condition contradicts such a direction when it lies more than this many of the data's
// standard deviations (in that direction) away from the mean, and more than kMinResidual.
constexpr double kResidualSigmas = 6.0;
constexpr double kMinResidual = 1e-9;  // scaled feature units (1e-6 px)

std::string userValueText(int feature, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g %s", value,
                  std::string(featureUnit(feature)).c_str());
    return buffer;
}

// Validates the conditions and sorts them by feature (so the order in which the caller lists
// them does not change the result).
std::vector<Condition> validated(std::vector<Condition> conditions) {
    std::sort(conditions.begin(), conditions.end(),
              [](const Condition& a, const Condition& b) { return a.feature < b.feature; });
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
    }
    return conditions;
}

// The conditions involved in a direction, for the "impossible" message.
std::string describeDirection(const Eigen::VectorXd& direction,
                              const std::vector<Condition>& conditions) {
    std::string text;
    for (Eigen::Index k = 0; k < direction.size(); ++k) {
        if (std::abs(direction[k]) < 0.05) continue;
        const Condition& c = conditions[k];
        text += (text.empty() ? "" : ", ") + featureName(c.feature) + " = " +
                userValueText(c.feature, c.value);
        if (c.jitter > 0) text += " ± " + userValueText(c.feature, c.jitter / 2);
    }
    return text;
}

// Σ₂₂⁺: the truncated pseudo-inverse of the fixed block. Throws when the conditions contradict
// a direction the data (practically) never varies in, or put a random offset on it.
Eigen::MatrixXd regularizedInverse(const Eigen::MatrixXd& block, const Eigen::VectorXd& offset,
                                   double largestEigenvalue,
                                   const std::vector<Condition>& conditions) {
    const detail::SortedEigen eigen = detail::decomposeSymmetric(block);
    const Eigen::VectorXd residual = eigen.vectors.transpose() * offset;
    Eigen::VectorXd inverseValues(eigen.values.size());
    for (Eigen::Index j = 0; j < eigen.values.size(); ++j) {
        if (eigen.values[j] > kDegenerate * largestEigenvalue) {
            inverseValues[j] = 1.0 / eigen.values[j];
            continue;
        }
        inverseValues[j] = 0.0;
        const double allowed = std::max(kMinResidual, kResidualSigmas * std::sqrt(eigen.values[j]));
        bool jittered = false;
        for (Eigen::Index k = 0; k < eigen.vectors.rows(); ++k) {
            jittered =
                jittered || (conditions[k].jitter > 0 && std::abs(eigen.vectors(k, j)) > 1e-6);
        }
        if (std::abs(residual[j]) > allowed || jittered) {
            throw Error("impossible condition: the species data never varies in the direction of " +
                        describeDirection(eigen.vectors.col(j), conditions) +
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

ConditionalModel SkeletonStats::condition(const std::vector<Condition>& conditions) const {
    ConditionalModel model;
    model.conditions = validated(conditions);
    model.mean = mean_;
    std::vector<bool> isFixed(kFeatureCount, false);
    for (const Condition& c : model.conditions) {
        model.fixedFeatures.push_back(c.feature);
        isFixed[c.feature] = true;
    }
    for (int i = 0; i < kFeatureCount; ++i) {
        if (!isFixed[i]) model.freeFeatures.push_back(i);
    }
    const std::vector<int>& a = model.freeFeatures;
    const std::vector<int>& b = model.fixedFeatures;

    Eigen::VectorXd offset(b.size());  // b − μ₂
    for (std::size_t k = 0; k < b.size(); ++k) {
        const Condition& c = model.conditions[k];
        offset[k] = scaleFeatureValue(c.feature, c.value) - mean_[b[k]];
    }
    const Eigen::MatrixXd inverse =
        regularizedInverse(submatrix(covariance_, b, b), offset, eigenvalues_[0], model.conditions);
    const Eigen::MatrixXd crossAB = submatrix(covariance_, a, b);  // Σ₁₂
    model.gain = crossAB * inverse;

    const Eigen::VectorXd meanShift = model.gain * offset;
    for (std::size_t k = 0; k < a.size(); ++k) model.mean[a[k]] += meanShift[k];
    for (std::size_t k = 0; k < b.size(); ++k) model.mean[b[k]] = mean_[b[k]] + offset[k];

    const Eigen::MatrixXd cov = submatrix(covariance_, a, a) - model.gain * crossAB.transpose();
    model.covariance = 0.5 * (cov + cov.transpose());  // exact symmetry for the solver
    detail::SortedEigen eigen = detail::decomposeSymmetric(model.covariance);
    model.eigenvalues = std::move(eigen.values);
    model.eigenvectors = std::move(eigen.vectors);
    return model;
}

Eigen::VectorXd ConditionalModel::sample(Rng& rng, SampleSpread spread) const {
    Eigen::VectorXd point = mean;
    // The fixed values with their random offsets, and the mean shift they cause.
    Eigen::VectorXd delta(conditions.size());
    for (std::size_t k = 0; k < conditions.size(); ++k) {
        const Condition& c = conditions[k];
        const double value =
            c.jitter > 0 ? c.value + rng.uniform(-0.5 * c.jitter, 0.5 * c.jitter) : c.value;
        const double scaled = scaleFeatureValue(c.feature, value);
        delta[k] = scaled - mean[c.feature];
        point[c.feature] = scaled;
    }
    const Eigen::VectorXd moved = gain * delta;
    for (std::size_t k = 0; k < freeFeatures.size(); ++k) point[freeFeatures[k]] += moved[k];
    const Eigen::Index n = eigenvalues.size();
    if (n == 0) return point;
    Eigen::VectorXd q(n);
    for (Eigen::Index i = 0; i < n; ++i)
        q[i] = detail::sampleCoordinate(rng, eigenvalues[i], spread);
    const Eigen::VectorXd shift = eigenvectors * q;
    for (std::size_t k = 0; k < freeFeatures.size(); ++k) point[freeFeatures[k]] += shift[k];
    return point;
}

}  // namespace ramus
