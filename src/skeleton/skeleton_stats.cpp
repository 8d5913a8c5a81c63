// Based on: seed 000 §3.5 (PCA), §4.2–4.4 (features, scaling, results), §6.3 (variations),
// §7.4; SPEC §E (the exact scaling of the thesis's implementation).
#include "ramus/skeleton_stats.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "ramus/error.hpp"
#include "skeleton/pca_math.hpp"

namespace ramus {

namespace {

constexpr double kPixelScale = 1000.0;  // frame size: coordinates and lengths → [0, 1]
constexpr double kDownscale = 100.0;    // wings, legs, weight: less influence (seed 000 §4.3)
constexpr double kMaxLegPairs = 2.0;
const double kLogMaxWeight = std::log10(kMaxWeightKg + 1.0);

bool isSpine(int feature) { return feature >= 0 && feature < 2 * kSpinePointCount; }
bool isLimb(int feature) {
    return feature >= kFeatureFirstLimb && feature < kFeatureFirstLimb + kLimbCount;
}

}  // namespace

namespace detail {
SortedEigen decomposeSymmetric(const Eigen::MatrixXd& matrix) {
    RAMUS_ASSERT(matrix.rows() == matrix.cols());
    SortedEigen result;
    if (matrix.rows() == 0) return result;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(matrix);
    RAMUS_ASSERT(solver.info() == Eigen::Success);
    // Eigen sorts ascending; we want descending. Rounding can leave tiny negative values.
    result.values = solver.eigenvalues().reverse().cwiseMax(0.0);
    result.vectors = solver.eigenvectors().rowwise().reverse();
    for (Eigen::Index c = 0; c < result.vectors.cols(); ++c) {
        Eigen::Index largest = 0;
        result.vectors.col(c).cwiseAbs().maxCoeff(&largest);
        if (result.vectors(largest, c) < 0) result.vectors.col(c) *= -1.0;
    }
    return result;
}

double sampleCoordinate(Rng& rng, double eigenvalue, SampleSpread spread) {
    const double deviation = spread == SampleSpread::Model ? std::sqrt(eigenvalue) : eigenvalue;
    return rng.gauss(0.0, deviation);
}
}  // namespace detail

std::string featureName(int feature) {
    RAMUS_ASSERT(feature >= 0 && feature < kFeatureCount);
    if (feature == kFeatureNeckYLength) return "neck_y_length";
    if (feature == kFeatureTailXLength) return "tail_x_length";
    if (isSpine(feature)) {
        return "p" + std::to_string(feature / 2) + (feature % 2 == 0 ? "_x" : "_y");
    }
    if (feature == kFeatureWings) return "wings";
    if (feature == kFeatureLegs) return "legs";
    if (isLimb(feature))
        return std::string(limbName(static_cast<Limb>(feature - kFeatureFirstLimb)));
    return "weight";
}

std::optional<int> parseFeatureName(std::string_view name) {
    for (int i = 0; i < kFeatureCount; ++i) {
        if (featureName(i) == name) return i;
    }
    return std::nullopt;
}

std::string_view featureUnit(int feature) {
    if (feature == kFeatureWings || feature == kFeatureLegs) return "pairs";
    if (feature == kFeatureWeight) return "kg";
    return "px";
}

double scaleFeatureValue(int feature, double userValue) {
    if (feature == kFeatureWings) return userValue / kDownscale;
    if (feature == kFeatureLegs) return userValue / (kMaxLegPairs * kDownscale);
    if (feature == kFeatureWeight) {
        return std::log10(std::max(userValue, 0.0) + 1.0) / (kLogMaxWeight * kDownscale);
    }
    return userValue / kPixelScale;
}

double unscaleFeatureValue(int feature, double scaledValue) {
    if (feature == kFeatureWings) return scaledValue * kDownscale;
    if (feature == kFeatureLegs) return scaledValue * kMaxLegPairs * kDownscale;
    if (feature == kFeatureWeight) {
        return std::pow(10.0, scaledValue * kLogMaxWeight * kDownscale) - 1.0;
    }
    return scaledValue * kPixelScale;
}

Eigen::VectorXd toFeaturePoint(const SkeletonFeatures& f) {
    Eigen::VectorXd x(kFeatureCount);
    for (int i = 0; i < kSpinePointCount; ++i) {
        x[2 * i] = f.spine[i].x() / kPixelScale;
        x[2 * i + 1] = f.spine[i].y() / kPixelScale;
    }
    // The two difference dimensions, so that neck and tail lengths can be conditioned on.
    x[kFeatureNeckYLength] = f.neckYLength() / kPixelScale;
    x[kFeatureTailXLength] = f.tailXLength() / kPixelScale;
    x[kFeatureWings] = scaleFeatureValue(kFeatureWings, f.wings);
    x[kFeatureLegs] = scaleFeatureValue(kFeatureLegs, f.legs);
    for (int i = 0; i < kLimbCount; ++i) x[kFeatureFirstLimb + i] = f.limbs[i] / kPixelScale;
    x[kFeatureWeight] = scaleFeatureValue(kFeatureWeight, f.weightKg);
    return x;
}

SkeletonFeatures fromFeaturePoint(const Eigen::VectorXd& x) {
    RAMUS_ASSERT(x.size() == kFeatureCount);
    SkeletonFeatures f;
    for (int i = 0; i < kSpinePointCount; ++i) {
        f.spine[i] = Vec2(x[2 * i], x[2 * i + 1]) * kPixelScale;
    }
    // P3.y = P0.y − neck y length; P9.x = P6.x + tail x length.
    f.spine[3].y() = (x[1] - x[kFeatureNeckYLength]) * kPixelScale;
    f.spine[9].x() = (x[12] + x[kFeatureTailXLength]) * kPixelScale;
    f.wings = unscaleFeatureValue(kFeatureWings, x[kFeatureWings]);
    f.legs = unscaleFeatureValue(kFeatureLegs, x[kFeatureLegs]);
    for (int i = 0; i < kLimbCount; ++i) f.limbs[i] = x[kFeatureFirstLimb + i] * kPixelScale;
    f.weightKg = unscaleFeatureValue(kFeatureWeight, x[kFeatureWeight]);
    return f;
}

SkeletonStats SkeletonStats::fit(std::vector<SpeciesRecord> species) {
    const auto n = static_cast<Eigen::Index>(species.size());
    if (n < 2) {
        throw Error("cannot fit the skeleton statistics: need at least 2 species, got " +
                    std::to_string(n));
    }
    SkeletonStats s;
    s.species_ = std::move(species);
    s.data_.resize(n, kFeatureCount);
    for (Eigen::Index i = 0; i < n; ++i) {
        s.data_.row(i) = toFeaturePoint(s.species_[i].features).transpose();
    }
    s.mean_ = s.data_.colwise().mean().transpose();
    const Eigen::MatrixXd centred = s.data_.rowwise() - s.mean_.transpose();
    // Population covariance (÷ n), as the thesis's implementation computes it.
    s.covariance_ = (centred.transpose() * centred) / static_cast<double>(n);

    detail::SortedEigen eigen = detail::decomposeSymmetric(s.covariance_);
    s.eigenvalues_ = std::move(eigen.values);
    s.eigenvectors_ = std::move(eigen.vectors);
    return s;
}

SkeletonStats SkeletonStats::load(const std::string& speciesFile) {
    return fit(loadSpeciesFile(speciesFile));
}

SkeletonStats SkeletonStats::builtin() { return fit(builtinSpecies()); }

double SkeletonStats::explainedVariance(int components) const {
    const double total = eigenvalues_.sum();
    if (total <= 0.0) return 1.0;
    const int k = std::clamp(components, 0, static_cast<int>(eigenvalues_.size()));
    return eigenvalues_.head(k).sum() / total;
}

int SkeletonStats::countEigenvaluesAbove(double threshold) const {
    return static_cast<int>((eigenvalues_.array() > threshold).count());
}

Eigen::VectorXd SkeletonStats::project(const Eigen::VectorXd& point) const {
    RAMUS_ASSERT(point.size() == kFeatureCount);
    return eigenvectors_.transpose() * (point - mean_);
}

Eigen::VectorXd SkeletonStats::reconstruct(const Eigen::VectorXd& coordinates) const {
    RAMUS_ASSERT(coordinates.size() <= kFeatureCount);
    return mean_ + eigenvectors_.leftCols(coordinates.size()) * coordinates;
}

Eigen::VectorXd SkeletonStats::axisPoint(int axis, double sigmas) const {
    RAMUS_ASSERT(axis >= 0 && axis < kFeatureCount);
    return mean_ + sigmas * std::sqrt(eigenvalues_[axis]) * eigenvectors_.col(axis);
}

Eigen::VectorXd SkeletonStats::sample(Rng& rng, SampleSpread spread) const {
    Eigen::VectorXd q(kFeatureCount);
    for (int i = 0; i < kFeatureCount; ++i) {
        q[i] = detail::sampleCoordinate(rng, eigenvalues_[i], spread);
    }
    return reconstruct(q);
}

Eigen::VectorXd SkeletonStats::sampleConditioned(const std::vector<Condition>& conditions, Rng& rng,
                                                 SampleSpread spread) const {
    return condition(conditions).sample(rng, spread);
}

Eigen::VectorXd SkeletonStats::fromExample(std::string_view name) const {
    if (const SpeciesRecord* record = findSpecies(species_, name)) {
        return toFeaturePoint(record->features);
    }
    std::string known;
    for (const SpeciesRecord& r : species_) known += (known.empty() ? "" : ", ") + r.name;
    throw Error("unknown species \"" + std::string(name) + "\"; expected one of: " + known);
}

Eigen::VectorXd SkeletonStats::vary(const Eigen::VectorXd& point, Rng& rng) const {
    Eigen::VectorXd q = project(point);
    for (int i = 0; i < kFeatureCount; ++i) q[i] = rng.gauss(q[i], std::sqrt(eigenvalues_[i] / 2));
    return reconstruct(q);
}

std::vector<double> SkeletonStats::distancesToMean() const {
    std::vector<double> d(species_.size());
    for (std::size_t i = 0; i < d.size(); ++i) {
        d[i] = (data_.row(static_cast<Eigen::Index>(i)).transpose() - mean_).norm();
    }
    return d;
}

}  // namespace ramus
