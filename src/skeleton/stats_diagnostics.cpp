// Based on: seed 000 §3.6 (Q-Q plots with rankit positions (i − 0.5)/n), §4.3–4.4 (the figures
// reported: eigenvalues, explained variance, the mean, nearest and farthest species);
// M. J. Wichura, "Algorithm AS 241: The percentage points of the normal distribution",
// Applied Statistics 37 (1988) 477–484 (PPND16) for Φ⁻¹.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ramus/skeleton_stats.hpp"

namespace ramus {

namespace {

double polynomial(const double (&c)[8], double x) {
    double r = c[7];
    for (int i = 6; i >= 0; --i) r = r * x + c[i];
    return r;
}

}  // namespace

double normalQuantile(double p) {
    if (!(p > 0.0)) return -std::numeric_limits<double>::infinity();
    if (!(p < 1.0)) return std::numeric_limits<double>::infinity();
    // AS 241 coefficients (PPND16), central region |p − 0.5| ≤ 0.425.
    static constexpr double a[8] = {3.3871328727963666080e0,  1.3314166789178437745e+2,
                                    1.9715909503065514427e+3, 1.3731693765509461125e+4,
                                    4.5921953931549871457e+4, 6.7265770927008700853e+4,
                                    3.3430575583588128105e+4, 2.5090809287301226727e+3};
    static constexpr double b[8] = {1.0,
                                    4.2313330701600911252e+1,
                                    6.8718700749205790830e+2,
                                    5.3941960214247511077e+3,
                                    2.1213794301586595867e+4,
                                    3.9307895800092710610e+4,
                                    2.8729085735721942674e+4,
                                    5.2264952788528545610e+3};
    // Intermediate region r ≤ 5.
    static constexpr double c[8] = {1.42343711074968357734e0,  4.63033784615654529590e0,
                                    5.76949722146069140550e0,  3.64784832476320460504e0,
                                    1.27045825245236838258e0,  2.41780725177450611770e-1,
                                    2.27238449892691845833e-2, 7.74545014278341407640e-4};
    static constexpr double d[8] = {1.0,
                                    2.05319162663775882187e0,
                                    1.67638483018380384940e0,
                                    6.89767334985100004550e-1,
                                    1.48103976427480074590e-1,
                                    1.51986665636164571966e-2,
                                    5.47593808499534494600e-4,
                                    1.05075007164441684324e-9};
    // Tail region.
    static constexpr double e[8] = {6.65790464350110377720e0,  5.46378491116411436990e0,
                                    1.78482653991729133580e0,  2.96560571828504891230e-1,
                                    2.65321895265761230930e-2, 1.24266094738807843860e-3,
                                    2.71155556874348757815e-5, 2.01033439929228813265e-7};
    static constexpr double f[8] = {1.0,
                                    5.99832206555887937690e-1,
                                    1.36929880922735805310e-1,
                                    1.48753612908506148525e-2,
                                    7.86869131145613259100e-4,
                                    1.84631831751005468180e-5,
                                    1.42151175831644588870e-7,
                                    2.04426310338993978564e-15};
    const double q = p - 0.5;
    if (std::abs(q) <= 0.425) {
        const double r = 0.180625 - q * q;
        return q * polynomial(a, r) / polynomial(b, r);
    }
    double r = std::sqrt(-std::log(q < 0 ? p : 1.0 - p));
    double value = 0;
    if (r <= 5.0) {
        r -= 1.6;
        value = polynomial(c, r) / polynomial(d, r);
    } else {
        r -= 5.0;
        value = polynomial(e, r) / polynomial(f, r);
    }
    return q < 0 ? -value : value;
}

QqPoints qqPoints(std::span<const double> values) {
    QqPoints points;
    points.sample.assign(values.begin(), values.end());
    std::sort(points.sample.begin(), points.sample.end());
    const auto n = static_cast<double>(values.size());
    points.theoretical.resize(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        // Rankit position (i − 0.5)/n with i 1-based.
        points.theoretical[i] = normalQuantile((static_cast<double>(i) + 0.5) / n);
    }
    return points;
}

namespace {

std::vector<EigenvectorEntry> largestEntries(const Eigen::VectorXd& vector, int count) {
    std::vector<int> order(static_cast<std::size_t>(vector.size()));
    std::iota(order.begin(), order.end(), 0);
    // Stable: equal magnitudes keep feature order.
    std::stable_sort(order.begin(), order.end(),
                     [&](int x, int y) { return std::abs(vector[x]) > std::abs(vector[y]); });
    std::vector<EigenvectorEntry> entries;
    for (int i = 0; i < count && i < static_cast<int>(order.size()); ++i) {
        entries.push_back({order[i], vector[order[i]]});
    }
    return entries;
}

}  // namespace

PcaReport makePcaReport(const SkeletonStats& stats) {
    PcaReport report;
    report.speciesCount = static_cast<int>(stats.species().size());
    const Eigen::VectorXd& values = stats.eigenvalues();
    report.eigenvalues.assign(values.data(), values.data() + values.size());
    report.explained6 = stats.explainedVariance(6);
    report.explained10 = stats.explainedVariance(10);
    report.explained20 = stats.explainedVariance(20);
    report.eigenvaluesAbove001 = stats.countEigenvaluesAbove(0.01);
    report.eigenvaluesAbove0001 = stats.countEigenvaluesAbove(0.001);
    report.meanFeatures = fromFeaturePoint(stats.mean());

    // Order by distance; ties keep the data's order.
    const std::vector<double> distances = stats.distancesToMean();
    std::vector<std::size_t> order(distances.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return distances[x] < distances[y]; });
    const auto& species = stats.species();
    report.nearest = species[order.front()].name;
    report.nearestDistance = distances[order.front()];
    report.farthest = species[order.back()].name;
    report.farthestDistance = distances[order.back()];
    const std::size_t second = order[order.size() - 2];
    report.secondFarthest = species[second].name;
    report.secondFarthestDistance = distances[second];

    const int axes = std::min<int>(7, static_cast<int>(values.size()));
    for (int i = 0; i < axes; ++i) {
        report.topEntries.push_back(largestEntries(stats.eigenvectors().col(i), 4));
    }
    return report;
}

}  // namespace ramus
