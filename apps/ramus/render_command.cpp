// `ramus render IN.glb -o OUT.png [--view V] [--size WxH]`: a PNG preview of a glTF file;
// with --sheet, several files tiled into one labelled contact sheet.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/render.hpp"

namespace ramus::cli {

namespace {

struct RenderOptions {
    std::vector<std::string> inputs;
    std::string output;
    bool sheet = false;
    int columns = 0;
    bool noLabels = false;
    std::string view = "three-quarter";
    std::string size = "800x800";
};

// Parses an option's value with `parse`, naming the option in the error.
template <typename Parse>
auto parseOption(const char* flag, const std::string& value, Parse parse) {
    try {
        return parse(value);
    } catch (const Error& e) {
        throw Error(std::string(flag) + ": " + e.message());
    }
}

void run(const RenderOptions& o) {
    // Check the options before the (possibly large) input is read.
    RenderParams params;
    params.view = parseOption("--view", o.view, ramus::parseView);
    const ImageSize size = parseOption("--size", o.size, ramus::parseImageSize);
    params.width = size.width;
    params.height = size.height;
    if (!o.sheet) {
        if (o.inputs.size() != 1) {
            throw Error("expected one input file, got " + std::to_string(o.inputs.size()) +
                        "; use --sheet to tile several into a contact sheet");
        }
        writePng(renderScene(readGltf(o.inputs.front()), params), o.output);
        return;
    }
    std::vector<SheetTile> tiles;
    tiles.reserve(o.inputs.size());
    for (const std::string& input : o.inputs) {
        tiles.push_back(
            {renderScene(readGltf(input), params), std::filesystem::path(input).stem().string()});
    }
    SheetParams sheet;
    sheet.columns = o.columns;
    sheet.labels = !o.noLabels;
    writePng(composeContactSheet(tiles, sheet), o.output);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "render a PNG preview of a .glb or .gltf file");
    cmd->add_option("IN", options->inputs, "the .glb or .gltf file (several with --sheet)")
        ->required();
    cmd->add_option("-o,--output", options->output, "the PNG to write")->required();
    cmd->add_option("--view", options->view, "camera: side|front|top|three-quarter")
        ->capture_default_str();
    cmd->add_option("--size", options->size, "image size WxH, each 16..8192 (per tile)")
        ->capture_default_str();
    cmd->add_flag("--sheet", options->sheet,
                  "tile every input into one contact sheet, labelled with the file names");
    cmd->add_option("--columns", options->columns, "tiles per row (default: a square layout)")
        ->check(CLI::Range(0, 1000));
    cmd->add_flag("--no-labels", options->noLabels, "contact sheet without file names");
    cmd->callback([options] { run(*options); });
}

}  // namespace ramus::cli
