// Based on: seed 000 §7.4.1 (annotating skeleton pictures in Inkscape: named paths for the
// spine curves and limb bones, absolute coordinates, SVG's y-down origin vs Inkscape's y-up
// ruler, layer offsets) and §4.2 (missing neck/tail repeat the back's end points); SPEC §E
// (fitting into the 1000×1000 frame).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "ramus/error.hpp"
#include "ramus/species.hpp"
#include "skeleton/number_text.hpp"
#include "skeleton/svg_path.hpp"
#include "skeleton/svg_xml.hpp"

namespace ramus {

namespace {

using detail::Affine2;
using detail::PathSegment;
using detail::SegmentKind;
using detail::XmlDocument;
using detail::XmlElement;

constexpr double kFrame = 1000.0;
// How far apart (px, in the frame) the neck's end and the back's start (and the back's end and
// the tail's start) may be; the shared point is taken from the back.
constexpr double kJointTolerance = 50.0;

// Annotation slots: 0 neck, 1 back, 2 tail, 3.. the six limbs.
constexpr int kNeck = 0, kBack = 1, kTail = 2, kFirstLimbSlot = 3, kSlotCount = 9;

int slotOf(std::string label) {
    for (char& ch : label) {
        ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        if (ch == '-' || ch == ' ') ch = '_';
    }
    if (label == "neck") return kNeck;
    if (label == "back") return kBack;
    if (label == "tail") return kTail;
    if (label == "lower_arm") label = "forearm";
    if (label == "upper_leg") label = "thigh";
    if (label == "lower_leg") label = "shank";
    for (int i = 0; i < kLimbCount; ++i) {
        if (label == limbName(static_cast<Limb>(i))) return kFirstLimbSlot + i;
    }
    return -1;
}

std::string slotName(int slot) {
    if (slot == kNeck) return "neck";
    if (slot == kBack) return "back";
    if (slot == kTail) return "tail";
    return std::string(limbName(static_cast<Limb>(slot - kFirstLimbSlot)));
}

struct Annotation {
    const XmlElement* element = nullptr;
    std::vector<PathSegment> segments;  // local coordinates
    Affine2 ctm;                        // local → document user space
};

class SvgImporter {
public:
    SvgImporter(std::string_view text, const std::string& fileName, const SvgImportOptions& options)
        : file_(fileName), options_(options), doc_(detail::parseXml(text, fileName)) {}

    SpeciesRecord run() {
        const XmlElement& root = doc_.elements.front();
        if (root.localName() != "svg")
            fail(root, "expected the root element <svg>, got <" + root.name + ">");
        collect();
        if (!annotations_[kBack].element) {
            throw Error(SourceLoc{file_, 0, 0},
                        "no path named \"back\"; expected paths labelled (inkscape:label or id) "
                        "neck, back, tail, upper_arm, forearm, hand, thigh, shank, foot");
        }
        const Affine2 toFrame = frameTransform();
        SpeciesRecord record;
        record.features.spine = spine(toFrame);
        for (int i = 0; i < kLimbCount; ++i) {
            record.features.limbs[i] = limbLength(annotations_[kFirstLimbSlot + i], toFrame);
        }
        // Extreme transforms can overflow; a record must hold finite numbers only.
        bool finite = true;
        for (const Vec2& p : record.features.spine) finite = finite && p.allFinite();
        for (double length : record.features.limbs) finite = finite && std::isfinite(length);
        if (!finite) {
            throw Error(SourceLoc{file_, 0, 0},
                        "coordinates overflow after applying the transforms; expected finite "
                        "numbers");
        }
        fillFields(record, root);
        return record;
    }

private:
    [[noreturn]] void fail(const XmlElement& e, const std::string& message) const {
        throw Error(SourceLoc{file_, e.line, e.column}, message);
    }

    static bool hidden(std::string_view name) {
        return name == "defs" || name == "clipPath" || name == "mask" || name == "symbol" ||
               name == "pattern" || name == "marker" || name == "metadata";
    }

    Affine2 ownTransform(const XmlElement& e) const {
        const std::string* t = e.attribute("transform");
        if (!t) return {};
        try {
            return detail::parseTransform(*t);
        } catch (const std::invalid_argument& error) {
            fail(e, "bad transform \"" + *t + "\": " + error.what());
        }
    }

    // Walks the document once: transforms, skipped subtrees, annotations, images.
    void collect() {
        const std::size_t n = doc_.elements.size();
        std::vector<Affine2> ctm(n);
        std::vector<bool> skipped(n, false);
        for (std::size_t i = 0; i < n; ++i) {
            const XmlElement& e = doc_.elements[i];
            const Affine2 parent = e.parent < 0 ? Affine2{} : ctm[e.parent];
            skipped[i] = (e.parent >= 0 && skipped[e.parent]) || hidden(e.localName());
            if (skipped[i]) continue;
            ctm[i] = parent * ownTransform(e);
            if (e.localName() == "image") addImage(e, ctm[i]);
            const std::string* label = e.attribute("inkscape:label");
            if (!label) label = e.attribute("id");
            const int slot = label ? slotOf(*label) : -1;
            if (slot < 0 || e.localName() == "g" || e.localName() == "svg") continue;
            Annotation& a = annotations_[slot];
            if (a.element) {
                fail(e, "a second element named \"" + slotName(slot) + "\" (the first is at line " +
                            std::to_string(a.element->line) + "); expected each name once");
            }
            a.element = &e;
            a.ctm = ctm[i];
            a.segments = segmentsOf(e, slot);
        }
    }

    std::vector<PathSegment> segmentsOf(const XmlElement& e, int slot) const {
        std::string d;
        const std::string_view kind = e.localName();
        if (kind == "path") {
            const std::string* attr = e.attribute("d");
            if (!attr) fail(e, "path \"" + slotName(slot) + "\" has no d attribute");
            d = *attr;
        } else if (kind == "line") {
            const auto num = [&](const char* key) {
                const std::string* v = e.attribute(key);
                return v ? *v : std::string("0");
            };
            d = "M " + num("x1") + " " + num("y1") + " L " + num("x2") + " " + num("y2");
        } else if (kind == "polyline") {
            const std::string* points = e.attribute("points");
            d = "M " + (points ? *points : std::string());
        } else {
            fail(e, "\"" + slotName(slot) + "\" is a <" + e.name +
                        ">; expected a <path>, <line> or <polyline>");
        }
        try {
            return detail::parsePathData(d);
        } catch (const std::invalid_argument& error) {
            fail(e, "bad path data for \"" + slotName(slot) + "\": " + error.what());
        }
    }

    void addImage(const XmlElement& e, const Affine2& ctm) {
        const auto value = [&](const char* key) {
            const std::string* v = e.attribute(key);
            std::size_t pos = 0;
            const auto number = v ? detail::parseNumber(*v, pos) : std::nullopt;
            return number.value_or(0.0);
        };
        const double x = value("x"), y = value("y"), w = value("width"), h = value("height");
        if (!(w > 0 && h > 0)) return;
        for (const Vec2& corner :
             {Vec2(x, y), Vec2(x + w, y), Vec2(x, y + h), Vec2(x + w, y + h)}) {
            imageBox_.add(Vec3(ctm.apply(corner).x(), ctm.apply(corner).y(), 0));
        }
    }

    // The rectangle (document user units) that is fitted into the frame.
    Aabb fitBox() const {
        if (options_.fit == SvgFit::Content) {
            if (!imageBox_.empty()) return imageBox_;
            Aabb box;
            for (const Annotation& a : annotations_) {
                for (const PathSegment& s : a.segments) {
                    for (const Vec2& p : {s.p0, s.p1, s.p2, s.p3}) {
                        const Vec2 q = a.ctm.apply(p);
                        box.add(Vec3(q.x(), q.y(), 0));
                    }
                }
            }
            return box;
        }
        return documentFrame();
    }

    Aabb documentFrame() const {
        const XmlElement& root = doc_.elements.front();
        Aabb box;
        if (const std::string* viewBox = root.attribute("viewBox")) {
            std::array<double, 4> v{};
            std::size_t pos = 0;
            for (double& value : v) {
                while (pos < viewBox->size() &&
                       (std::isspace(static_cast<unsigned char>((*viewBox)[pos])) ||
                        (*viewBox)[pos] == ','))
                    ++pos;
                const auto number = detail::parseNumber(*viewBox, pos);
                if (!number) fail(root, "bad viewBox \"" + *viewBox + "\"; expected 4 numbers");
                value = *number;
            }
            if (!(v[2] > 0 && v[3] > 0)) fail(root, "viewBox width and height must be > 0");
            box.add(Vec3(v[0], v[1], 0));
            box.add(Vec3(v[0] + v[2], v[1] + v[3], 0));
            return box;
        }
        const double w = length(root, "width"), h = length(root, "height");
        box.add(Vec3(0, 0, 0));
        box.add(Vec3(w, h, 0));
        return box;
    }

    // A root width/height in user units (px; mm, cm, in, pt, pc converted at 96 dpi).
    double length(const XmlElement& root, const char* key) const {
        const std::string* v = root.attribute(key);
        if (!v) fail(root, std::string("the <svg> has neither a viewBox nor a ") + key);
        std::size_t pos = 0;
        const auto number = detail::parseNumber(*v, pos);
        const std::string unit = v->substr(pos);
        double factor = 0;
        if (unit.empty() || unit == "px")
            factor = 1;
        else if (unit == "mm")
            factor = 96 / 25.4;
        else if (unit == "cm")
            factor = 96 / 2.54;
        else if (unit == "in")
            factor = 96;
        else if (unit == "pt")
            factor = 96.0 / 72;
        else if (unit == "pc")
            factor = 16;
        if (!number || factor == 0 || !(*number > 0)) {
            fail(root, std::string("bad ") + key + " \"" + *v + "\"; expected a positive length");
        }
        return *number * factor;
    }

    // Document user space → 1000×1000 frame, y up: scale to fit without distortion, bottom
    // edge on y = 0, centred horizontally (Frame/Content), or just the flip (None).
    Affine2 frameTransform() const {
        const Aabb box = fitBox();
        if (box.empty()) return Affine2{1, 0, 0, options_.yUp ? 1.0 : -1.0, 0, 0};
        const double width = box.max.x() - box.min.x();
        const double height = box.max.y() - box.min.y();
        double scale = 1.0;
        double shiftX = 0.0;
        if (options_.fit != SvgFit::None) {
            const double larger = std::max(width, height);
            scale = larger > 0 ? kFrame / larger : 1.0;
            shiftX = (kFrame - width * scale) / 2 - box.min.x() * scale;
        }
        // y up: bottom = min y; y down (SVG): bottom = max y, and y is mirrored.
        if (options_.yUp) return {scale, 0, 0, scale, shiftX, -box.min.y() * scale};
        return {scale, 0, 0, -scale, shiftX, box.max.y() * scale};
    }

    // The single curve of a spine part as 4 control points in the frame.
    std::array<Vec2, 4> curve(int slot, const Affine2& toFrame) const {
        const Annotation& a = annotations_[slot];
        if (a.segments.size() != 1) {
            fail(*a.element, "\"" + slotName(slot) + "\" must be one cubic Bézier (or line), got " +
                                 std::to_string(a.segments.size()) + " segments");
        }
        const PathSegment& s = a.segments.front();
        const Affine2 m = toFrame * a.ctm;
        switch (s.kind) {
            case SegmentKind::Cubic:
                return {m.apply(s.p0), m.apply(s.p1), m.apply(s.p2), m.apply(s.p3)};
            case SegmentKind::Quadratic:  // exact degree elevation
                return {m.apply(s.p0), m.apply(s.p0 + (s.p1 - s.p0) * (2.0 / 3)),
                        m.apply(s.p3 + (s.p1 - s.p3) * (2.0 / 3)), m.apply(s.p3)};
            case SegmentKind::Line:
                return {m.apply(s.p0), m.apply(s.p0 + (s.p3 - s.p0) / 3),
                        m.apply(s.p0 + (s.p3 - s.p0) * (2.0 / 3)), m.apply(s.p3)};
            case SegmentKind::Arc:
                break;
        }
        fail(*a.element, "\"" + slotName(slot) + "\" is an arc; expected a cubic Bézier or line");
    }

    static std::array<Vec2, 4> reversed(const std::array<Vec2, 4>& c) {
        return {c[3], c[2], c[1], c[0]};
    }

    void checkJoint(int slot, const Vec2& end, const Vec2& joint, const char* jointName) const {
        const double gap = (end - joint).norm();
        if (gap > kJointTolerance) {
            fail(*annotations_[slot].element, "\"" + slotName(slot) +
                                                  "\" does not meet the back at the " + jointName +
                                                  " (" + detail::shortest(std::round(gap)) +
                                                  " px apart in the 1000 px frame); expected "
                                                  "the curves to share that point");
        }
    }

    std::array<Vec2, kSpinePointCount> spine(const Affine2& toFrame) const {
        const bool hasNeck = annotations_[kNeck].element != nullptr;
        const bool hasTail = annotations_[kTail].element != nullptr;
        std::array<Vec2, 4> back = curve(kBack, toFrame);
        std::array<Vec2, 4> neck{}, tail{};
        if (hasNeck) neck = curve(kNeck, toFrame);
        if (hasTail) tail = curve(kTail, toFrame);
        // Orient the back from shoulder to hip: by which end the neck (else tail) touches, or
        // with the head towards −x when there is neither.
        const auto nearest = [](const Vec2& p, const std::array<Vec2, 4>& c) {
            return std::min((p - c[0]).norm(), (p - c[3]).norm());
        };
        bool flip = back[0].x() > back[3].x();
        if (hasNeck)
            flip = nearest(back[3], neck) < nearest(back[0], neck);
        else if (hasTail)
            flip = nearest(back[0], tail) < nearest(back[3], tail);
        if (flip) back = reversed(back);
        std::array<Vec2, kSpinePointCount> p;
        p[3] = back[0];
        p[4] = back[1];
        p[5] = back[2];
        p[6] = back[3];
        if (hasNeck) {
            if ((neck[0] - p[3]).norm() < (neck[3] - p[3]).norm()) neck = reversed(neck);
            checkJoint(kNeck, neck[3], p[3], "shoulder");
            p[0] = neck[0], p[1] = neck[1], p[2] = neck[2];
        } else {
            p[0] = p[1] = p[2] = p[3];
        }
        if (hasTail) {
            if ((tail[3] - p[6]).norm() < (tail[0] - p[6]).norm()) tail = reversed(tail);
            checkJoint(kTail, tail[0], p[6], "hip");
            p[7] = tail[1], p[8] = tail[2], p[9] = tail[3];
        } else {
            p[7] = p[8] = p[9] = p[6];
        }
        return p;
    }

    // Sum of the segments' chords. Measured in the path's own coordinates and scaled when the
    // mapping is a similarity (so lengths survive a round trip exactly), else after mapping.
    double limbLength(const Annotation& a, const Affine2& toFrame) const {
        if (!a.element) return 0.0;
        const Affine2 m = toFrame * a.ctm;
        const double scale = m.similarityScale();
        double total = 0.0;
        for (const PathSegment& s : a.segments) {
            const Vec2 chord = scale > 0 ? (s.p3 - s.p0) : (m.apply(s.p3) - m.apply(s.p0));
            total += std::hypot(chord.x(), chord.y());
        }
        return scale > 0 ? total * scale : total;
    }

    void fillFields(SpeciesRecord& r, const XmlElement& root) const {
        const auto text = [&](const char* key) -> std::optional<std::string> {
            const std::string* v = root.attribute(key);
            return v ? std::optional<std::string>(*v) : std::nullopt;
        };
        const auto number = [&](const char* key, const std::optional<double>& given,
                                const char* option) {
            if (given) return *given;
            const std::string* v = root.attribute(key);
            if (!v) {
                throw Error(SourceLoc{file_, 0, 0}, std::string("missing ") + option +
                                                        ": the SVG has no " + key +
                                                        " attribute; give it as an option");
            }
            std::size_t pos = 0;
            const auto parsed = detail::parseNumber(*v, pos);
            if (!parsed || pos != v->size() || *parsed < 0) {
                fail(root, std::string("bad ") + key + " \"" + *v + "\"; expected a number >= 0");
            }
            return *parsed;
        };
        r.name = options_.name.value_or(text("ramus:name").value_or(""));
        if (r.name.empty()) {
            throw Error(SourceLoc{file_, 0, 0},
                        "missing name: the SVG has no ramus:name attribute; give it as an option");
        }
        r.nameDe = options_.nameDe.value_or(text("ramus:name-de").value_or(""));
        if (options_.animalClass) {
            r.animalClass = *options_.animalClass;
        } else {
            const auto cls = text("ramus:class");
            if (!cls) {
                throw Error(SourceLoc{file_, 0, 0},
                            "missing class: the SVG has no ramus:class attribute; give it as an "
                            "option (fish, amphibian, reptile, bird, mammal)");
            }
            const auto parsed = parseAnimalClass(*cls);
            if (!parsed)
                fail(root, "bad ramus:class \"" + *cls +
                               "\"; expected fish, amphibian, reptile, bird or mammal");
            r.animalClass = *parsed;
        }
        r.features.wings = number("ramus:wings", options_.wings, "wings");
        r.features.legs = number("ramus:legs", options_.legs, "legs");
        r.features.weightKg = number("ramus:weight-kg", options_.weightKg, "weight");
        r.weightSource = text("ramus:weight-source").value_or("");
        r.notes = text("ramus:notes").value_or("");
    }

    const std::string& file_;
    const SvgImportOptions& options_;
    XmlDocument doc_;
    std::array<Annotation, kSlotCount> annotations_{};
    Aabb imageBox_;
};

}  // namespace

SpeciesRecord importSpeciesSvg(std::string_view svgText, const std::string& fileName,
                               const SvgImportOptions& options) {
    return SvgImporter(svgText, fileName, options).run();
}

}  // namespace ramus
