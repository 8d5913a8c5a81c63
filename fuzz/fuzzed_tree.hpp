// The tree an arbitrary text draws as a .lsys file, for the fuzz targets that mesh trees
// (fuzz_weld, fuzz_union): parsed, derived for at most 4 steps under a 20 000-module and 8 MiB
// limit, and drawn by the turtle.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string_view>

#include "ramus/branch_tree.hpp"
#include "ramus/error.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/turtle.hpp"

namespace ramus::fuzz {

/// The tree `text` draws, or nothing where the library answers with a ramus::Error or the tree
/// has more than `maxNodes` nodes.
inline std::optional<BranchTree> fuzzedTree(std::string_view text, std::size_t maxNodes) {
    try {
        const LSystem system = parseLSystem(text, "fuzz.lsys");
        DeriveOptions options;
        options.derivations = std::min(system.settings.derivations, 4);
        options.maxModules = 20000;
        options.maxMemoryBytes = std::size_t{8} << 20;
        const ModuleString word = deriveLSystem(system, options);
        BranchTree tree =
            interpretTurtle(word, system.symbols, turtleParamsFrom(system.settings)).tree;
        if (tree.size() > maxNodes) return std::nullopt;
        return tree;
    } catch (const Error&) {
        return std::nullopt;
    }
}

}  // namespace ramus::fuzz
