// `ramus bones export|check`: the default bone library written out as a user library (a
// template to edit), and a user library checked without generating skeletons (docs/bones.md).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ramus/bones.hpp"
#include "ramus/error.hpp"

namespace ramus::cli {

namespace {

struct BonesOptions {
    std::string directory;
    std::string resolution = "all";
};

std::vector<BoneResolution> resolutionsOf(const std::string& name) {
    if (name == "all") return {BoneResolution::Low, BoneResolution::High};
    return {*parseBoneResolution(name)};
}

void exportLibrary(const BonesOptions& o) {
    BoneLibrary library;
    for (BoneResolution res : resolutionsOf(o.resolution)) {
        const BoneLibrary& builtin = BoneLibrary::builtin(res);
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            library.set(kind, res, builtin.model(kind, res));
        }
    }
    writeBoneLibrary(library, o.directory);
    std::printf("wrote %s/bones.json and %d model files\n", o.directory.c_str(),
                kBoneModelKindCount * static_cast<int>(resolutionsOf(o.resolution).size()));
}

/// Loads the library at each resolution (every check of loadBoneLibrary) and lists the models'
/// triangle counts against the budgets.
void checkLibrary(const BonesOptions& o) {
    for (BoneResolution res : resolutionsOf(o.resolution)) {
        const BoneLibrary library = loadBoneLibrary(o.directory, res);
        std::printf("%s resolution:\n", std::string(boneResolutionName(res)).c_str());
        for (int k = 0; k < kBoneModelKindCount; ++k) {
            const auto kind = static_cast<BoneModelKind>(k);
            const std::size_t triangles = library.model(kind, res).mesh.triangleCount();
            const int budget = boneTriangleBudget(kind, res);
            std::printf("  %-16s %7zu triangles (budget %d)%s\n",
                        std::string(boneModelKindName(kind)).c_str(), triangles, budget,
                        triangles > static_cast<std::size_t>(budget) ? "  over budget" : "");
        }
    }
    std::printf("%s: ok\n", o.directory.c_str());
}

void addResolution(CLI::App& cmd, BonesOptions& o, const char* what) {
    cmd.add_option("--resolution", o.resolution, what)
        ->check(CLI::IsMember({"low", "high", "all"}))
        ->capture_default_str();
}

}  // namespace

void addBonesCommand(CLI::App& app) {
    auto o = std::make_shared<BonesOptions>();
    CLI::App* cmd = app.add_subcommand("bones", "bone model libraries (docs/bones.md)");
    cmd->require_subcommand(1);
    CLI::App* exp = cmd->add_subcommand(
        "export", "write the default bone library as a user library (bones.json + OBJ files)");
    exp->add_option("directory", o->directory, "output directory")->required();
    addResolution(*exp, *o, "which resolutions to write");
    exp->callback([o] { exportLibrary(*o); });
    CLI::App* check = cmd->add_subcommand(
        "check", "load a user bone library and list its models' triangle counts");
    check->add_option("directory", o->directory, "library directory (with bones.json)")->required();
    addResolution(*check, *o, "which resolutions to check");
    check->callback([o] { checkLibrary(*o); });
}

}  // namespace ramus::cli
