// `ramus render IN.glb -o OUT.png [--view V] [--size WxH]`: a PNG preview of a glTF file.
#include <memory>
#include <string>

#include "commands.hpp"
#include "ramus/error.hpp"
#include "ramus/export.hpp"
#include "ramus/render.hpp"

namespace ramus::cli {

namespace {

struct RenderOptions {
    std::string input;
    std::string output;
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
    const Scene scene = readGltf(o.input);
    writePng(renderScene(scene, params), o.output);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "render a PNG preview of a .glb or .gltf file");
    cmd->add_option("IN", options->input, "the .glb or .gltf file")->required();
    cmd->add_option("-o,--output", options->output, "the PNG to write")->required();
    cmd->add_option("--view", options->view, "camera: side|front|top|three-quarter")
        ->capture_default_str();
    cmd->add_option("--size", options->size, "image size WxH, each 16..8192")
        ->capture_default_str();
    cmd->callback([options] { run(*options); });
}

}  // namespace ramus::cli
