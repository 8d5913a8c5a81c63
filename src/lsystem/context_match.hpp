// Internal: context matching in bracketed words (ABOP §1.8, p. 32) in O(pattern length) per
// test, using neighbour tables built once per derivation step in O(word length).
#pragma once

#include <cstdint>
#include <vector>

#include "lsystem/compiled_rules.hpp"
#include "ramus/lsystem.hpp"

namespace ramus::detail {

inline constexpr std::uint32_t kNoIndex = 0xFFFFFFFFu;

/// Per-step tables over one word. For module i:
///  - prev[i]: the module that precedes i on its path towards the root, skipping complete
///    branches `[…]`, the `[` that opens i's own branch, and ignored modules (ABOP: the left
///    context "is found by skipping over branches");
///  - next[i]: the module that follows i on the same axis, skipping lateral branches and
///    ignored modules; it may be the `]` that ends i's branch (a stop for the right context);
///  - nextKept[i]: the first module after i that is not ignored (entering a branch `[`);
///  - match[i]: for a bracket, the index of its partner.
/// Only the tables the system's rules need are built.
class ContextMatcher {
public:
    explicit ContextMatcher(const CompiledRules& rules);

    /// Rebuilds the tables for `word` (balanced brackets assumed; unbalanced ones are treated
    /// as if closed at the end).
    void build(const ModuleString& word);

    /// Tests the left context of `rule` for the module at `index`; binds its formal parameters
    /// into `slots` on success.
    bool matchLeft(const Rule& rule, const ModuleString& word, std::uint32_t index,
                   double* slots) const;
    /// Same for the right context; a `[` in the pattern enters a branch, a `]` skips the rest
    /// of the entered branch.
    bool matchRight(const Rule& rule, const ModuleString& word, std::uint32_t index, double* slots);

private:
    void buildPrev(const ModuleString& word);
    void buildNext(const ModuleString& word);
    void buildBrackets(const ModuleString& word);

    const CompiledRules& rules_;
    std::vector<std::uint32_t> prev_;
    std::vector<std::uint32_t> next_;
    std::vector<std::uint32_t> nextKept_;
    std::vector<std::uint32_t> match_;
    std::vector<std::uint32_t> stack_;
    std::vector<std::uint32_t> entered_;
};

}  // namespace ramus::detail
