// libFuzzer target for the .lsys language: parses arbitrary text, derives at most 5 steps under
// a 100 000-module and 8 MiB memory limit (so both limit paths are reached), and checks that the
// formatted word parses back to the same length. Only ramus::Error may escape the library; anything
// else (crash, sanitizer report, other exception, hang) is a bug. Run with scripts/fuzz.sh.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"

namespace {

/// The `module` line that declares every multi-character name of `symbols`.
std::string moduleDeclarations(const ramus::SymbolTable& symbols) {
    std::string line;
    for (const auto& name : symbols.names) {
        if (name.size() > 1) line += " " + name;
    }
    return line.empty() ? std::string() : "module" + line + "\n";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    ramus::LSystem system;
    ramus::ModuleString word;
    try {
        system = ramus::parseLSystem(text, "fuzz.lsys");
        ramus::DeriveOptions options;
        options.derivations = std::min(system.settings.derivations, 5);
        options.maxModules = 100000;
        options.maxMemoryBytes = std::size_t{8} << 20;
        word = ramus::deriveLSystem(system, options);
    } catch (const ramus::Error&) {
        return 0;
    }
    if (word.size() == 0) return 0;
    // formatModules must round-trip: the same number of modules with the same names.
    std::string formatted = ramus::formatModules(system.symbols, word);
    ramus::LSystem back =
        ramus::parseLSystem(moduleDeclarations(system.symbols) + "axiom: " + formatted);
    if (back.axiom.size() != word.size()) __builtin_trap();
    for (std::size_t i = 0; i < word.size(); ++i) {
        const ramus::Module& a = word.modules[i];
        const ramus::Module& b = back.axiom.modules[i];
        if (system.symbols.names[a.symbol] != back.symbols.names[b.symbol]) __builtin_trap();
        if (a.paramCount != b.paramCount) __builtin_trap();
    }
    return 0;
}
