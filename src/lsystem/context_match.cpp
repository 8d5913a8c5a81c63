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
    if (rules_.hasLeftContext) buildPrev(word);
    if (rules_.hasRightContext) buildNext(word);
    if (rules_.hasRightBrackets) buildBrackets(word);
}

void ContextMatcher::buildPrev(const ModuleString& word) {
    // Forward: `cur` is the nearest kept module on the path to the root before i; a `[` saves
    // it for the partner `]`, which restores it (so complete branches are skipped).
    const auto n = static_cast<std::uint32_t>(word.modules.size());
    prev_.resize(n);
    stack_.clear();
    std::uint32_t cur = kNoIndex;
    for (std::uint32_t i = 0; i < n; ++i) {
        prev_[i] = cur;
        std::uint32_t s = word.modules[i].symbol;
        if (s == rules_.openSymbol) {
            stack_.push_back(cur);
        } else if (s == rules_.closeSymbol) {
            cur = stack_.empty() ? kNoIndex : stack_.back();
            if (!stack_.empty()) stack_.pop_back();
        } else if (!rules_.ignored[s]) {
            cur = i;
        }
    }
}

void ContextMatcher::buildNext(const ModuleString& word) {
    // Backward: `cur` is the next kept module (or `]`) on the same axis after i; a `]` saves
    // it for the partner `[`, which restores it (so lateral branches are skipped).
    const auto n = static_cast<std::uint32_t>(word.modules.size());
    next_.resize(n);
    stack_.clear();
    std::uint32_t cur = kNoIndex;
    for (std::uint32_t i = n; i-- > 0;) {
        next_[i] = cur;
        std::uint32_t s = word.modules[i].symbol;
        if (s == rules_.closeSymbol) {
            stack_.push_back(cur);
            cur = i;
        } else if (s == rules_.openSymbol) {
            cur = stack_.empty() ? kNoIndex : stack_.back();
            if (!stack_.empty()) stack_.pop_back();
        } else if (!rules_.ignored[s]) {
            cur = i;
        }
    }
}

void ContextMatcher::buildBrackets(const ModuleString& word) {
    const auto n = static_cast<std::uint32_t>(word.modules.size());
    nextKept_.resize(n);
    std::uint32_t cur = kNoIndex;
    for (std::uint32_t i = n; i-- > 0;) {
        nextKept_[i] = cur;
        if (!rules_.ignored[word.modules[i].symbol]) cur = i;
    }
    match_.assign(n, kNoIndex);
    stack_.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
        std::uint32_t s = word.modules[i].symbol;
        if (s == rules_.openSymbol) {
            stack_.push_back(i);
        } else if (s == rules_.closeSymbol && !stack_.empty()) {
            match_[stack_.back()] = i;
            match_[i] = stack_.back();
            stack_.pop_back();
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
