// `ramus species list|import-svg|export-svg`: the species data behind the skeleton statistics.
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/species.hpp"

namespace ramus::cli {

namespace {

struct SpeciesOptions {
    std::string speciesFile;  // empty = built-in data
    bool json = false;
    // import-svg
    std::string svgFile;
    std::string target;
    std::string fit = "frame";
    bool yUp = false;
    std::vector<std::string> name, nameDe, animalClass;  // 0 or 1 value each
    std::vector<double> wings, legs, weight;
    // export-svg
    std::string species;
    std::string output;
};

std::vector<SpeciesRecord> loadSpecies(const std::string& file) {
    return file.empty() ? builtinSpecies() : loadSpeciesFile(file);
}

// The attribution line of the built-in data, kept when a file starts from it.
std::string builtinAttribution() {
    return nlohmann::json::parse(builtinSpeciesJson())["attribution"].get<std::string>();
}

// Left-aligns `text` in `width` columns, counting UTF-8 code points (so umlauts line up).
std::string padded(const std::string& text, std::size_t width) {
    std::size_t columns = 0;
    for (char c : text) columns += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return text + std::string(columns < width ? width - columns : 1, ' ');
}

void runList(const SpeciesOptions& o) {
    const std::vector<SpeciesRecord> species = loadSpecies(o.speciesFile);
    if (o.json) {
        std::fputs(
            writeSpeciesJson(species, o.speciesFile.empty() ? builtinAttribution() : "").c_str(),
            stdout);
        return;
    }
    std::printf("%s%s%-9s %5s %4s %10s\n", padded("name", 27).c_str(),
                padded("name (de)", 29).c_str(), "class", "wings", "legs", "weight kg");
    for (const SpeciesRecord& r : species) {
        std::printf("%s%s%-9s %5g %4g %10g\n", padded(r.name, 27).c_str(),
                    padded(r.nameDe, 29).c_str(),
                    std::string(animalClassName(r.animalClass)).c_str(), r.features.wings,
                    r.features.legs, r.features.weightKg);
    }
    std::printf(
        "%zu species (%s)\n", species.size(),
        o.speciesFile.empty() ? "built-in data, seed 000 appendix A.1" : o.speciesFile.c_str());
}

SvgImportOptions importOptions(const SpeciesOptions& o) {
    SvgImportOptions options;
    options.fit = o.fit == "content" ? SvgFit::Content
                  : o.fit == "none"  ? SvgFit::None
                                     : SvgFit::Frame;
    options.yUp = o.yUp;
    if (!o.name.empty()) options.name = o.name.front();
    if (!o.nameDe.empty()) options.nameDe = o.nameDe.front();
    if (!o.animalClass.empty()) {
        options.animalClass = parseAnimalClass(o.animalClass.front());
        if (!options.animalClass) {
            throw Error("--class: invalid class '" + o.animalClass.front() +
                        "'; expected fish, amphibian, reptile, bird or mammal");
        }
    }
    if (!o.wings.empty()) options.wings = o.wings.front();
    if (!o.legs.empty()) options.legs = o.legs.front();
    if (!o.weight.empty()) options.weightKg = o.weight.front();
    return options;
}

void runImport(const SpeciesOptions& o) {
    const SpeciesRecord record = importSpeciesSvg(readFile(o.svgFile), o.svgFile, importOptions(o));
    if (o.target.empty()) {
        std::fputs(writeSpeciesJson({record}).c_str(), stdout);
        return;
    }
    std::vector<SpeciesRecord> species;
    std::string attribution;
    if (std::filesystem::exists(o.target)) {
        species = loadSpeciesFile(o.target);
        attribution = nlohmann::json::parse(readFile(o.target)).value("attribution", "");
    } else {
        species = loadSpecies(o.speciesFile);
        if (o.speciesFile.empty()) attribution = builtinAttribution();
    }
    species.push_back(record);
    const std::string text = writeSpeciesJson(species, attribution);
    parseSpeciesJson(text, o.target);  // rejects e.g. a duplicate name before anything is written
    writeFileAtomic(o.target, text);
    std::fprintf(stderr, "added %s to %s (%zu species)\n", record.name.c_str(), o.target.c_str(),
                 species.size());
}

void runExport(const SpeciesOptions& o) {
    const std::vector<SpeciesRecord> species = loadSpecies(o.speciesFile);
    const SpeciesRecord* record = findSpecies(species, o.species);
    if (!record) {
        throw Error("unknown species \"" + o.species + "\"; `ramus species list` shows the names");
    }
    const std::string svg = exportSpeciesSvg(*record);
    if (o.output.empty() || o.output == "-") {
        std::fputs(svg.c_str(), stdout);
    } else {
        writeFileAtomic(o.output, svg);
    }
}

}  // namespace

void addSpeciesCommand(CLI::App& app) {
    auto o = std::make_shared<SpeciesOptions>();
    CLI::App* cmd = app.add_subcommand("species", "the species data of the skeleton statistics");
    cmd->require_subcommand(1);

    CLI::App* list = cmd->add_subcommand("list", "show the species that are loaded");
    list->add_option("--species", o->speciesFile, "species file (default: the built-in data)");
    list->add_flag("--json", o->json, "print the data as a species file (a start for your own)");
    list->callback([o] { runList(*o); });

    CLI::App* import = cmd->add_subcommand(
        "import-svg", "read an annotated side view (paths neck, back, tail, upper_arm, …)");
    import->add_option("FILE", o->svgFile, "the annotated .svg")->required();
    import->add_option("--to", o->target,
                       "append to this species file (created from --species or the built-in "
                       "data if missing); without it the record is printed");
    import->add_option("--species", o->speciesFile, "base data for a new --to file");
    import->add_option("--fit", o->fit, "frame (default), content or none")
        ->check(CLI::IsMember({"frame", "content", "none"}));
    import->add_flag("--y-up", o->yUp, "the path coordinates are already y-up");
    import->add_option("--name", o->name, "English name")->expected(1);
    import->add_option("--name-de", o->nameDe, "German name")->expected(1);
    import->add_option("--class", o->animalClass, "fish, amphibian, reptile, bird or mammal")
        ->expected(1);
    import->add_option("--wings", o->wings, "wing pairs (0 or 1)")
        ->expected(1)
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"));
    import->add_option("--legs", o->legs, "pairs of legs with ground contact (0, 1, 2)")
        ->expected(1)
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"));
    import->add_option("--weight", o->weight, "body weight in kg")
        ->expected(1)
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"));
    import->callback([o] { runImport(*o);
});

CLI::App* exportSvg =
    cmd->add_subcommand("export-svg", "write a species as an annotated SVG (importable again)");
exportSvg->add_option("NAME", o->species, "species name (English or German)")->required();
exportSvg->add_option("--species", o->speciesFile, "species file (default: the built-in data)");
exportSvg->add_option("-o,--output", o->output, "output .svg (default: standard output)");
exportSvg->callback([o] { runExport(*o); });
}  // namespace ramus::cli

}  // namespace ramus::cli
