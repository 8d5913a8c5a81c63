// SVG drawing primitives for the statistics' diagnostic figures.
#include "skeleton/plot_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skeleton/svg_xml.hpp"

namespace ramus::detail {

std::string fixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

void padRange(double& lo, double& hi, double margin) {
    if (!(hi > lo)) {
        lo -= 1;
        hi += 1;
        return;
    }
    const double pad = (hi - lo) * margin;
    lo -= pad;
    hi += pad;
}

SvgDocument::SvgDocument(double width, double height) : width_(width), height_(height) {}

void SvgDocument::line(double x1, double y1, double x2, double y2, std::string_view colour,
                       double strokeWidth, std::string_view dash) {
    body_ += "<line x1=\"" + fixed(x1) + "\" y1=\"" + fixed(y1) + "\" x2=\"" + fixed(x2) +
             "\" y2=\"" + fixed(y2) + "\" stroke=\"" + std::string(colour) + "\" stroke-width=\"" +
             fixed(strokeWidth) + "\"";
    if (!dash.empty()) body_ += " stroke-dasharray=\"" + std::string(dash) + "\"";
    body_ += "/>\n";
}

void SvgDocument::circle(double x, double y, double radius, std::string_view fill,
                         std::string_view stroke) {
    body_ += "<circle cx=\"" + fixed(x) + "\" cy=\"" + fixed(y) + "\" r=\"" + fixed(radius) +
             "\" fill=\"" + std::string(fill) + "\" stroke=\"" + std::string(stroke) + "\"/>\n";
}

void SvgDocument::rect(double x, double y, double w, double h, std::string_view fill,
                       std::string_view stroke) {
    body_ += "<rect x=\"" + fixed(x) + "\" y=\"" + fixed(y) + "\" width=\"" + fixed(w) +
             "\" height=\"" + fixed(h) + "\" fill=\"" + std::string(fill) + "\" stroke=\"" +
             std::string(stroke) + "\"/>\n";
}

void SvgDocument::text(double x, double y, std::string_view content, double size,
                       std::string_view anchor, std::string_view colour) {
    body_ += "<text x=\"" + fixed(x) + "\" y=\"" + fixed(y) + "\" font-size=\"" + fixed(size, 1) +
             "\" text-anchor=\"" + std::string(anchor) + "\" fill=\"" + std::string(colour) +
             "\">" + escapeXml(content) + "</text>\n";
}

namespace {

// Tick spacing 1, 2 or 5 × 10^k giving about `count` ticks.
double niceStep(double range, int count) {
    const double raw = range / (count + 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (m * magnitude >= raw) return m * magnitude;
    }
    return 10 * magnitude;
}

std::string tickLabel(double value, double step) {
    const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step))), 0, 6);
    return fixed(std::abs(value) < step * 1e-9 ? 0.0 : value, decimals);
}

}  // namespace

void SvgDocument::axes(const PlotPanel& p, std::string_view xTitle, std::string_view yTitle) {
    rect(p.left, p.top, p.width, p.height, "none", "#888888");
    const double xStep = niceStep(p.xMax - p.xMin, 4);
    for (double x = std::ceil(p.xMin / xStep) * xStep; x <= p.xMax; x += xStep) {
        line(p.px(x), p.top + p.height, p.px(x), p.top + p.height + 3, "#888888");
        text(p.px(x), p.top + p.height + 12, tickLabel(x, xStep), 8, "middle", "#555555");
    }
    const double yStep = niceStep(p.yMax - p.yMin, 4);
    for (double y = std::ceil(p.yMin / yStep) * yStep; y <= p.yMax; y += yStep) {
        line(p.left - 3, p.py(y), p.left, p.py(y), "#888888");
        text(p.left - 5, p.py(y) + 3, tickLabel(y, yStep), 8, "end", "#555555");
    }
    if (!xTitle.empty()) text(p.left + p.width / 2, p.top + p.height + 24, xTitle, 9, "middle");
    if (!yTitle.empty()) {
        body_ += "<text transform=\"translate(" + fixed(p.left - 34) + " " +
                 fixed(p.top + p.height / 2) +
                 ") rotate(-90)\" font-size=\"9.0\" text-anchor=\"middle\" fill=\"#222222\">" +
                 escapeXml(yTitle) + "</text>\n";
    }
}

std::string SvgDocument::finish() const {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
           fixed(width_, 0) + "\" height=\"" + fixed(height_, 0) + "\" viewBox=\"0 0 " +
           fixed(width_, 0) + " " + fixed(height_, 0) +
           "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n<rect width=\"100%\" "
           "height=\"100%\" fill=\"#ffffff\"/>\n" +
           body_ + "</svg>\n";
}

std::string_view categoryColour(int index) {
    static constexpr std::string_view kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                                    "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
    return kPalette[static_cast<std::size_t>(index) % 8];
}

namespace {

std::string pointText(const Vec2& p) { return fixed(p.x(), 1) + " " + fixed(p.y(), 1); }

// One spine part: the cubic and its dashed control polygon, in frame coordinates.
std::string curveMarkup(const SkeletonFeatures& f, int first, std::string_view colour) {
    const auto& s = f.spine;
    std::string out = "<path d=\"M " + pointText(s[first]) + " L " + pointText(s[first + 1]) +
                      " L " + pointText(s[first + 2]) + " L " + pointText(s[first + 3]) +
                      "\" fill=\"none\" stroke=\"" + std::string(colour) +
                      "\" stroke-opacity=\"0.45\" stroke-width=\"3\" stroke-dasharray=\"12 8\"/>\n";
    out += "<path d=\"M " + pointText(s[first]) + " C " + pointText(s[first + 1]) + " " +
           pointText(s[first + 2]) + " " + pointText(s[first + 3]) + "\" fill=\"none\" stroke=\"" +
           std::string(colour) + "\" stroke-width=\"12\" stroke-linecap=\"round\"/>\n";
    return out;
}

std::string limbMarkup(const SkeletonFeatures& f, int firstLimb, Vec2 start,
                       std::string_view colour) {
    std::string out;
    for (int i = firstLimb; i < firstLimb + 3; ++i) {
        const double length = f.limbs[i];
        if (!(length > 0)) continue;
        const Vec2 end = start - Vec2(0, length);
        // Alternate a little sideways so consecutive bones stay distinguishable.
        const double dx = (i % 3 == 1) ? 14 : 0;
        out += "<line x1=\"" + fixed(start.x() + dx, 1) + "\" y1=\"" + fixed(start.y(), 1) +
               "\" x2=\"" + fixed(end.x() + dx, 1) + "\" y2=\"" + fixed(end.y(), 1) +
               "\" stroke=\"" + std::string(colour) +
               "\" stroke-width=\"9\" stroke-linecap=\"round\"/>\n";
        start = end;
    }
    return out;
}

}  // namespace

namespace {

// A nested viewport on the frame with a 10 % margin; the group inside flips y up.
std::string frameOpen(double left, double top, double size) {
    return "<svg x=\"" + fixed(left) + "\" y=\"" + fixed(top) + "\" width=\"" + fixed(size) +
           "\" height=\"" + fixed(size) +
           "\" viewBox=\"-100 -100 1200 1200\" overflow=\"hidden\">\n"
           "<rect x=\"0\" y=\"0\" width=\"1000\" height=\"1000\" fill=\"#fafafa\" "
           "stroke=\"#bbbbbb\" stroke-width=\"4\"/>\n"
           "<g transform=\"matrix(1 0 0 -1 0 1000)\">\n";
}

}  // namespace

void drawSkeleton(SvgDocument& doc, const SkeletonFeatures& f, double left, double top,
                  double size) {
    std::string out = frameOpen(left, top, size);
    out += limbMarkup(f, 0, f.spine[3], "#9467bd");
    out += limbMarkup(f, 3, f.spine[6], "#ff7f0e");
    out += curveMarkup(f, 0, "#d62728");
    out += curveMarkup(f, 3, "#1f77b4");
    out += curveMarkup(f, 6, "#2ca02c");
    out += "<circle cx=\"" + fixed(f.spine[0].x(), 1) + "\" cy=\"" + fixed(f.spine[0].y(), 1) +
           "\" r=\"22\" fill=\"#d62728\"/>\n</g>\n</svg>\n";
    doc.raw(out);
}

void drawSpines(SvgDocument& doc, std::span<const SkeletonFeatures> skeletons, double left,
                double top, double size) {
    std::string out = frameOpen(left, top, size);
    for (std::size_t i = 0; i < skeletons.size(); ++i) {
        const auto& s = skeletons[i].spine;
        std::string d = "M " + pointText(s[0]);
        for (int first : {0, 3, 6}) {
            d += " C " + pointText(s[first + 1]) + " " + pointText(s[first + 2]) + " " +
                 pointText(s[first + 3]);
        }
        out += "<path d=\"" + d + "\" fill=\"none\" stroke=\"" +
               std::string(categoryColour(static_cast<int>(i))) +
               "\" stroke-width=\"8\" stroke-opacity=\"0.8\"/>\n";
        out += "<circle cx=\"" + fixed(s[0].x(), 1) + "\" cy=\"" + fixed(s[0].y(), 1) +
               "\" r=\"14\" fill=\"" + std::string(categoryColour(static_cast<int>(i))) + "\"/>\n";
    }
    doc.raw(out + "</g>\n</svg>\n");
}

}  // namespace ramus::detail
