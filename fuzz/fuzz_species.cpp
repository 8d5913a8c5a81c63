// libFuzzer target for the species data readers: the species file (JSON) and the annotated-SVG
// import. Input starting with '<' goes to the SVG reader, anything else to the JSON reader.
// Whatever is accepted must round-trip exactly (write → read gives the same records). Only
// ramus::Error may escape the library; anything else (crash, sanitizer report, other exception,
// hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "ramus/error.hpp"
#include "ramus/species.hpp"

namespace {

void fuzzJson(std::string_view text) {
    std::vector<ramus::SpeciesRecord> species;
    try {
        species = ramus::parseSpeciesJson(text, "fuzz.json");
    } catch (const ramus::Error&) {
        return;
    }
    if (ramus::parseSpeciesJson(ramus::writeSpeciesJson(species), "back.json") != species) {
        __builtin_trap();
    }
}

void fuzzSvg(std::string_view text) {
    ramus::SvgImportOptions options;
    options.name = "fuzz";  // so that files without ramus:* attributes get past the fields
    options.animalClass = ramus::AnimalClass::Bird;
    options.wings = 1;
    options.legs = 1;
    options.weightKg = 1;
    ramus::SpeciesRecord record;
    try {
        record = ramus::importSpeciesSvg(text, "fuzz.svg", options);
    } catch (const ramus::Error&) {
        return;
    }
    if (ramus::importSpeciesSvg(ramus::exportSpeciesSvg(record), "back.svg") != record) {
        __builtin_trap();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (!text.empty() && text.front() == '<') {
        fuzzSvg(text);
    } else {
        fuzzJson(text);
    }
    return 0;
}
