// Based on: ABOP §1.8 (p. 32), context in bracketed strings: the left context skips complete
// branches and leaves the current branch through its `[`; the right context skips lateral
// branches unless the pattern enters them with `[ … ]`; modules on the ignore list (cpfg
// `#ignore`) are skipped in both directions.
#include "lsystem/context_match.hpp"

#include <cstring>

namespace ramus::detail {

ContextMatcher::ContextMatcher(const CompiledRules& rules) : rules_(rules) {
    entered_.resize(static_cast<std::size_t>(rules.maxRightDepth) + 1);
}

void ContextMatcher::build(const ModuleString& word) {
    const auto n = static_cast<std::uint32_t>(word.modules.size());
    const Module* mods = word.modules.data();
    const std::uint8_t* ignored = rules_.ignored.data();
    const std::uint32_t open = rules_.openSymbol;
    const std::uint32_t close = rules_.closeSymbol;
    if (rules_.hasLeftContext) {
        // Forward: `cur` is the nearest kept module on the path to the root before i.
        prev_.resize(n);
        stack_.clear();
        std::uint32_t cur = kNoIndex;
        for (std::uint32_t i = 0; i < n; ++i) {
            prev_[i] = cur;
            std::uint32_t s = mods[i].symbol;
            if (s == open) {
                stack_.push_back(cur);
            } else if (s == close) {
                if (!stack_.empty()) {
                    cur = stack_.back();
                    stack_.pop_back();
                } else {
                    cur = kNoIndex;
                }
            } else if (!ignored[s]) {
                cur = i;
            }
        }
    }
    if (rules_.hasRightContext) {
        // Backward: `cur` is the next kept module (or `]`) on the same axis after i.
        next_.resize(n);
        stack_.clear();
        std::uint32_t cur = kNoIndex;
        for (std::uint32_t i = n; i-- > 0;) {
            next_[i] = cur;
            std::uint32_t s = mods[i].symbol;
            if (s == close) {
                stack_.push_back(cur);
                cur = i;
            } else if (s == open) {
                if (!stack_.empty()) {
                    cur = stack_.back();
                    stack_.pop_back();
                } else {
                    cur = kNoIndex;
                }
            } else if (!ignored[s]) {
                cur = i;
            }
        }
    }
    if (rules_.hasRightBrackets) {
        nextKept_.resize(n);
        std::uint32_t cur = kNoIndex;
        for (std::uint32_t i = n; i-- > 0;) {
            nextKept_[i] = cur;
            if (!ignored[mods[i].symbol]) cur = i;
        }
        match_.assign(n, kNoIndex);
        stack_.clear();
        for (std::uint32_t i = 0; i < n; ++i) {
            std::uint32_t s = mods[i].symbol;
            if (s == open) {
                stack_.push_back(i);
            } else if (s == close && !stack_.empty()) {
                match_[stack_.back()] = i;
                match_[i] = stack_.back();
                stack_.pop_back();
            }
        }
    }
}

namespace {

/// True when module m has the pattern's symbol and arity; copies its parameters into slots.
inline bool bind(const PatternModule& p, const Module& m, const ModuleString& word, double* slots) {
    if (m.symbol != p.symbol || m.paramCount != p.arity) return false;
    if (p.arity) {
        std::memcpy(slots + p.firstSlot, word.params.data() + m.paramOffset,
                    sizeof(double) * p.arity);
    }
    return true;
}

}  // namespace

bool ContextMatcher::matchLeft(const Rule& rule, const ModuleString& word, std::uint32_t index,
                               double* slots) const {
    std::uint32_t pos = index;
    for (std::uint32_t k = rule.leftEnd; k-- > rule.leftBegin;) {
        pos = prev_[pos];
        if (pos == kNoIndex) return false;
        if (!bind(rules_.patterns[k], word.modules[pos], word, slots)) return false;
    }
    return true;
}

bool ContextMatcher::matchRight(const Rule& rule, const ModuleString& word, std::uint32_t index,
                                double* slots) {
    std::uint32_t pos = index;
    std::size_t depth = 0;
    for (std::uint32_t k = rule.rightBegin; k < rule.rightEnd; ++k) {
        const PatternModule& p = rules_.patterns[k];
        if (p.symbol == rules_.openSymbol) {
            // Enter the branch that must start right here (after ignored modules).
            pos = nextKept_[pos];
            if (pos == kNoIndex || word.modules[pos].symbol != rules_.openSymbol) return false;
            entered_[depth++] = pos;
        } else if (p.symbol == rules_.closeSymbol) {
            // Skip whatever remains of the entered branch.
            pos = match_[entered_[--depth]];
            if (pos == kNoIndex) return false;
        } else {
            pos = next_[pos];
            if (pos == kNoIndex) return false;
            if (!bind(p, word.modules[pos], word, slots)) return false;
        }
    }
    return true;
}

}  // namespace ramus::detail
