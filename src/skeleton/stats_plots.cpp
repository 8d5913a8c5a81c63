// Based on: seed 000 §3.6 and figs. 4.1, 4.2, A.4, A.5 (Q-Q plots with rankits), figs. 4.3c/4.4
// (projection onto the first two eigenvectors, marked by class, wings and legs), fig. 4.6 (the
// mean), figs. 4.10/A.6 (±σ along the first six eigenvectors).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton_stats.hpp"
#include "skeleton/plot_svg.hpp"

namespace ramus {

namespace {

using detail::fixed;
using detail::PlotPanel;
using detail::SvgDocument;

constexpr double kPanelW = 150, kPanelH = 110, kCellW = 215, kCellH = 165;

// One Q-Q panel: sorted values against rankit quantiles, with the line mean + sd·z.
void qqPanel(SvgDocument& doc, double left, double top, std::span<const double> values,
             const std::string& title, double lineMean, double lineSd) {
    const QqPoints qq = qqPoints(values);
    PlotPanel p{left, top, kPanelW, kPanelH};
    p.xMin = qq.theoretical.front();
    p.xMax = qq.theoretical.back();
    p.yMin = std::min(qq.sample.front(), lineMean + lineSd * p.xMin);
    p.yMax = std::max(qq.sample.back(), lineMean + lineSd * p.xMax);
    detail::padRange(p.xMin, p.xMax);
    detail::padRange(p.yMin, p.yMax);
    doc.axes(p, "normal quantile", "");
    doc.line(p.px(p.xMin), p.py(lineMean + lineSd * p.xMin), p.px(p.xMax),
             p.py(lineMean + lineSd * p.xMax), "#d62728", 1, "4 3");
    for (std::size_t i = 0; i < qq.sample.size(); ++i) {
        doc.circle(p.px(qq.theoretical[i]), p.py(qq.sample[i]), 2.2, "#1f77b4");
    }
    doc.text(left + kPanelW / 2, top - 5, title, 10, "middle");
}

std::pair<double, double> meanAndSd(const std::vector<double>& v) {
    double mean = 0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    double var = 0;
    for (double x : v) var += (x - mean) * (x - mean);
    return {mean, std::sqrt(var / static_cast<double>(v.size()))};
}

void gridTitle(SvgDocument& doc, double width, const std::string& title, const std::string& sub) {
    doc.text(width / 2, 22, title, 15, "middle");
    doc.text(width / 2, 40, sub, 10, "middle", "#555555");
}

std::string qqFeatures(const SkeletonStats& s) {
    constexpr int kCols = 6, kPanels = kFeatureCount + 1;
    const double width = kCols * kCellW + 20;
    SvgDocument doc(width, 60 + ((kPanels + kCols - 1) / kCols) * kCellH);
    gridTitle(doc, width, "Q-Q plots of the input features (rankits (i - 0.5)/n)",
              "points: the species sorted; dashed: mean + sd * quantile; spine and limbs in px");
    for (int f = 0; f < kPanels; ++f) {
        std::vector<double> values;
        std::string title;
        for (Eigen::Index i = 0; i < s.data().rows(); ++i) {
            const double scaled = s.data()(i, std::min(f, kFeatureWeight));
            if (f == kFeatureWeight) {
                values.push_back(scaled * 100 * std::log10(kMaxWeightKg + 1));  // log10(kg + 1)
            } else {
                values.push_back(unscaleFeatureValue(std::min(f, kFeatureWeight), scaled));
            }
        }
        if (f < kFeatureWeight) title = featureName(f) + " (" + std::string(featureUnit(f)) + ")";
        if (f == kFeatureWeight) title = "weight (log10(kg + 1))";
        if (f == kFeatureWeight + 1) title = "weight (kg, linear)";
        const auto [mean, sd] = meanAndSd(values);
        qqPanel(doc, 50 + (f % kCols) * kCellW, 75 + (f / kCols) * kCellH, values, title, mean, sd);
    }
    return doc.finish();
}

std::string qqAxes(const SkeletonStats& s) {
    constexpr int kCols = 6;
    const double width = kCols * kCellW + 20;
    SvgDocument doc(width, 60 + ((kFeatureCount + kCols - 1) / kCols) * kCellH);
    gridTitle(doc, width, "Q-Q plots of the species projected onto each principal axis",
              "points: PCA coordinates q_i sorted; dashed: sqrt(lambda_i) * quantile");
    for (int a = 0; a < kFeatureCount; ++a) {
        std::vector<double> values;
        for (Eigen::Index i = 0; i < s.data().rows(); ++i) {
            values.push_back(s.project(s.data().row(i).transpose())[a]);
        }
        const double lambda = s.eigenvalues()[a];
        char title[80];
        std::snprintf(title, sizeof title, "axis %d (lambda %.3g)", a + 1, lambda);
        qqPanel(doc, 50 + (a % kCols) * kCellW, 75 + (a / kCols) * kCellH, values, title, 0.0,
                std::sqrt(lambda));
    }
    return doc.finish();
}

// Projection onto the first two axes, one colour per category.
std::string projection(const SkeletonStats& s, const std::string& what,
                       const std::vector<int>& category, const std::vector<std::string>& names) {
    SvgDocument doc(760, 640);
    doc.text(380, 24, "Species projected onto the first two principal axes, by " + what, 15,
             "middle");
    PlotPanel p{70, 50, 540, 520};
    std::vector<Vec2> q;
    for (Eigen::Index i = 0; i < s.data().rows(); ++i) {
        const Eigen::VectorXd c = s.project(s.data().row(i).transpose());
        q.emplace_back(c[0], c[1]);
    }
    p.xMin = p.yMin = 1e300;
    p.xMax = p.yMax = -1e300;
    for (const Vec2& v : q) {
        p.xMin = std::min(p.xMin, v.x()), p.xMax = std::max(p.xMax, v.x());
        p.yMin = std::min(p.yMin, v.y()), p.yMax = std::max(p.yMax, v.y());
    }
    detail::padRange(p.xMin, p.xMax, 0.12);
    detail::padRange(p.yMin, p.yMax, 0.08);
    doc.axes(p, "q1 (first principal axis)", "q2 (second principal axis)");
    for (std::size_t i = 0; i < q.size(); ++i) {
        const std::string_view colour = detail::categoryColour(category[i]);
        doc.circle(p.px(q[i].x()), p.py(q[i].y()), 4.5, colour, "#333333");
        doc.text(p.px(q[i].x()) + 6, p.py(q[i].y()) + 3, s.species()[i].name, 7, "start",
                 "#444444");
    }
    for (std::size_t c = 0; c < names.size(); ++c) {
        const double y = 70 + 18 * static_cast<double>(c);
        doc.circle(630, y - 3, 5, detail::categoryColour(static_cast<int>(c)), "#333333");
        doc.text(642, y, names[c], 11);
    }
    return doc.finish();
}

std::string eigenvalues(const SkeletonStats& s) {
    SvgDocument doc(760, 600);
    doc.text(380, 24, "Eigenvalues (log scale) and cumulative explained variance", 15, "middle");
    PlotPanel top{70, 50, 640, 230, 0, kFeatureCount + 1.0, -7, 0};
    doc.axes(top, "", "log10(eigenvalue)");
    for (double threshold : {-2.0, -3.0}) {
        doc.line(top.left, top.py(threshold), top.left + top.width, top.py(threshold), "#d62728", 1,
                 "4 3");
    }
    doc.text(top.left + top.width - 4, top.py(-2) - 3, "0.01", 8, "end", "#d62728");
    doc.text(top.left + top.width - 4, top.py(-3) - 3, "0.001", 8, "end", "#d62728");
    PlotPanel bottom{70, 330, 640, 210, 0, kFeatureCount + 1.0, 0, 1.05};
    doc.axes(bottom, "number of components", "explained variance");
    for (int i = 0; i < kFeatureCount; ++i) {
        const double value = std::log10(std::max(s.eigenvalues()[i], 1e-7));
        doc.rect(top.px(i + 0.6), top.py(value), top.px(i + 1.4) - top.px(i + 0.6),
                 top.py(-7) - top.py(value), "#1f77b4");
        const double explained = s.explainedVariance(i + 1);
        doc.circle(bottom.px(i + 1), bottom.py(explained), 3, "#1f77b4");
        if (i + 1 == 6 || i + 1 == 10 || i + 1 == 20) {
            doc.text(bottom.px(i + 1), bottom.py(explained) + 16, fixed(100 * explained) + " %", 9,
                     "middle", "#d62728");
        }
    }
    return doc.finish();
}

std::string caption(const SkeletonFeatures& f) {
    return "wings " + fixed(f.wings, 3) + ", legs " + fixed(f.legs, 2) + ", weight " +
           fixed(f.weightKg, 1) + " kg";
}

std::string meanSkeleton(const SkeletonStats& s) {
    SvgDocument doc(560, 640);
    const SkeletonFeatures mean = fromFeaturePoint(s.mean());
    doc.text(280, 26, "The mean of the species (1000 x 1000 frame)", 15, "middle");
    detail::drawSkeleton(doc, mean, 30, 40, 500);
    doc.text(280, 570, caption(mean), 12, "middle");
    doc.text(280, 592, "neck red, back blue, tail green; front limb purple, hind limb orange", 10,
             "middle", "#555555");
    doc.text(280, 610, "(limbs: only their lengths are data; they hang from shoulder and hip)", 10,
             "middle", "#555555");
    return doc.finish();
}

std::string axesSigma(const SkeletonStats& s) {
    constexpr double kSize = 240;
    SvgDocument doc(2 * kSize + 80, 60 + 6 * (kSize + 40));
    doc.text(kSize + 40, 24, "Points at -sigma and +sigma along the first six axes", 15, "middle");
    for (int axis = 0; axis < 6; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const double sigmas = side == 0 ? -1.0 : 1.0;
            const SkeletonFeatures f = fromFeaturePoint(s.axisPoint(axis, sigmas));
            const double left = 40 + side * kSize, top = 50 + axis * (kSize + 40);
            detail::drawSkeleton(doc, f, left, top, kSize - 10);
            doc.text(left + kSize / 2 - 5, top + kSize + 4,
                     std::to_string(axis + 1) + (side == 0 ? "- : " : "+ : ") + caption(f), 9,
                     "middle");
        }
    }
    return doc.finish();
}

// Seed 000 fig. 4.12: ten conditionally sampled spines each for wings = 0 exactly, wings = 0
// with the random offset, and one pair of legs with the offset (fixed seed); the top row with
// the model's spread, the bottom row with the thesis implementation's (SampleSpread::Thesis).
std::string conditionedSpines(const SkeletonStats& s) {
    constexpr double kSize = 320;
    SvgDocument doc(3 * kSize + 40, 2 * (kSize + 50) + 60);
    doc.text((3 * kSize + 40) / 2, 24, "Ten conditionally sampled spines each (seed 000 fig. 4.12)",
             15, "middle");
    const std::vector<std::pair<std::string, Condition>> panels = {
        {"wings = 0 (exact)", Condition{kFeatureWings, 0.0, 0.0}},
        {"wings = 0 + U(-0.5, 0.5)", Condition::wings(0.0)},
        {"legs = 1 pair + U(-0.5, 0.5)", Condition::legs(1.0)},
    };
    for (int row = 0; row < 2; ++row) {
        const SampleSpread spread = row == 0 ? SampleSpread::Model : SampleSpread::Thesis;
        const double top = 45 + row * (kSize + 50);
        for (std::size_t p = 0; p < panels.size(); ++p) {
            const ConditionalModel model = s.condition({panels[p].second});
            std::vector<SkeletonFeatures> spines;
            for (std::uint64_t i = 0; i < 10; ++i) {
                Rng rng = Rng::forStream(2020, i);
                spines.push_back(fromFeaturePoint(model.sample(rng, spread)));
            }
            const double left = 20 + static_cast<double>(p) * kSize;
            detail::drawSpines(doc, spines, left, top, kSize - 10);
            doc.text(left + kSize / 2 - 5, top + kSize + 10,
                     panels[p].first + (row == 0 ? ", q ~ N(0, lambda)" : ", q = lambda N(0, 1)"),
                     11, "middle");
        }
    }
    return doc.finish();
}

std::string speciesGrid(const SkeletonStats& s) {
    constexpr int kCols = 8;
    constexpr double kSize = 150;
    const int rows = static_cast<int>((s.species().size() + kCols - 1) / kCols);
    SvgDocument doc(kCols * kSize + 20, 50 + rows * (kSize + 22));
    doc.text((kCols * kSize + 20) / 2, 24, "The species data", 15, "middle");
    for (std::size_t i = 0; i < s.species().size(); ++i) {
        const double left = 10 + static_cast<double>(i % kCols) * kSize;
        const double top = 40 + static_cast<double>(i / kCols) * (kSize + 22);
        detail::drawSkeleton(doc, s.species()[i].features, left, top, kSize - 6);
        doc.text(left + kSize / 2, top + kSize + 8, s.species()[i].name, 9, "middle");
    }
    return doc.finish();
}

}  // namespace

std::vector<std::string> writePcaPlots(const SkeletonStats& stats, const std::string& directory) {
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (ec) throw Error(directory + ": cannot create directory: " + ec.message());
    std::vector<int> byClass, byWings, byLegs;
    for (const SpeciesRecord& r : stats.species()) {
        byClass.push_back(static_cast<int>(r.animalClass));
        byWings.push_back(r.features.wings > 0.5 ? 1 : 0);
        byLegs.push_back(static_cast<int>(std::clamp(std::round(r.features.legs), 0.0, 2.0)));
    }
    const std::vector<std::pair<std::string, std::string>> files = {
        {"qq_features.svg", qqFeatures(stats)},
        {"qq_axes.svg", qqAxes(stats)},
        {"projection_class.svg",
         projection(stats, "class", byClass, {"fish", "amphibian", "reptile", "bird", "mammal"})},
        {"projection_wings.svg", projection(stats, "wings", byWings, {"no wings", "wings"})},
        {"projection_legs.svg", projection(stats, "pairs of legs on the ground", byLegs,
                                           {"0 pairs", "1 pair", "2 pairs"})},
        {"eigenvalues.svg", eigenvalues(stats)},
        {"mean_skeleton.svg", meanSkeleton(stats)},
        {"axes_sigma.svg", axesSigma(stats)},
        {"species.svg", speciesGrid(stats)},
        {"conditioned_spines.svg", conditionedSpines(stats)},
    };
    std::vector<std::string> written;
    for (const auto& [name, content] : files) {
        const std::string path = (std::filesystem::path(directory) / name).string();
        writeFileAtomic(path, content);
        written.push_back(path);
    }
    return written;
}

}  // namespace ramus
