// Skeleton statistics: PCA over the species data, sampling, conditional distributions,
// variations and diagnostics (seed 000 ch. 4, §6.3, §7.4; SPEC §E).
//
// A skeleton is a "feature point": a vector of kFeatureCount = 29 scaled numbers (SPEC §E):
//   0..19  spine P0.x P0.y … P9.x P9.y ÷ 1000, except
//            7  = (P0.y − P3.y) / 1000  neck y length (head above shoulder)
//           18  = (P9.x − P6.x) / 1000  tail x length (hip to tail tip)
//   20     wing pairs ÷ 100
//   21     leg pairs with ground contact ÷ 2 ÷ 100
//   22..27 upper arm, forearm, hand, thigh, shank, foot lengths ÷ 1000
//   28     log10(weight + 1) / (log10(120000 + 1) · 100)
// The PCA coordinates of a point x are q = Vᵀ(x − μ) with the eigenvectors V of the population
// covariance (÷ n) as columns, sorted by descending eigenvalue.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/rng.hpp"
#include "ramus/species.hpp"

namespace ramus {

inline constexpr int kFeatureCount = 29;
inline constexpr int kFeatureNeckYLength = 7;
inline constexpr int kFeatureTailXLength = 18;
inline constexpr int kFeatureWings = 20;
inline constexpr int kFeatureLegs = 21;
inline constexpr int kFeatureFirstLimb = 22;  ///< + static_cast<int>(Limb)
inline constexpr int kFeatureWeight = 28;
/// The weight that maps to 1 before the ÷100: the blue whale, the heaviest vertebrate (kg).
inline constexpr double kMaxWeightKg = 120000.0;

/// Feature names: "p0_x", "p0_y", …, "neck_y_length" (7), …, "tail_x_length" (18), "p9_y",
/// "wings", "legs", "upper_arm", "forearm", "hand", "thigh", "shank", "foot", "weight".
/// `feature` must be in [0, kFeatureCount).
std::string featureName(int feature);
/// Inverse of featureName; nullopt for an unknown name.
std::optional<int> parseFeatureName(std::string_view name);
/// The user unit of a feature: "px", "pairs" or "kg".
std::string_view featureUnit(int feature);
/// A value in user units (px, pairs, kg) → the scaled feature value. Weights below 0 kg are
/// treated as 0.
double scaleFeatureValue(int feature, double userValue);
/// Inverse of scaleFeatureValue.
double unscaleFeatureValue(int feature, double scaledValue);

/// Features → feature point (29 scaled numbers).
Eigen::VectorXd toFeaturePoint(const SkeletonFeatures& features);
/// Feature point → features (undoes the scaling and the two difference dimensions). The point
/// must have kFeatureCount entries. Values are not clamped (a generated point can have, e.g.,
/// wings −0.05 or a slightly negative limb length); the generator interprets them.
SkeletonFeatures fromFeaturePoint(const Eigen::VectorXd& point);

/// How far random points spread along the principal axes.
enum class SampleSpread {
    /// qᵢ ~ N(0, λᵢ): the model the thesis describes (seed 000 §3.5, SPEC §E). Default.
    Model,
    /// qᵢ = λᵢ·N(0, 1): what the thesis's implementation does (standard deviation λᵢ instead of
    /// √λᵢ), which keeps points much closer to the mean — its figures of random and
    /// conditioned skeletons (e.g. fig. 4.12) were made this way.
    Thesis,
};

/// A condition on one feature (seed 000 §4.5, §6.1): the feature is fixed to
/// value + U(−jitter/2, jitter/2), in the feature's user unit (px, pairs, kg).
struct Condition {
    int feature = 0;
    double value = 0.0;
    /// Width of the uniform random offset; the thesis uses 1 ([−0.5, 0.5]); 0 = exact value.
    double jitter = 1.0;

    /// Pairs of legs with ground contact (the thesis's GUI takes a leg count n and uses n/2).
    static Condition legs(double pairs) { return {kFeatureLegs, pairs}; }
    /// Wing pairs (the GUI takes a wing count n and uses min(1, n/2)).
    static Condition wings(double pairs) { return {kFeatureWings, pairs}; }
    /// Neck y length P0.y − P3.y in px.
    static Condition neckYLength(double px) { return {kFeatureNeckYLength, px}; }
    /// Tail x length P9.x − P6.x in px.
    static Condition tailXLength(double px) { return {kFeatureTailXLength, px}; }
};

/// The distribution of a feature point given fixed values for some features:
/// μ̄ = μ₁ + Σ₁₂Σ₂₂⁻¹(b − μ₂), Σ̄ = Σ₁₁ − Σ₁₂Σ₂₂⁻¹Σ₂₁ (seed 000 §4.5, its typo corrected), with
/// the eigen-decomposition re-run on Σ̄. Σ̄ does not depend on b, so one model serves any number
/// of samples; each sample draws its own random offsets for the fixed values.
struct ConditionalModel {
    std::vector<Condition> conditions;  ///< sorted by feature
    std::vector<int> fixedFeatures;     ///< ascending (the conditions' features)
    std::vector<int> freeFeatures;      ///< ascending; the rest
    /// Full feature point at the conditions' values without offsets: the conditional mean at
    /// the free features, the scaled values at the fixed ones.
    Eigen::VectorXd mean;
    /// Σ₁₂Σ₂₂⁻¹ (free × fixed): how the free features' mean moves per unit (scaled) change of
    /// a fixed value — the regression coefficients.
    Eigen::MatrixXd gain;
    /// Σ̄ over the free features (in freeFeatures order).
    Eigen::MatrixXd covariance;
    /// Eigenvalues of Σ̄, descending, ≥ 0; eigenvectors as columns in the same order.
    Eigen::VectorXd eigenvalues;
    Eigen::MatrixXd eigenvectors;

    /// Draws each condition's offset from U(−jitter/2, jitter/2) (in feature order), moves the
    /// mean by gain·(b − b₀), then draws q ~ N(0, Λ̄) (or per `spread`) and maps it back: free
    /// features μ̄ + V̄q, fixed features the offset values.
    Eigen::VectorXd sample(Rng& rng, SampleSpread spread = SampleSpread::Model) const;
};

/// The PCA model of a species set.
class SkeletonStats {
public:
    /// Fits the model: feature points of all species, mean, population covariance, its
    /// eigen-decomposition (Eigen's SelfAdjointEigenSolver; eigenvalues clamped to ≥ 0, sorted
    /// descending; each eigenvector's largest-magnitude entry made positive). Throws Error when
    /// there are fewer than 2 species.
    static SkeletonStats fit(std::vector<SpeciesRecord> species);
    /// loadSpeciesFile(path) + fit.
    static SkeletonStats load(const std::string& speciesFile);
    /// fit(builtinSpecies()).
    static SkeletonStats builtin();

    const std::vector<SpeciesRecord>& species() const { return species_; }
    /// One row per species: its feature point.
    const Eigen::MatrixXd& data() const { return data_; }
    const Eigen::VectorXd& mean() const { return mean_; }
    /// Population covariance (÷ n).
    const Eigen::MatrixXd& covariance() const { return covariance_; }
    /// Descending, ≥ 0.
    const Eigen::VectorXd& eigenvalues() const { return eigenvalues_; }
    /// Unit eigenvectors as columns, in eigenvalue order.
    const Eigen::MatrixXd& eigenvectors() const { return eigenvectors_; }

    /// Fraction of the total variance in the first `components` eigenvalues (clamped to
    /// [0, kFeatureCount]); 1 when the total variance is 0.
    double explainedVariance(int components) const;
    /// How many eigenvalues are strictly greater than `threshold`.
    int countEigenvaluesAbove(double threshold) const;

    /// PCA coordinates q = Vᵀ(point − μ).
    Eigen::VectorXd project(const Eigen::VectorXd& point) const;
    /// point = μ + Σᵢ qᵢvᵢ over the given coordinates (fewer than kFeatureCount = the first
    /// ones; the others count as 0). Exact inverse of project with all coordinates.
    Eigen::VectorXd reconstruct(const Eigen::VectorXd& coordinates) const;
    /// μ + s·√λᵢ·vᵢ: the point at s standard deviations along axis i (seed 000 fig. 4.10).
    Eigen::VectorXd axisPoint(int axis, double sigmas) const;

    /// A random skeleton: qᵢ ~ N(0, λᵢ) independently (or per `spread`), mapped back (seed 000
    /// §3.5, §5.1).
    Eigen::VectorXd sample(Rng& rng, SampleSpread spread = SampleSpread::Model) const;
    /// The conditional model for the conditions. Throws Error for a feature index out of
    /// range, a feature conditioned twice, a non-finite value or jitter, or an impossible
    /// condition: a value (or a random offset) in a direction the data never varies in, e.g.
    /// wings = 1 when no species has wings. Near-singular Σ₂₂ blocks are regularized by a
    /// truncated pseudo-inverse. No conditions = the unconditioned model. To draw many samples
    /// under the same conditions, call this once and ConditionalModel::sample repeatedly.
    ConditionalModel condition(const std::vector<Condition>& conditions) const;
    /// condition(conditions).sample(rng, spread).
    Eigen::VectorXd sampleConditioned(const std::vector<Condition>& conditions, Rng& rng,
                                      SampleSpread spread = SampleSpread::Model) const;
    /// The feature point of a species, by English or German name (case-insensitive). Throws
    /// Error listing the known names when there is no such species.
    Eigen::VectorXd fromExample(std::string_view name) const;
    /// A variation of a point (seed 000 §6.3): each PCA coordinate qᵢ' ~ N(qᵢ, λᵢ/2).
    Eigen::VectorXd vary(const Eigen::VectorXd& point, Rng& rng) const;

    /// Euclidean distance of each species' feature point to the mean (species order).
    std::vector<double> distancesToMean() const;

private:
    std::vector<SpeciesRecord> species_;
    Eigen::MatrixXd data_;
    Eigen::VectorXd mean_;
    Eigen::MatrixXd covariance_;
    Eigen::VectorXd eigenvalues_;
    Eigen::MatrixXd eigenvectors_;
};

// ---- diagnostics ---------------------------------------------------------------------------

/// Φ⁻¹(p), the standard normal quantile, for p in (0, 1) (Wichura's AS 241, ~1e-16 relative).
/// Returns −inf for p ≤ 0 and +inf for p ≥ 1.
double normalQuantile(double p);

/// Points of a normal Q-Q plot with rankit positions: theoretical[i] = Φ⁻¹((i + 0.5)/n) (i.e.
/// (i − 0.5)/n 1-based, seed 000 §3.6), sample = the values sorted ascending. Empty input gives
/// empty vectors.
struct QqPoints {
    std::vector<double> theoretical;
    std::vector<double> sample;
};
QqPoints qqPoints(std::span<const double> values);

/// One of the largest-magnitude entries of an eigenvector.
struct EigenvectorEntry {
    int feature = 0;
    double value = 0.0;
};

/// The figures `ramus pca report` prints (seed 000 §4.3–4.4).
struct PcaReport {
    int speciesCount = 0;
    std::vector<double> eigenvalues;  ///< all, descending
    double explained6 = 0, explained10 = 0, explained20 = 0;
    int eigenvaluesAbove001 = 0;   ///< > 0.01
    int eigenvaluesAbove0001 = 0;  ///< > 0.001
    SkeletonFeatures meanFeatures;
    std::string nearest, farthest, secondFarthest;  ///< species names (English)
    double nearestDistance = 0, farthestDistance = 0, secondFarthestDistance = 0;
    /// For each of the first 7 eigenvectors (fewer if the model has fewer), its 4 entries of
    /// largest magnitude, largest first.
    std::vector<std::vector<EigenvectorEntry>> topEntries;
};

/// Computes the report; needs a fitted model with at least 2 species.
PcaReport makePcaReport(const SkeletonStats& stats);

/// Writes the diagnostic figures as SVG files into `directory` (created if needed) and returns
/// their paths: Q-Q plots per feature and per principal axis, projections onto the first two
/// axes coloured by class, wings and legs, the eigenvalue spectrum, the mean skeleton,
/// skeletons at ±1σ along each of the first 6 axes, all species, and conditionally sampled
/// spines (wings = 0, legs = 1; fixed seed). Throws Error when a file cannot be written.
std::vector<std::string> writePcaPlots(const SkeletonStats& stats, const std::string& directory);

}  // namespace ramus
