// libFuzzer target for the colonization config loader (docs/colonize.md): any text must either
// parse or throw ramus::Error; an accepted config must also grow without anything else escaping
// (bounded here so one input stays fast). Crashes, sanitizer reports, other exceptions and hangs
// are bugs.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "ramus/colonize.hpp"
#include "ramus/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    ramus::ColonizeConfig config;
    try {
        // A folder that does not exist: "mesh" shapes and point files fail to load, as they must.
        config = ramus::parseColonizeConfig(text, "/nonexistent-ramus-fuzz/config.json");
    } catch (const ramus::Error&) {
        return 0;
    }
    // Keep each run small: few points and iterations (the limits themselves are tested elsewhere).
    for (ramus::Envelope& e : config.envelopes)
        e.pointCount = std::min<std::uint32_t>(e.pointCount, 300);
    config.params.maxIterations = std::min(config.params.maxIterations, 50);
    try {
        const std::vector<ramus::Vec3> points = ramus::configAttractionPoints(config);
        (void)ramus::growFromConfig(config, points);
    } catch (const ramus::Error&) {
    }
    return 0;
}
