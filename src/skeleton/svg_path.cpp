// Based on: W3C SVG 1.1 (Second Edition) §8.3 "Path data" (grammar and command semantics,
// including the reflected control points of S/T) and §7.6 "The transform attribute".
#include "skeleton/svg_path.hpp"

#include <cmath>
#include <stdexcept>

#include "skeleton/number_text.hpp"

namespace ramus::detail {

double Affine2::similarityScale() const {
    const double det = a * d - b * c;
    const double scale = std::sqrt(std::abs(det));
    const double tolerance = 1e-12 * (std::abs(a) + std::abs(b) + std::abs(c) + std::abs(d));
    const bool rotation = std::abs(a - d) <= tolerance && std::abs(b + c) <= tolerance;
    const bool reflection = std::abs(a + d) <= tolerance && std::abs(b - c) <= tolerance;
    if (scale == 0.0 || !(rotation || reflection)) return -1.0;
    // Exact for the common cases (pure translation, flips, uniform scale).
    if (b == 0.0 && c == 0.0 && std::abs(a) == std::abs(d)) return std::abs(a);
    return scale;
}

namespace {

bool isSpace(char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f'; }

// A cursor over path data or a transform list with the shared number/separator rules.
class Scanner {
public:
    explicit Scanner(std::string_view text) : text_(text) {}

    void skipSpace() {
        while (pos_ < text_.size() && isSpace(text_[pos_])) ++pos_;
    }
    void skipSeparator() {
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == ',') ++pos_;
        skipSpace();
    }
    bool atEnd() {
        skipSpace();
        return pos_ >= text_.size();
    }
    char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
    void advance() { ++pos_; }
    std::size_t position() const { return pos_; }

    bool startsNumber() {
        skipSpace();
        const char ch = peek();
        return (ch >= '0' && ch <= '9') || ch == '-' || ch == '+' || ch == '.';
    }

    double number(const char* what) {
        skipSpace();
        const std::optional<double> value = parseNumber(text_, pos_);
        if (!value) fail(std::string("expected a number (") + what + ")");
        skipSeparator();
        return *value;
    }

    // Arc flags are single characters and may be written without separators ("a1 1 0 00 1 1").
    bool flag() {
        skipSpace();
        const char ch = peek();
        if (ch != '0' && ch != '1') fail("expected an arc flag 0 or 1");
        ++pos_;
        skipSeparator();
        return ch == '1';
    }

    [[noreturn]] void fail(const std::string& message) const {
        std::string got = pos_ < text_.size() ? "'" + std::string(1, text_[pos_]) + "'" : "the end";
        throw std::invalid_argument("at character " + std::to_string(pos_ + 1) + ": " + message +
                                    ", got " + got);
    }

private:
    std::string_view text_;
    std::size_t pos_ = 0;
};

Affine2 transformFunction(std::string_view name, const std::vector<double>& v, Scanner& s) {
    const std::size_t n = v.size();
    const auto needs = [&](bool ok, const char* expected) {
        if (!ok) s.fail(std::string(name) + "() takes " + expected);
    };
    if (name == "matrix") {
        needs(n == 6, "6 numbers");
        return {v[0], v[1], v[2], v[3], v[4], v[5]};
    }
    if (name == "translate") {
        needs(n == 1 || n == 2, "1 or 2 numbers");
        return {1, 0, 0, 1, v[0], n == 2 ? v[1] : 0.0};
    }
    if (name == "scale") {
        needs(n == 1 || n == 2, "1 or 2 numbers");
        return {v[0], 0, 0, n == 2 ? v[1] : v[0], 0, 0};
    }
    if (name == "rotate") {
        needs(n == 1 || n == 3, "1 or 3 numbers");
        const double r = degToRad(v[0]);
        const Affine2 rotation{std::cos(r), std::sin(r), -std::sin(r), std::cos(r), 0, 0};
        if (n == 1) return rotation;
        return Affine2{1, 0, 0, 1, v[1], v[2]} * rotation * Affine2{1, 0, 0, 1, -v[1], -v[2]};
    }
    if (name == "skewX") {
        needs(n == 1, "1 number");
        return {1, 0, std::tan(degToRad(v[0])), 1, 0, 0};
    }
    if (name == "skewY") {
        needs(n == 1, "1 number");
        return {1, std::tan(degToRad(v[0])), 0, 1, 0, 0};
    }
    s.fail("expected matrix, translate, scale, rotate, skewX or skewY");
}

}  // namespace

Affine2 parseTransform(std::string_view text) {
    Scanner s(text);
    Affine2 result;
    while (!s.atEnd()) {
        std::string name;
        while (std::isalpha(static_cast<unsigned char>(s.peek()))) {
            name += s.peek();
            s.advance();
        }
        if (name.empty()) s.fail("expected a transform function name");
        s.skipSpace();
        if (s.peek() != '(') s.fail("expected ( after " + name);
        s.advance();
        std::vector<double> values;
        while (s.startsNumber() && values.size() < 7) values.push_back(s.number("argument"));
        s.skipSpace();
        if (s.peek() != ')') s.fail("expected ) to close " + name + "(");
        s.advance();
        result = result * transformFunction(name, values, s);
        s.skipSeparator();
    }
    return result;
}

namespace {

// Path state machine: current point, subpath start, last control point (for S/T reflection).
class PathBuilder {
public:
    explicit PathBuilder(std::string_view d) : s_(d) {}

    std::vector<PathSegment> run() {
        char command = 0;
        while (!s_.atEnd()) {
            if (!s_.startsNumber()) {
                command = s_.peek();
                s_.advance();
            } else if (command == 0) {
                s_.fail("expected a path command (M, L, C, …)");
            } else if (command == 'M' || command == 'm') {
                command = command == 'M' ? 'L' : 'l';  // implicit lineto after a moveto
            } else if (command == 'Z' || command == 'z') {
                s_.fail("expected a command after Z");
            }
            if (segments_.empty() && !started_ && command != 'M' && command != 'm') {
                s_.fail("path data must start with M or m");
            }
            step(command);
        }
        return std::move(segments_);
    }

private:
    Vec2 point(bool relative, const char* what) {
        const double x = s_.number(what);
        const double y = s_.number(what);
        return relative ? current_ + Vec2(x, y) : Vec2(x, y);
    }

    void add(SegmentKind kind, Vec2 p1, Vec2 p2, Vec2 end) {
        segments_.push_back({kind, current_, p1, p2, end, subpath_});
        current_ = end;
    }

    void step(char command) {
        const bool rel = std::islower(static_cast<unsigned char>(command)) != 0;
        const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
        const SegmentKind previous = lastKind_;
        lastKind_ = SegmentKind::Line;
        switch (upper) {
            case 'M':
                current_ = point(rel && started_, "moveto point");
                subpathStart_ = current_;
                if (started_) ++subpath_;
                started_ = true;
                break;
            case 'L':
                add(SegmentKind::Line, current_, current_, point(rel, "lineto point"));
                break;
            case 'H': {
                const double x = s_.number("x");
                add(SegmentKind::Line, current_, current_,
                    {rel ? current_.x() + x : x, current_.y()});
                break;
            }
            case 'V': {
                const double y = s_.number("y");
                add(SegmentKind::Line, current_, current_,
                    {current_.x(), rel ? current_.y() + y : y});
                break;
            }
            case 'C':
            case 'S': {
                // S: first control = reflection of the previous cubic's second control point.
                const Vec2 c1 = upper == 'C'                     ? point(rel, "control point")
                                : previous == SegmentKind::Cubic ? 2 * current_ - control_
                                                                 : current_;
                const Vec2 c2 = point(rel, "control point");
                add(SegmentKind::Cubic, c1, c2, point(rel, "end point"));
                control_ = c2;
                lastKind_ = SegmentKind::Cubic;
                break;
            }
            case 'Q':
            case 'T': {
                const Vec2 c = upper == 'Q'                         ? point(rel, "control point")
                               : previous == SegmentKind::Quadratic ? 2 * current_ - control_
                                                                    : current_;
                add(SegmentKind::Quadratic, c, c, point(rel, "end point"));
                control_ = c;
                lastKind_ = SegmentKind::Quadratic;
                break;
            }
            case 'A': {
                for (int i = 0; i < 3; ++i) s_.number("arc radius/rotation");
                s_.flag();
                s_.flag();
                add(SegmentKind::Arc, current_, current_, point(rel, "arc end point"));
                break;
            }
            case 'Z':
                if (current_ != subpathStart_)
                    add(SegmentKind::Line, current_, current_, subpathStart_);
                current_ = subpathStart_;
                break;
            default:
                s_.fail("expected a path command (M L H V C S Q T A Z)");
        }
    }

    Scanner s_;
    std::vector<PathSegment> segments_;
    Vec2 current_{0, 0};
    Vec2 subpathStart_{0, 0};
    Vec2 control_{0, 0};
    SegmentKind lastKind_ = SegmentKind::Line;
    int subpath_ = 0;
    bool started_ = false;
};

}  // namespace

std::vector<PathSegment> parsePathData(std::string_view d) { return PathBuilder(d).run(); }

}  // namespace ramus::detail
