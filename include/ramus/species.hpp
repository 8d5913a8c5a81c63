// Species data for the skeleton statistics: one record per measured animal (seed 000 §4.2,
// appendix A.1), the species file format (docs/species-format.md), and the annotated-SVG import
// and export of a record (seed 000 §7.4.1).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/math.hpp"

namespace ramus {

/// Vertebrate class of a species. Recorded, but not a PCA dimension (seed 000 §4.2).
enum class AnimalClass { Fish, Amphibian, Reptile, Bird, Mammal };

/// "fish", "amphibian", "reptile", "bird" or "mammal".
std::string_view animalClassName(AnimalClass animalClass);
/// Inverse of animalClassName (exact, lower case); nullopt for anything else.
std::optional<AnimalClass> parseAnimalClass(std::string_view name);

/// The six limb bones whose lengths are measured (front limb, then hind limb).
enum class Limb { UpperArm, Forearm, Hand, Thigh, Shank, Foot };
inline constexpr int kLimbCount = 6;
/// "upper_arm", "forearm", "hand", "thigh", "shank", "foot".
std::string_view limbName(Limb limb);

/// Number of spine control points: three cubic Béziers (neck P0..P3, back P3..P6, tail P6..P9)
/// sharing the shoulder point P3 and the hip point P6.
inline constexpr int kSpinePointCount = 10;

/// The measured (or generated) features of one skeleton, in the thesis's annotation frame:
/// 1000×1000 px, y up, the head towards −x, the animal standing on the bottom edge.
struct SkeletonFeatures {
    /// Spine control points in px. A missing neck repeats P3 as P0..P2, a missing tail repeats
    /// P6 as P7..P9.
    std::array<Vec2, kSpinePointCount> spine{};
    /// Wing pairs. 0 or 1 in the data; generated values read as a probability (seed 000 §4.2).
    double wings = 0.0;
    /// Pairs of legs with ground contact. 0, 1 or 2 in the data; generated values in [0, 1]
    /// read as the probability of a hind pair, in [1, 2] of a front pair as well.
    double legs = 0.0;
    /// Limb bone lengths in px, indexed by Limb; 0 = the bone is absent.
    std::array<double, kLimbCount> limbs{};
    /// Body weight in kg (≥ 0).
    double weightKg = 0.0;

    double limb(Limb which) const { return limbs[static_cast<int>(which)]; }
    /// Neck y length in px: P0.y − P3.y (head above shoulder), conditionable (seed 000 §4.5).
    double neckYLength() const { return spine[0].y() - spine[3].y(); }
    /// Tail x length in px: P9.x − P6.x (hip to tail tip), conditionable (seed 000 §4.5).
    double tailXLength() const { return spine[9].x() - spine[6].x(); }

    bool operator==(const SkeletonFeatures&) const = default;
};

/// One species of the data set.
struct SpeciesRecord {
    std::string name;    ///< English name; unique (case-insensitively) within a species file
    std::string nameDe;  ///< German name as in the thesis; may be empty
    AnimalClass animalClass = AnimalClass::Mammal;
    SkeletonFeatures features;
    std::string weightSource;  ///< the weight as the source gives it ("23-44 t"); may be empty
    std::string notes;         ///< free text; may be empty

    bool operator==(const SpeciesRecord&) const = default;
};

/// The 44 species measured by the thesis (data/species/species.json, compiled in), in the
/// file's order.
const std::vector<SpeciesRecord>& builtinSpecies();

/// The text of the built-in species file (identical to data/species/species.json).
std::string_view builtinSpeciesJson();

/// Parses a species file (docs/species-format.md). `fileName` is used in error messages.
/// Throws Error naming the file, the record (index and name) and the field for every problem:
/// malformed JSON (with line and column), wrong format/version, missing or unknown fields,
/// wrong types, non-finite or negative values, wrong point counts, duplicate names.
/// An empty "species" array is valid and gives an empty vector.
std::vector<SpeciesRecord> parseSpeciesJson(std::string_view text, const std::string& fileName);

/// readFile + parseSpeciesJson.
std::vector<SpeciesRecord> loadSpeciesFile(const std::string& path);

/// Writes records in the species file format (stable field order; numbers in the shortest
/// form that reads back to the same double, so parse(write(x)) == x). `attribution` is stored
/// in the header (empty: left out).
std::string writeSpeciesJson(const std::vector<SpeciesRecord>& species,
                             const std::string& attribution = {});

/// Finds a species by English or German name, case-insensitively; nullptr when absent.
const SpeciesRecord* findSpecies(const std::vector<SpeciesRecord>& species, std::string_view name);

/// How an annotated SVG's coordinates are mapped into the 1000×1000 y-up frame.
enum class SvgFit {
    /// The document's frame (viewBox, else width/height) is scaled without distortion to fit
    /// 1000×1000, moved to the bottom edge and centred horizontally (seed 000 §7.4.1 steps 2–4,
    /// for a picture that was not yet placed). A 1000×1000 document maps onto itself.
    Frame,
    /// Like Frame, but for the bounding box of the document's <image> elements, or when there is
    /// none, of the annotations (steps 1–4: crop, scale, move).
    Content,
    /// No scaling: only the y axis is flipped against the bottom of the document's frame.
    None,
};

/// Options for importSpeciesSvg. The optional fields override what the SVG itself carries
/// (ramus:* attributes on the root element, written by exportSpeciesSvg); every field must come
/// from one of the two.
struct SvgImportOptions {
    SvgFit fit = SvgFit::Frame;
    /// false (default): SVG coordinates, y pointing down (what Inkscape writes to the file,
    /// whatever its on-screen ruler shows). true: the path coordinates are already y-up.
    bool yUp = false;
    std::optional<std::string> name;
    std::optional<std::string> nameDe;
    std::optional<AnimalClass> animalClass;
    std::optional<double> wings;
    std::optional<double> legs;
    std::optional<double> weightKg;
};

/// Reads an annotated side view (seed 000 §7.4.1): <path> elements named (inkscape:label, else
/// id) neck, back, tail (one cubic Bézier each; a straight line or quadratic is converted
/// exactly) and upper_arm, forearm, hand, thigh, shank, foot (length = sum of the segment
/// chords). Absolute and relative path commands, nested <g> transforms (matrix, translate,
/// scale, rotate, skewX, skewY) and the root viewBox are applied. "back" is required; a missing
/// neck or tail repeats the back's first or last point; a missing limb has length 0. Throws
/// Error with the file name for malformed XML, bad path data, a curve with more than one
/// segment, duplicate names, or a missing field.
SpeciesRecord importSpeciesSvg(std::string_view svgText, const std::string& fileName,
                               const SvgImportOptions& options = {});

/// Writes a record as a 1000×1000 annotated SVG that importSpeciesSvg reads back to an identical
/// record (spine as three named cubic paths, limbs as named vertical segments, the other fields
/// as ramus:* attributes).
std::string exportSpeciesSvg(const SpeciesRecord& record);

}  // namespace ramus
