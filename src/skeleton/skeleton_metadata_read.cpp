// Reading skeleton metadata files (docs/skeleton.md "Metadata format"): strict validation of the
// design, with errors that name the file and the field.
//
// Based on: seed 000 §6.2 (load a saved skeleton and regenerate it) and the grammar's parameter
// constraints (seed 000 §5.3, §5.4, §5.5.3; SPEC §F), which a loaded design must satisfy.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "core/json_text.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"
#include "skeleton/number_text.hpp"

namespace ramus {

namespace {

using Json = nlohmann::json;

/// Largest vertebra count per spine region a file may ask for (a sanity limit: the thesis's
/// animals have at most 30 neck, 25 back and 20 tail vertebrae).
constexpr std::int64_t kMaxVertebrae = 1000;

// Reads typed values and reports problems as "FILE: field 'a.b': message".
class Reader {
public:
    explicit Reader(const std::string& fileName) : fileName_(fileName) {}

    [[noreturn]] void fail(const std::string& field, const std::string& message) const {
        throw Error(SourceLoc{fileName_, 0, 0}, "field '" + field + "': " + message);
    }

    // `object` must be a JSON object with only the `known` keys.
    void object(const Json& value, const std::string& field,
                std::initializer_list<std::string_view> known) const {
        if (!value.is_object())
            fail(field, "expected an object; got " + detail::describeJson(value));
        for (const auto& item : value.items()) {
            if (std::find(known.begin(), known.end(), item.key()) == known.end()) {
                fail(join(field, item.key()), "unknown field");
            }
        }
    }

    const Json& member(const Json& object, const std::string& field, const char* key) const {
        const auto it = object.find(key);
        if (it == object.end()) fail(join(field, key), "missing");
        return *it;
    }

    double number(const Json& value, const std::string& field) const {
        if (!value.is_number())
            fail(field, "expected a number; got " + detail::describeJson(value));
        const double v = value.get<double>();
        if (!std::isfinite(v))
            fail(field, "expected a finite number; got " + detail::describeJson(value));
        return v;
    }

    double numberIn(const Json& value, const std::string& field, double lo, double hi) const {
        const double v = number(value, field);
        if (v < lo || v > hi) {
            fail(field, "expected a number in [" + detail::shortest(lo) + ", " +
                            detail::shortest(hi) + "]; got " + detail::describeJson(value));
        }
        return v;
    }

    int count(const Json& value, const std::string& field, std::int64_t lo, std::int64_t hi) const {
        if (!value.is_number_integer())
            fail(field, "expected an integer; got " + detail::describeJson(value));
        const std::int64_t v =
            value.is_number_unsigned()
                ? static_cast<std::int64_t>(std::min<std::uint64_t>(
                      value.get<std::uint64_t>(), static_cast<std::uint64_t>(kMaxVertebrae) + 1))
                : value.get<std::int64_t>();
        if (v < lo || v > hi) {
            fail(field, "expected an integer in [" + std::to_string(lo) + ", " +
                            std::to_string(hi) + "]; got " + detail::describeJson(value));
        }
        return static_cast<int>(v);
    }

    std::string string(const Json& value, const std::string& field) const {
        if (!value.is_string())
            fail(field, "expected a string; got " + detail::describeJson(value));
        return value.get<std::string>();
    }

    // A decimal string of an unsigned 64-bit integer, or a non-negative JSON integer.
    std::uint64_t unsignedInteger(const Json& value, const std::string& field) const {
        if (value.is_number_unsigned()) return value.get<std::uint64_t>();
        const std::string expected =
            "expected an integer in [0, 18446744073709551615] or its "
            "decimal string; got " +
            detail::describeJson(value);
        if (!value.is_string()) fail(field, expected);
        const std::string& s = value.get_ref<const std::string&>();
        std::uint64_t v = 0;
        const auto result = std::from_chars(s.data(), s.data() + s.size(), v);
        const bool digitsOnly = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
            return c >= '0' && c <= '9';
        });
        if (!digitsOnly || result.ec != std::errc() || result.ptr != s.data() + s.size()) {
            fail(field, expected);
        }
        return v;
    }

    template <typename Enum, typename Parse>
    Enum choice(const Json& value, const std::string& field, Parse parse,
                const std::string& names) const {
        const std::string s = value.is_string() ? value.get<std::string>() : std::string();
        const std::optional<Enum> parsed = parse(s);
        if (!value.is_string() || !parsed) {
            fail(field, "expected one of " + names + "; got " + detail::describeJson(value));
        }
        return *parsed;
    }

    static std::string join(const std::string& field, std::string_view key) {
        return field.empty() ? std::string(key) : field + "." + std::string(key);
    }

private:
    const std::string& fileName_;
};

template <typename Enum, int N, typename NameOf>
std::string nameList(NameOf nameOf) {
    std::string names;
    for (int i = 0; i < N; ++i) {
        if (i > 0) names += ", ";
        names += nameOf(static_cast<Enum>(i));
    }
    return names;
}

void readFeaturePoint(const Reader& r, const Json& value, SkeletonDesign& design) {
    const std::string field = "design.feature_point";
    if (!value.is_array() || value.size() != static_cast<std::size_t>(kFeatureCount)) {
        r.fail(field, "expected an array of " + std::to_string(kFeatureCount) + " numbers; got " +
                          detail::describeJson(value));
    }
    design.featurePoint.resize(kFeatureCount);
    for (int i = 0; i < kFeatureCount; ++i) {
        design.featurePoint[i] = r.number(value[i], field + "[" + std::to_string(i) + "]");
    }
}

void readVertebrae(const Reader& r, const Json& value, SkeletonDesign& design) {
    const std::string field = "design.vertebrae";
    r.object(value, field, {"neck", "back_front", "back_rear", "tail"});
    design.neckVertebrae =
        r.count(r.member(value, field, "neck"), field + ".neck", 0, kMaxVertebrae);
    if (design.neckVertebrae > 0 && design.neckVertebrae < 7) {
        r.fail(field + ".neck",
               "expected 0 (no neck) or at least 7; got " + std::to_string(design.neckVertebrae));
    }
    design.frontBackVertebrae =
        r.count(r.member(value, field, "back_front"), field + ".back_front", 3, kMaxVertebrae);
    design.rearBackVertebrae =
        r.count(r.member(value, field, "back_rear"), field + ".back_rear", 1, kMaxVertebrae);
    design.tailVertebrae =
        r.count(r.member(value, field, "tail"), field + ".tail", 0, kMaxVertebrae);
}

// Limb kinds per attachment; a missing attachment has no limb.
void readLimbs(const Reader& r, const Json& value, SkeletonDesign& design) {
    const std::string field = "design.limbs";
    r.object(value, field, {"hip", "shoulder", "hip2", "shoulder2", "neck", "neck2"});
    const std::string kinds = nameList<LimbKind, 5>(limbKindName);
    design.limbs.fill(LimbKind::None);
    for (const auto& item : value.items()) {
        const Attachment a = *parseAttachment(item.key());
        const std::string f = field + "." + item.key();
        const LimbKind kind = r.choice<LimbKind>(item.value(), f, parseLimbKind, kinds);
        if (!attachmentAccepts(a, kind)) {
            r.fail(f, "a " + std::string(limbKindName(kind)) + " cannot attach at the " +
                          item.key() + " (seed 000 §5.5.3)");
        }
        design.limbs[static_cast<int>(a)] = kind;
    }
    const auto needs = [&](Attachment second, Attachment first) {
        if (design.limb(second) != LimbKind::None && design.limb(first) == LimbKind::None) {
            r.fail(field + "." + std::string(attachmentName(second)),
                   "needs a limb at " + std::string(attachmentName(first)) + "; it has none");
        }
    };
    needs(Attachment::Hip2, Attachment::Hip);
    needs(Attachment::Shoulder2, Attachment::Shoulder);
    needs(Attachment::Neck2, Attachment::Neck);
    if (design.limb(Attachment::Neck) != LimbKind::None && design.neckVertebrae == 0) {
        r.fail(field + ".neck",
               "a limb on the neck needs neck vertebrae; design.vertebrae.neck "
               "is 0");
    }
}

WingAngles readWing(const Reader& r, const Json& value, const std::string& field) {
    r.object(value, field, {"shoulder_front", "shoulder_side", "elbow", "wrist"});
    WingAngles w;
    w.shoulderFront =
        r.numberIn(r.member(value, field, "shoulder_front"), field + ".shoulder_front", 130, 170);
    w.shoulderSide =
        r.numberIn(r.member(value, field, "shoulder_side"), field + ".shoulder_side", 0, 45);
    w.elbow = r.numberIn(r.member(value, field, "elbow"), field + ".elbow", -45, 0);
    w.wrist = r.numberIn(r.member(value, field, "wrist"), field + ".wrist", 0, 90);
    return w;
}

// Angles for exactly the attachments that carry a wing (read after the limbs).
void readWingAngles(const Reader& r, const Json& value, SkeletonDesign& design) {
    const std::string field = "design.wing_angles";
    r.object(value, field, {"hip", "shoulder", "hip2", "shoulder2", "neck", "neck2"});
    for (int a = 0; a < kAttachmentCount; ++a) {
        const std::string key(attachmentName(static_cast<Attachment>(a)));
        const bool wing = design.limbs[a] == LimbKind::Wing;
        if (value.contains(key) && !wing) {
            r.fail(field + "." + key, "design.limbs." + key + " is not a wing");
        }
        if (!wing) continue;
        if (!value.contains(key)) r.fail(field + "." + key, "missing (the attachment has a wing)");
        design.wingAngles[a] = readWing(r, value[key], field + "." + key);
    }
}

void readCountsAndLimbs(const Reader& r, const Json& d, SkeletonDesign& design) {
    readFeaturePoint(r, r.member(d, "design", "feature_point"), design);
    readVertebrae(r, r.member(d, "design", "vertebrae"), design);
    const int back = design.frontBackVertebrae + design.rearBackVertebrae;
    design.ribs = r.count(r.member(d, "design", "ribs"), "design.ribs", 0, back);
    readLimbs(r, r.member(d, "design", "limbs"), design);
    readWingAngles(r, r.member(d, "design", "wing_angles"), design);
}

SkeletonDesign readDesign(const Reader& r, const Json& d) {
    r.object(d, "design",
             {"feature_point", "features", "vertebrae", "ribs", "limbs", "wing_angles", "heel_draw",
              "head_kind", "spacing", "grammar_seed", "metres_per_pixel"});
    SkeletonDesign design;
    readCountsAndLimbs(r, d, design);
    const Json& heel = r.member(d, "design", "heel_draw");
    design.heelDraw = r.number(heel, "design.heel_draw");
    if (design.heelDraw < 0.0 || design.heelDraw >= 1.0) {
        r.fail("design.heel_draw",
               "expected a number in [0, 1); got " + detail::describeJson(heel));
    }
    design.headKind = r.string(r.member(d, "design", "head_kind"), "design.head_kind");
    design.spacing = r.choice<SpineSpacing>(r.member(d, "design", "spacing"), "design.spacing",
                                            parseSpineSpacing, "arc_length, parameter");
    design.grammarSeed =
        r.unsignedInteger(r.member(d, "design", "grammar_seed"), "design.grammar_seed");
    const Json& scale = r.member(d, "design", "metres_per_pixel");
    design.metresPerPixel = r.number(scale, "design.metres_per_pixel");
    if (design.metresPerPixel <= 0.0) {
        r.fail("design.metres_per_pixel",
               "expected a number > 0; got " + detail::describeJson(scale));
    }
    return design;
}

void checkHeader(const Reader& r, const Json& root) {
    const Json& format = r.member(root, "", "format");
    if (!format.is_string() || format.get<std::string>() != "ramus-skeleton") {
        r.fail("format", "expected \"ramus-skeleton\"; got " + detail::describeJson(format));
    }
    const Json& version = r.member(root, "", "version");
    if (!version.is_number_integer() || version.get<std::int64_t>() != kSkeletonMetadataVersion) {
        r.fail("version", "unsupported version " + detail::describeJson(version) +
                              "; this ramus reads version " +
                              std::to_string(kSkeletonMetadataVersion));
    }
}

}  // namespace

LoadedSkeleton parseSkeletonMetadata(std::string_view text, const std::string& fileName) {
    Json root;
    try {
        root = detail::parseJsonText(text, fileName);
    } catch (const Json::exception& e) {
        // Number overflow ("1e999") is reported as out_of_range, without an offset.
        std::string what = e.what();
        const std::size_t bracket = what.find("] ");
        if (bracket != std::string::npos) what = what.substr(bracket + 2);
        throw Error(SourceLoc{fileName, 0, 0}, "invalid JSON: " + what);
    }
    const Reader r(fileName);
    if (!root.is_object())
        r.fail("(top level)", "expected an object; got " + detail::describeJson(root));
    checkHeader(r, root);
    r.object(root, "", {"format", "version", "name", "seed", "design", "skeleton"});
    LoadedSkeleton loaded;
    loaded.name = r.string(r.member(root, "", "name"), "name");
    loaded.seed = r.unsignedInteger(r.member(root, "", "seed"), "seed");
    loaded.design = readDesign(r, r.member(root, "", "design"));
    return loaded;
}

LoadedSkeleton readSkeletonMetadata(const std::string& path) {
    return parseSkeletonMetadata(readFile(path), path);
}

}  // namespace ramus
