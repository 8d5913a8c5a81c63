// Writes a species record as an annotated side view that importSpeciesSvg reads back to the
// identical record, and that Inkscape opens for editing (layer "annotation", y-up group).
// Based on: seed 000 §7.4.1 (the annotation scheme).
#include <string>

#include "ramus/species.hpp"
#include "skeleton/number_text.hpp"
#include "skeleton/svg_xml.hpp"

namespace ramus {

namespace {

using detail::appendShortest;
using detail::escapeXml;

// Colours as in the thesis's figures: one per spine part, limbs in the part's tone.
constexpr const char* kNeckColour = "#d62728";
constexpr const char* kBackColour = "#1f77b4";
constexpr const char* kTailColour = "#2ca02c";
constexpr const char* kFrontColour = "#9467bd";
constexpr const char* kHindColour = "#ff7f0e";

void appendPoint(std::string& out, const Vec2& p) {
    appendShortest(out, p.x());
    out += ' ';
    appendShortest(out, p.y());
}

void appendCurve(std::string& out, const char* name, const std::array<Vec2, 10>& spine, int first,
                 const char* colour) {
    out += "    <path id=\"";
    out += name;
    out += "\" inkscape:label=\"";
    out += name;
    out += "\" fill=\"none\" stroke=\"";
    out += colour;
    out += "\" stroke-width=\"6\" d=\"M ";
    appendPoint(out, spine[first]);
    out += " C ";
    appendPoint(out, spine[first + 1]);
    out += ' ';
    appendPoint(out, spine[first + 2]);
    out += ' ';
    appendPoint(out, spine[first + 3]);
    out += "\"/>\n";
}

// A limb chain hanging straight down from `start`; each bone is drawn from its own origin so
// the imported length equals the stored one bit for bit.
void appendLimbChain(std::string& out, const SkeletonFeatures& f, int firstLimb, Vec2 start,
                     const char* colour) {
    for (int i = firstLimb; i < firstLimb + 3; ++i) {
        const double length = f.limbs[i];
        if (length <= 0) continue;
        const std::string name(limbName(static_cast<Limb>(i)));
        out += "    <path id=\"" + name + "\" inkscape:label=\"" + name +
               "\" fill=\"none\" stroke=\"" + colour +
               "\" stroke-width=\"4\" stroke-linecap=\"round\" transform=\"translate(";
        appendPoint(out, start);
        out += ")\" d=\"M 0 0 L 0 ";
        appendShortest(out, -length);
        out += "\"/>\n";
        start.y() -= length;
    }
}

void appendAttribute(std::string& out, const char* key, const std::string& value) {
    if (value.empty()) return;
    out += "\n     ";
    out += key;
    out += "=\"" + escapeXml(value) + "\"";
}

}  // namespace

std::string exportSpeciesSvg(const SpeciesRecord& record) {
    const SkeletonFeatures& f = record.features;
    std::string out =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!-- ramus species annotation (docs/species-format.md): spine curves neck, back, tail\n"
        "     and limb bones in layer \"annotation\"; coordinates in the 1000x1000 frame, y up. "
        "-->\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\"\n"
        "     xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"\n"
        "     xmlns:ramus=\"urn:ramus:species:1\"\n"
        "     width=\"1000\" height=\"1000\" viewBox=\"0 0 1000 1000\"";
    appendAttribute(out, "ramus:name", record.name);
    appendAttribute(out, "ramus:name-de", record.nameDe);
    appendAttribute(out, "ramus:class", std::string(animalClassName(record.animalClass)));
    appendAttribute(out, "ramus:wings", detail::shortest(f.wings));
    appendAttribute(out, "ramus:legs", detail::shortest(f.legs));
    appendAttribute(out, "ramus:weight-kg", detail::shortest(f.weightKg));
    appendAttribute(out, "ramus:weight-source", record.weightSource);
    appendAttribute(out, "ramus:notes", record.notes);
    out += ">\n  <title>" + escapeXml(record.name) + "</title>\n";
    out += "  <rect width=\"1000\" height=\"1000\" fill=\"#ffffff\" stroke=\"#cccccc\"/>\n";
    out +=
        "  <g id=\"annotation\" inkscape:groupmode=\"layer\" inkscape:label=\"annotation\" "
        "transform=\"matrix(1 0 0 -1 0 1000)\">\n";
    // A missing neck or tail is written as a curve collapsed onto the shoulder or hip: it
    // reads back the same and keeps the back's direction unambiguous.
    appendCurve(out, "neck", f.spine, 0, kNeckColour);
    appendCurve(out, "back", f.spine, 3, kBackColour);
    appendCurve(out, "tail", f.spine, 6, kTailColour);
    appendLimbChain(out, f, 0, f.spine[3], kFrontColour);
    appendLimbChain(out, f, 3, f.spine[6], kHindColour);
    out += "  </g>\n</svg>\n";
    return out;
}

}  // namespace ramus
