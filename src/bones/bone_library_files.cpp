// User bone libraries (include/ramus/bones.hpp, docs/bones.md "User bone libraries"): a
// directory with bones.json naming per model kind a mesh file and its joint offsets.
//
// Based on: seed 000 §5.6 (models and their offsets stored per bone and swappable without code
// changes; unit-cube conventions), §6.1 (resolutions).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>

#include "bones/bone_files.hpp"
#include "core/json_text.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "skeleton/number_text.hpp"

namespace ramus {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Path = std::vector<std::string>;

constexpr int kManifestVersion = 1;
constexpr const char* kManifestName = "bones.json";

std::string knownKinds() {
    std::string out;
    for (int k = 0; k < kBoneModelKindCount; ++k) {
        out += (k == 0 ? "" : ", ") + std::string(boneModelKindName(static_cast<BoneModelKind>(k)));
    }
    return out;
}

/// "models.rib.child_joints[0]"
std::string dotted(const Path& path) {
    std::string out;
    for (const std::string& key : path) {
        const bool index = !key.empty() && key.find_first_not_of("0123456789") == std::string::npos;
        out += index ? "[" + key + "]" : (out.empty() ? "" : ".") + key;
    }
    return out;
}

Path child(Path path, const std::string& key) {
    path.push_back(key);
    return path;
}

/// Reads one resolution of a library's manifest; errors are located in the manifest.
class ManifestReader {
public:
    ManifestReader(const std::string& directory, BoneResolution resolution)
        : directory_(directory),
          file_((fs::path(directory) / kManifestName).string()),
          resolution_(resolution) {}

    BoneLibrary load() {
        if (!fs::is_directory(directory_)) {
            throw Error(SourceLoc{directory_, 0, 0},
                        "bone library: not a directory; expected a directory with bones.json");
        }
        text_ = readFile(file_);
        const Json root = detail::parseJsonText(text_, file_);
        object(root, {}, {"version", "models", "comment"});
        const Json& version = member(root, {}, "version", "the manifest format version, 1");
        if (!version.is_number_integer() || version.get<std::int64_t>() != kManifestVersion) {
            fail({"version"}, "unsupported version " + detail::describeJson(version) +
                                  "; expected " + std::to_string(kManifestVersion));
        }
        const Json& models = member(root, {}, "models", "an object of models by kind");
        object(models, {"models"}, {});
        BoneLibrary library;
        for (const auto& [name, entry] : models.items()) {
            const std::optional<BoneModelKind> kind = parseBoneModelKind(name);
            if (!kind) {
                fail({"models", name},
                     "unknown bone model kind \"" + name + "\"; expected one of " + knownKinds());
            }
            library.set(*kind, resolution_, model(name, entry));
        }
        for (int k = 0; k < kBoneModelKindCount; ++k) {  // the rest: the default library's
            const auto kind = static_cast<BoneModelKind>(k);
            if (!library.has(kind, resolution_)) {
                library.set(kind, resolution_,
                            BoneLibrary::builtin(resolution_).model(kind, resolution_));
            }
        }
        return library;
    }

private:
    [[noreturn]] void fail(const Path& path, const std::string& message) const {
        throw Error(detail::jsonValueLoc(text_, path, file_), dotted(path) + ": " + message);
    }

    // `value` must be an object; with `known` non-empty, only those keys.
    void object(const Json& value, const Path& path,
                std::initializer_list<std::string_view> known) const {
        if (!value.is_object()) {
            fail(path, "expected an object; got " + detail::describeJson(value));
        }
        if (known.size() == 0) return;
        for (const auto& item : value.items()) {
            if (std::find(known.begin(), known.end(), item.key()) == known.end()) {
                std::string list;
                for (std::string_view k : known)
                    list += (list.empty() ? "" : ", ") + std::string(k);
                fail(child(path, item.key()), "unknown key; expected one of " + list);
            }
        }
    }

    const Json& member(const Json& object, const Path& path, const char* key,
                       const std::string& what) const {
        const auto it = object.find(key);
        if (it == object.end()) {
            fail(path, "missing \"" + std::string(key) + "\" (" + what + ")");
        }
        return *it;
    }

    Vec3 point(const Json& value, const Path& path) const {
        if (!value.is_array() || value.size() != 3) {
            fail(path,
                 "expected [x, y, z] in unit-cube coordinates; got " + detail::describeJson(value));
        }
        Vec3 p;
        for (int k = 0; k < 3; ++k) {
            const Json& c = value[static_cast<std::size_t>(k)];
            if (!c.is_number() || !std::isfinite(c.get<double>())) {
                fail(child(path, std::to_string(k)),
                     "expected a finite number; got " + detail::describeJson(c));
            }
            p[k] = c.get<double>();
        }
        return p;
    }

    std::string meshPath(const std::string& name, const Json& entry, const Path& path) const {
        const std::string res(boneResolutionName(resolution_));
        const bool single = entry.contains("mesh");
        if (single && (entry.contains("low") || entry.contains("high"))) {
            fail(path,
                 "both \"mesh\" and \"low\"/\"high\"; expected either \"mesh\" (one file "
                 "for both resolutions) or \"low\" and \"high\"");
        }
        if (!single && !entry.contains(res)) {
            fail(path, "missing \"mesh\" or \"" + res + "\" (the mesh file of \"" + name +
                           "\" at the " + res + " resolution: .obj, .gltf or .glb)");
        }
        const std::string key = single ? "mesh" : res;
        const Json& value = entry[key];
        if (!value.is_string() || value.get<std::string>().empty()) {
            fail(child(path, key), "expected a mesh file name; got " + detail::describeJson(value));
        }
        const fs::path file(value.get<std::string>());
        const fs::path full = file.is_absolute() ? file : fs::path(directory_) / file;
        if (!fs::is_regular_file(full)) {
            fail(child(path, key), "mesh file not found: " + full.string());
        }
        return full.string();
    }

    // parent_joint, child_joints and width_from_height of an entry.
    void readOffsets(const Json& entry, const Path& path, BoneModel& model) const {
        const Json& parent = member(entry, path, "parent_joint",
                                    "where the joint to the parent sits, e.g. [0, 0, 0]");
        model.parentJoint = point(parent, child(path, "parent_joint"));
        const Json& children = member(entry, path, "child_joints",
                                      "where the joints to the children sit, e.g. [[1, 0, 0]]");
        const Path childPath = child(path, "child_joints");
        if (!children.is_array() || children.empty()) {
            fail(childPath,
                 "expected a non-empty list of [x, y, z]; got " + detail::describeJson(children));
        }
        model.childJoints.clear();
        for (std::size_t i = 0; i < children.size(); ++i) {
            model.childJoints.push_back(point(children[i], child(childPath, std::to_string(i))));
        }
        if (!(model.childJoints.front().x() > model.parentJoint.x())) {
            fail(child(childPath, "0"),
                 "the first child joint (the bone's end) must lie further along x than the "
                 "parent joint; expected x > " +
                     detail::shortest(model.parentJoint.x()) + ", got " +
                     detail::shortest(model.childJoints.front().x()));
        }
        if (entry.contains("width_from_height")) {
            const Json& w = entry["width_from_height"];
            if (!w.is_number() || !(w.get<double>() >= 0.0) || !std::isfinite(w.get<double>())) {
                fail(child(path, "width_from_height"),
                     "expected a finite number >= 0 (0: the width follows the bone's width); got " +
                         detail::describeJson(w));
            }
            model.widthFromHeight = w.get<double>();
        }
    }

    BoneModel model(const std::string& name, const Json& entry) const {
        const Path path = {"models", name};
        object(entry, path,
               {"mesh", "low", "high", "parent_joint", "child_joints", "width_from_height",
                "comment"});
        BoneModel model;
        const std::string mesh = meshPath(name, entry, path);
        readOffsets(entry, path, model);
        try {
            model.mesh = detail::readBoneMesh(mesh, name);
        } catch (const Error& e) {
            throw Error(e.loc(), e.message() + " (bone model \"" + name + "\", " +
                                     std::string(boneResolutionName(resolution_)) + ", in " +
                                     file_ + ")");
        }
        return model;
    }

    std::string directory_;
    std::string file_;
    BoneResolution resolution_;
    std::string text_;
};

void makeDirectory(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Error(dir.string() + ": cannot create directory: " + ec.message());
}

void appendPoint(std::string& out, const Vec3& p) {
    out += '[';
    for (int k = 0; k < 3; ++k) {
        if (k > 0) out += ", ";
        detail::appendShortest(out, p[k]);
    }
    out += ']';
}

bool sameOffsets(const BoneModel& a, const BoneModel& b) {
    return a.parentJoint == b.parentJoint && a.childJoints == b.childJoints &&
           a.widthFromHeight == b.widthFromHeight;
}

/// The manifest entry of a kind (its files written) or "" when the library has no model of it.
std::string writeEntry(const BoneLibrary& library, BoneModelKind kind, const fs::path& dir) {
    const std::string name(boneModelKindName(kind));
    const BoneModel* first = nullptr;
    std::string files;
    for (BoneResolution res : {BoneResolution::Low, BoneResolution::High}) {
        if (!library.has(kind, res)) continue;
        const BoneModel& model = library.model(kind, res);
        if (first != nullptr && !sameOffsets(*first, model)) {
            throw Error("bone model " + name +
                        ": the low and high models have different joint offsets; expected the "
                        "same (a manifest entry has one set of offsets)");
        }
        first = first != nullptr ? first : &model;
        const std::string resName(boneResolutionName(res));
        const std::string file = resName + "/" + name + ".obj";
        makeDirectory(dir / resName);
        writeFileAtomic(
            (dir / file).string(),
            detail::boneMeshObj(model.mesh, "ramus bone model " + name + " (" + resName +
                                                "), unit-cube coordinates: "
                                                "docs/bones.md"));
        files += "      \"" + resName + "\": \"" + file + "\",\n";
    }
    if (first == nullptr) return {};
    std::string out = "    \"" + name + "\": {\n" + files + "      \"parent_joint\": ";
    appendPoint(out, first->parentJoint);
    out += ",\n      \"child_joints\": [";
    for (std::size_t i = 0; i < first->childJoints.size(); ++i) {
        if (i > 0) out += ", ";
        appendPoint(out, first->childJoints[i]);
    }
    out += "],\n      \"width_from_height\": ";
    detail::appendShortest(out, first->widthFromHeight);
    out += "\n    }";
    return out;
}

}  // namespace

BoneLibrary loadBoneLibrary(const std::string& directory, BoneResolution resolution) {
    if (resolution == BoneResolution::Box) {
        throw Error("bone library " + directory +
                    ": the box resolution has no bone models; expected low or high");
    }
    return ManifestReader(directory, resolution).load();
}

void writeBoneLibrary(const BoneLibrary& library, const std::string& directory) {
    const fs::path dir(directory);
    makeDirectory(dir);
    std::string entries;
    for (int k = 0; k < kBoneModelKindCount; ++k) {
        const std::string entry = writeEntry(library, static_cast<BoneModelKind>(k), dir);
        if (entry.empty()) continue;
        entries += (entries.empty() ? "" : ",\n") + entry;
    }
    const std::string manifest = "{\n  \"version\": " + std::to_string(kManifestVersion) +
                                 ",\n  \"models\": {\n" + entries + (entries.empty() ? "" : "\n") +
                                 "  }\n}\n";
    // The manifest last, so it never names a missing mesh file.
    writeFileAtomic((dir / kManifestName).string(), manifest);
}

}  // namespace ramus
