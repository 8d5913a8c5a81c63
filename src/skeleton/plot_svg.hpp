// Internal: just enough SVG to draw the statistics' diagnostic figures — a document, panels
// with linear data→pixel axes, marks, text. Numbers are printed with fixed precision so the
// files are byte-identical across runs.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/math.hpp"
#include "ramus/species.hpp"

namespace ramus::detail {

/// A rectangle on the page (pixels, y down) showing data in [xMin, xMax] × [yMin, yMax].
struct PlotPanel {
    double left = 0, top = 0, width = 100, height = 100;
    double xMin = 0, xMax = 1, yMin = 0, yMax = 1;

    double px(double x) const { return left + (x - xMin) / (xMax - xMin) * width; }
    double py(double y) const { return top + height - (y - yMin) / (yMax - yMin) * height; }
};

/// Expands [lo, hi] by a margin fraction; a degenerate range becomes [lo − 1, hi + 1].
void padRange(double& lo, double& hi, double margin = 0.05);

class SvgDocument {
public:
    SvgDocument(double width, double height);

    void line(double x1, double y1, double x2, double y2, std::string_view colour,
              double strokeWidth = 1, std::string_view dash = {});
    void circle(double x, double y, double radius, std::string_view fill,
                std::string_view stroke = "none");
    void rect(double x, double y, double w, double h, std::string_view fill,
              std::string_view stroke = "none");
    /// anchor: "start", "middle" or "end".
    void text(double x, double y, std::string_view content, double size = 11,
              std::string_view anchor = "start", std::string_view colour = "#222222");
    /// Frame, ticks at "nice" positions with labels, and axis titles.
    void axes(const PlotPanel& panel, std::string_view xTitle, std::string_view yTitle);
    /// Raw markup (already escaped).
    void raw(std::string_view markup) { body_ += markup; }

    std::string finish() const;

private:
    double width_, height_;
    std::string body_;
};

/// "%.*f" with a fixed number of decimals.
std::string fixed(double value, int decimals = 2);

/// Draws a skeleton's spine (neck, back, tail curves and their control polygons) and limb
/// chains hanging from shoulder and hip into the square cell [left, left+size] × [top, top+size]
/// of the page, which shows the 1000×1000 frame (y up) with a margin.
void drawSkeleton(SvgDocument& doc, const SkeletonFeatures& features, double left, double top,
                  double size);

/// Draws only the spines of several skeletons (one colour each, head as a dot) into one cell,
/// like drawSkeleton.
void drawSpines(SvgDocument& doc, std::span<const SkeletonFeatures> skeletons, double left,
                double top, double size);

/// Distinct colours for categories (index modulo the palette size).
std::string_view categoryColour(int index);

}  // namespace ramus::detail
