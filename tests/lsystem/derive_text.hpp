// The derivation tests' shorthand: an L-system's text in, its derived string out.
#pragma once

#include <string>

#include "ramus/lsystem.hpp"

namespace ramus::test {

/// Parses `text` (named d.lsys in messages), derives it `derivations` times (-1: the
/// system's own count) and formats the resulting modules.
inline std::string derive(const std::string& text, int derivations = -1) {
    LSystem system = parseLSystem(text, "d.lsys");
    DeriveOptions options;
    options.derivations = derivations;
    return formatModules(system.symbols, deriveLSystem(system, options));
}

}  // namespace ramus::test
