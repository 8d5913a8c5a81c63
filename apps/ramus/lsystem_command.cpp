// `ramus lsystem FILE.lsys …`: derive, interpret, mesh, write.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/tube_mesher.hpp"
#include "ramus/turtle.hpp"
#include "tree_output.hpp"

namespace ramus::cli {

namespace {

struct LsystemOptions {
    std::string file;
    int derivations = -1;
    std::vector<std::string> seed;  // 0 or 1 value; a vector tells "absent" from "0"
    std::vector<std::string> sets;
    std::size_t maxModules = DeriveOptions{}.maxModules;
    std::size_t maxMemoryMiB = DeriveOptions{}.maxMemoryBytes >> 20;
    std::string tropismMode;
    bool print = false;
    bool stats = false;
    TreeOutputs outputs;
    TubeMeshParams mesh;
    AssetOptions assets;
};

// "NAME=VALUE" → pair; the value must be a plain, finite number.
std::pair<std::string, double> parseSetting(const std::string& text) {
    const std::size_t eq = text.find('=');
    std::size_t used = 0;
    double value = 0;
    if (eq != std::string::npos && eq > 0) {
        try {
            value = std::stod(text.substr(eq + 1), &used);
        } catch (const std::out_of_range&) {
            throw Error("--set: the value of '" + text +
                        "' is outside the range of a double; expected a finite number");
        } catch (const std::exception&) {
            used = 0;
        }
    }
    if (eq == std::string::npos || eq == 0 || used == 0 || used != text.size() - eq - 1) {
        throw Error("--set: invalid setting '" + text + "'; expected NAME=NUMBER, e.g. a=30");
    }
    if (!std::isfinite(value)) {
        throw Error("--set: the value of '" + text + "' is not finite; expected a finite number");
    }
    return {text.substr(0, eq), value};
}

void run(LsystemOptions& o) {
    ParseOptions parseOptions;
    for (const std::string& s : o.sets) parseOptions.constantOverrides.push_back(parseSetting(s));
    DeriveOptions deriveOptions;
    deriveOptions.derivations = o.derivations;
    deriveOptions.maxModules = o.maxModules;
    deriveOptions.maxMemoryBytes = o.maxMemoryMiB << 20;
    if (!o.seed.empty()) {
        deriveOptions.overrideSeed = true;
        deriveOptions.seed = parseSeed(o.seed.front());
    }
    const LSystem system = loadLSystem(o.file, parseOptions);
    TurtleParams turtle = turtleParamsFrom(system.settings);
    if (o.tropismMode == "blend") turtle.tropismMode = TropismMode::Blend;
    if (o.tropismMode == "rotate") turtle.tropismMode = TropismMode::Rotate;

    if (!o.print && !o.stats && !o.outputs.any()) {
        o.outputs.model = std::filesystem::path(o.file).stem().string() + ".glb";
        std::fprintf(stderr, "writing %s (use -o to choose the output)\n", o.outputs.model.c_str());
    }

    const AssetSettings assets = applyAssetOptions(o.mesh, o.assets, AssetSettings{});
    StageTimer timer;
    const ModuleString word = deriveLSystem(system, deriveOptions);
    timer.lap("derive");
    if (o.print) std::printf("%s\n", formatModules(system.symbols, word).c_str());

    timer.restart();
    const TurtleResult shape = interpretTurtle(word, system.symbols, turtle);
    timer.lap("interpret");

    const TreeModel model = plantModel(shape, assets.mesh, assets.lods);
    warnOfBarkCompromises(model);
    timer.lap("mesh");

    writeTreeOutputs(o.outputs, shape.tree, model, o.mesh);
    if (o.stats) {
        nlohmann::ordered_json stats;
        stats["modules"] = word.size();
        stats["nodes"] = shape.tree.size();
        stats["edges"] = shape.tree.edgeCount();
        stats["polygons"] = shape.polygonCount();
        printTreeStats(std::move(stats), model, timer);
    }
}

}  // namespace

void addLsystemCommand(CLI::App& app) {
    auto options = std::make_shared<LsystemOptions>();
    CLI::App* cmd = app.add_subcommand("lsystem", "grow a plant from an L-system file (.lsys)");
    cmd->add_option("FILE", options->file, "the .lsys file")->required();
    cmd->add_option("-n,--derivations", options->derivations,
                    "derivation steps (default: the file's `derivations:`)")
        ->check(CLI::Range(0, 1000));
    cmd->add_option("--seed", options->seed, "seed for stochastic rules and rand()")->expected(1);
    cmd->add_option("--set", options->sets, "override a constant: NAME=VALUE (repeatable)");
    cmd->add_option("--max-modules", options->maxModules,
                    "stop with an error when a derived word would exceed this many modules")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--max-memory", options->maxMemoryMiB,
                    "stop with an error when a derivation step's words would need more than "
                    "this many MiB (modules and their parameters)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20))
        ->capture_default_str();
    cmd->add_option("--tropism-mode", options->tropismMode,
                    "rotate (ABOP, bending accumulates) or blend (seed 002 eq 2.18)")
        ->check(CLI::IsMember({"rotate", "blend"}));
    cmd->add_flag("--print", options->print, "print the derived word in file notation");
    cmd->add_flag("--stats", options->stats, "print statistics as one JSON object");
    addTreeOutputOptions(*cmd, options->outputs);
    addTubeMeshOptions(*cmd, options->mesh);
    addAssetOptions(*cmd, options->assets);
    cmd->callback([options] { run(*options); });
}

}  // namespace ramus::cli
