// Parametric, bracketed L-systems (seed 002 ch. 2, §4.2; ABOP ch. 1–2): parsing the .lsys
// language (docs/lsystem.md) and parallel derivation into a compact module store.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ramus/math.hpp"

namespace ramus {

/// One module in a ModuleString: a symbol id and its parameters in ModuleString::params.
/// 12 bytes; parameterless modules cost no parameter storage.
struct Module {
    std::uint32_t symbol = 0;       ///< index into SymbolTable::names
    std::uint32_t paramOffset = 0;  ///< first parameter in ModuleString::params; 0 if none
    std::uint16_t paramCount = 0;
    std::uint16_t reserved = 0;
};

/// A derived word: modules in order plus all parameters in one flat array.
struct ModuleString {
    std::vector<Module> modules;
    std::vector<double> params;

    std::size_t size() const { return modules.size(); }
    const double* paramsOf(const Module& m) const { return params.data() + m.paramOffset; }
};

/// Symbol names by id ("F", "+", "[", "Apex", …). Ids are dense and stable for one LSystem.
struct SymbolTable {
    std::vector<std::string> names;
    /// Id of `name`, or -1 when the system never mentions it.
    int find(std::string_view name) const;
};

/// How tropism bends the turtle (SPEC §B). Rotate is the default.
enum class TropismMode {
    Rotate,  ///< ABOP: rotate H by e·|H×T| about H×T each step; bending accumulates
    Blend,   ///< seed 002 eq 2.18: step along normalize(H + e·T); H itself is unchanged
};

/// Header settings of a .lsys file (names as in the file).
struct LSystemSettings {
    int derivations = 1;          ///< `derivations:`  (≥ 0)
    double angleDegrees = 90.0;   ///< `angle:` default for + - & ^ \ / without argument
    double step = 1.0;            ///< `step:` default length for F and f without argument
    std::uint64_t seed = 0;       ///< `seed:` for stochastic rules and rand()
    Vec3 tropism = Vec3::Zero();  ///< `tropism: x y z e` — T in world coordinates (Y up)
    double susceptibility = 0.0;  ///< e of `tropism:`; 0 = no tropism
    TropismMode tropismMode = TropismMode::Rotate;  ///< `tropism_mode: rotate|blend`
    double width = 0.0;  ///< `width:` initial turtle width for `!`; 0 = unset
};

namespace detail {
struct CompiledRules;  // parsed productions with compiled expressions (src/lsystem)
}

/// A parsed L-system, immutable after parsing; cheap to copy (rules are shared).
struct LSystem {
    std::string fileName;  ///< as given to the parser, used in error messages
    LSystemSettings settings;
    SymbolTable symbols;
    ModuleString axiom;
    std::shared_ptr<const detail::CompiledRules> rules;
};

/// Options for parsing.
struct ParseOptions {
    /// `--set NAME=VALUE`: replaces the value of a `#define` constant (or defines it) before
    /// anything is evaluated; names that the file does not use are an error.
    std::vector<std::pair<std::string, double>> constantOverrides;
};

/// Parses .lsys text. Throws Error "file:line:col: what; expected …" on any syntax or
/// semantic error (unknown symbols in expressions, arity mismatches, bad numbers, …).
LSystem parseLSystem(std::string_view text, const std::string& fileName = "<string>",
                     const ParseOptions& options = {});

/// Reads and parses a .lsys file (errors name the path).
LSystem loadLSystem(const std::string& path, const ParseOptions& options = {});

/// Options for derivation.
struct DeriveOptions {
    int derivations = -1;  ///< -1 = use LSystemSettings::derivations
    bool overrideSeed = false;
    std::uint64_t seed = 0;  ///< used when overrideSeed
    /// Stop with Error when a word would exceed it. Parameter values are limited to 4 × this,
    /// and a word to 2^32 − 2 modules whatever is set here.
    std::size_t maxModules = 50'000'000;
    /// Memory budget (bytes) of the two words a derivation step holds — the current one and
    /// the one being written, kModuleBytes per module plus kParamBytes per parameter value —
    /// counted from the words' actual contents. Stop with Error when a step would need more
    /// (parameters can make a word large while it is still under maxModules).
    std::size_t maxMemoryBytes = std::size_t{4} << 30;
};

/// Bytes a derived word stores per module and per parameter value (what maxMemoryBytes counts).
inline constexpr std::size_t kModuleBytes = sizeof(Module);
inline constexpr std::size_t kParamBytes = sizeof(double);

/// Derives the word after n parallel rewriting steps (0 steps = the axiom). Deterministic for
/// a given system, options and seed. Throws Error on the module or memory limit (naming the
/// file, the step and the limit), and on division by zero or a non-finite value, naming the
/// rule (file:line:col of the production).
ModuleString deriveLSystem(const LSystem& system, const DeriveOptions& options = {});

/// Writes a word in file notation, e.g. "F(50)[&(36)F(50)A]": parameters printed with up to
/// 10 significant digits (%.10g), comma separated; multi-letter modules are separated from a
/// following letter by a space so the text parses back to the same word.
std::string formatModules(const SymbolTable& symbols, const ModuleString& word);

}  // namespace ramus
