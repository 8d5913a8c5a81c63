// The species file format (docs/species-format.md): strict validation with errors that name the
// file, the record and the field; a writer whose output reads back to identical records.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "core/json_text.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/species.hpp"
#include "skeleton/number_text.hpp"

namespace ramus {

namespace {

using Json = nlohmann::json;

constexpr std::string_view kFormat = "ramus-species";
constexpr int kVersion = 1;

// Reports problems inside one record: "species[3] (Dromedary): field: message".
class RecordContext {
public:
    RecordContext(const std::string& fileName, std::string where)
        : fileName_(fileName), where_(std::move(where)) {}

    [[noreturn]] void fail(const std::string& field, const std::string& message) const {
        throw Error(SourceLoc{fileName_, 0, 0},
                    where_ + (field.empty() ? "" : ": " + field) + ": " + message);
    }

    void setName(const std::string& name) { where_ += " (" + name + ")"; }

    double number(const Json& value, const std::string& field, double minimum) const {
        if (!value.is_number())
            fail(field, "expected a number, got " + detail::describeJson(value));
        const double v = value.get<double>();
        if (!std::isfinite(v))
            fail(field, "expected a finite number, got " + detail::describeJson(value));
        if (v < minimum) {
            fail(field, "expected a number >= " + detail::shortest(minimum) + ", got " +
                            detail::describeJson(value));
        }
        return v;
    }

    std::string string(const Json& value, const std::string& field, bool allowEmpty) const {
        if (!value.is_string())
            fail(field, "expected a string, got " + detail::describeJson(value));
        std::string s = value.get<std::string>();
        if (!allowEmpty && s.empty()) fail(field, "expected a non-empty string, got \"\"");
        return s;
    }

private:
    const std::string& fileName_;
    std::string where_;
};

const Json& require(const Json& object, const char* key, const RecordContext& ctx) {
    const auto it = object.find(key);
    if (it == object.end()) ctx.fail(key, "missing field");
    return *it;
}

void rejectUnknownFields(const Json& object, std::initializer_list<std::string_view> known,
                         const RecordContext& ctx, const std::string& prefix = {}) {
    for (const auto& item : object.items()) {
        if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
        std::string list;
        for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        ctx.fail(prefix + item.key(), "unknown field; expected one of " + list);
    }
}

std::array<Vec2, kSpinePointCount> parseSpine(const Json& value, const RecordContext& ctx) {
    if (!value.is_array() || value.size() != kSpinePointCount) {
        ctx.fail("spine",
                 "expected an array of 10 [x, y] points, got " + detail::describeJson(value));
    }
    std::array<Vec2, kSpinePointCount> spine;
    for (int i = 0; i < kSpinePointCount; ++i) {
        const Json& p = value[i];
        const std::string field = "spine[" + std::to_string(i) + "]";
        if (!p.is_array() || p.size() != 2) {
            ctx.fail(field, "expected [x, y] with two numbers, got " + detail::describeJson(p));
        }
        spine[i] =
            Vec2(ctx.number(p[0], field + ".x", -1e300), ctx.number(p[1], field + ".y", -1e300));
    }
    return spine;
}

std::array<double, kLimbCount> parseLimbs(const Json& value, const RecordContext& ctx) {
    if (!value.is_object())
        ctx.fail("limbs", "expected an object, got " + detail::describeJson(value));
    std::array<double, kLimbCount> limbs{};
    rejectUnknownFields(value, {"upper_arm", "forearm", "hand", "thigh", "shank", "foot"}, ctx,
                        "limbs.");
    for (int i = 0; i < kLimbCount; ++i) {
        const std::string key(limbName(static_cast<Limb>(i)));
        const auto it = value.find(key);
        if (it == value.end()) ctx.fail("limbs." + key, "missing field (0 = bone absent)");
        limbs[i] = ctx.number(*it, "limbs." + key, 0.0);
    }
    return limbs;
}

SpeciesRecord parseRecord(const Json& value, RecordContext ctx) {
    if (!value.is_object()) ctx.fail("", "expected an object, got " + detail::describeJson(value));
    SpeciesRecord r;
    r.name = ctx.string(require(value, "name", ctx), "name", false);
    ctx.setName(r.name);
    rejectUnknownFields(value,
                        {"name", "name_de", "class", "wings", "legs", "weight_kg", "spine", "limbs",
                         "weight_source", "notes"},
                        ctx);
    if (value.contains("name_de")) r.nameDe = ctx.string(value["name_de"], "name_de", true);
    const std::string cls = ctx.string(require(value, "class", ctx), "class", false);
    const auto parsedClass = parseAnimalClass(cls);
    if (!parsedClass) {
        ctx.fail("class", "expected fish, amphibian, reptile, bird or mammal, got \"" + cls + "\"");
    }
    r.animalClass = *parsedClass;
    r.features.wings = ctx.number(require(value, "wings", ctx), "wings", 0.0);
    r.features.legs = ctx.number(require(value, "legs", ctx), "legs", 0.0);
    r.features.weightKg = ctx.number(require(value, "weight_kg", ctx), "weight_kg", 0.0);
    r.features.spine = parseSpine(require(value, "spine", ctx), ctx);
    r.features.limbs = parseLimbs(require(value, "limbs", ctx), ctx);
    if (value.contains("weight_source")) {
        r.weightSource = ctx.string(value["weight_source"], "weight_source", true);
    }
    if (value.contains("notes")) r.notes = ctx.string(value["notes"], "notes", true);
    return r;
}

void checkHeader(const Json& root, const RecordContext& ctx) {
    rejectUnknownFields(root, {"format", "version", "attribution", "frame", "species"}, ctx);
    const Json& format = require(root, "format", ctx);
    if (!format.is_string() || format.get<std::string>() != kFormat) {
        ctx.fail("format", "expected \"ramus-species\", got " + detail::describeJson(format));
    }
    const Json& version = require(root, "version", ctx);
    if (!version.is_number_integer() || version.get<long long>() != kVersion) {
        ctx.fail("version", "expected 1 (the only version this ramus reads), got " +
                                detail::describeJson(version));
    }
    if (root.contains("attribution")) ctx.string(root["attribution"], "attribution", true);
    if (root.contains("frame")) {
        const Json expected =
            Json::parse(R"({"width":1000,"height":1000,"y_axis":"up","head":"-x"})");
        if (root["frame"] != expected) {
            ctx.fail("frame",
                     "expected {\"width\": 1000, \"height\": 1000, \"y_axis\": \"up\", "
                     "\"head\": \"-x\"} (the only frame supported), got " +
                         detail::describeJson(root["frame"]));
        }
    }
}

std::string lowerAscii(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

std::vector<SpeciesRecord> parseSpeciesJson(std::string_view text, const std::string& fileName) {
    Json root;
    try {
        root = detail::parseJsonText(text, fileName);
    } catch (const Json::exception& e) {
        throw Error(SourceLoc{fileName, 0, 0}, std::string("invalid JSON: ") + e.what());
    }
    const RecordContext top(fileName, "species file");
    if (!root.is_object())
        top.fail("", "expected a JSON object, got " + detail::describeJson(root));
    checkHeader(root, top);
    const Json& list = require(root, "species", top);
    if (!list.is_array())
        top.fail("species", "expected an array, got " + detail::describeJson(list));

    std::vector<SpeciesRecord> species;
    std::set<std::string> seen;
    species.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        RecordContext ctx(fileName, "species[" + std::to_string(i) + "]");
        SpeciesRecord record = parseRecord(list[i], ctx);
        // A record may use the same name in both languages; other records may not reuse it.
        std::map<std::string, std::string> own{{lowerAscii(record.name), record.name}};
        if (!record.nameDe.empty()) own.emplace(lowerAscii(record.nameDe), record.nameDe);
        for (const auto& [key, name] : own) {
            if (!seen.insert(key).second) {
                ctx.setName(record.name);
                ctx.fail("name", "duplicate species name \"" + name +
                                     "\" (names are compared case-insensitively)");
            }
        }
        species.push_back(std::move(record));
    }
    return species;
}

std::vector<SpeciesRecord> loadSpeciesFile(const std::string& path) {
    return parseSpeciesJson(readFile(path), path);
}

namespace {

std::string quoted(const std::string& s) {
    return Json(s).dump(-1, ' ', false, Json::error_handler_t::replace);
}

void appendRecord(std::string& out, const SpeciesRecord& r) {
    using detail::appendShortest;
    const SkeletonFeatures& f = r.features;
    out += "    {\n      \"name\": " + quoted(r.name) + ", \"name_de\": " + quoted(r.nameDe) +
           ", \"class\": " + quoted(std::string(animalClassName(r.animalClass))) + ",\n";
    out += "      \"wings\": ";
    appendShortest(out, f.wings);
    out += ", \"legs\": ";
    appendShortest(out, f.legs);
    out += ", \"weight_kg\": ";
    appendShortest(out, f.weightKg);
    out += ", \"weight_source\": " + quoted(r.weightSource) + ",\n      \"spine\": [\n";
    for (int i = 0; i < kSpinePointCount; ++i) {
        out += (i % 2 == 0) ? "        [" : ", [";
        appendShortest(out, f.spine[i].x());
        out += ", ";
        appendShortest(out, f.spine[i].y());
        out += ']';
        if (i % 2 == 1) out += (i + 1 < kSpinePointCount) ? ",\n" : "\n";
    }
    out += "      ],\n      \"limbs\": {";
    for (int i = 0; i < kLimbCount; ++i) {
        if (i == 3)
            out += ",\n                ";
        else if (i > 0)
            out += ", ";
        out += '"' + std::string(limbName(static_cast<Limb>(i))) + "\": ";
        appendShortest(out, f.limbs[i]);
    }
    out += '}';
    if (!r.notes.empty()) out += ",\n      \"notes\": " + quoted(r.notes);
    out += "\n    }";
}

}  // namespace

std::string writeSpeciesJson(const std::vector<SpeciesRecord>& species,
                             const std::string& attribution) {
    std::string out = "{\n  \"format\": \"ramus-species\",\n  \"version\": 1,\n";
    if (!attribution.empty()) out += "  \"attribution\": " + quoted(attribution) + ",\n";
    out +=
        "  \"frame\": {\"width\": 1000, \"height\": 1000, \"y_axis\": \"up\", \"head\": \"-x\"},\n";
    out += "  \"species\": [\n";
    for (std::size_t i = 0; i < species.size(); ++i) {
        appendRecord(out, species[i]);
        out += (i + 1 < species.size()) ? ",\n" : "\n";
    }
    out += "  ]\n}\n";
    return out;
}

}  // namespace ramus
