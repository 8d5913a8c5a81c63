// Based on: parallel rewriting of (parametric, bracketed) L-systems, ABOP §1.1–1.2, §2.1
// (seed 002 §2.2–2.4); context matching per ABOP §1.8 (context_match.cpp); stochastic choice
// per ABOP §1.7; the cut symbol `%` as cpfg implements it (the rest of the branch is dropped
// while the word is rewritten).
#include <algorithm>
#include <cstring>
#include <string>

#include "lsystem/compiled_rules.hpp"
#include "lsystem/context_match.hpp"
#include "lsystem/expression.hpp"
#include "ramus/rng.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ramus {
namespace {

using detail::CompiledRules;
using detail::kNoExpr;
using detail::Rule;
using detail::SymbolKind;

/// Parameter values allowed per module on average before the module limit applies to them.
constexpr std::size_t kParamsPerModuleLimit = 4;
/// Largest word size: indices are 32 bits and 0xFFFFFFFF means "none" in context tables.
constexpr std::size_t kMaxIndex = 0xFFFFFFFEu;

/// Bytes a word's contents take (what DeriveOptions::maxMemoryBytes counts).
std::size_t wordBytes(std::size_t modules, std::size_t params) {
    return modules * kModuleBytes + params * kParamBytes;
}

/// Reserves room for `count` elements; for large words asks the kernel for transparent huge
/// pages. Most of a derivation's time otherwise goes into first-touch page faults of the
/// freshly allocated output (one per 4 KiB); it is only a hint and harmless if refused.
template <typename T>
void reserveWord(std::vector<T>& v, std::size_t count) {
    if (count <= v.capacity()) return;
    v.reserve(count);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::size_t kHuge = std::size_t(2) << 20;
    std::size_t bytes = v.capacity() * sizeof(T);
    if (bytes >= 4 * kHuge) {
        auto begin = reinterpret_cast<std::uintptr_t>(v.data());
        std::uintptr_t alignedBegin = (begin + kHuge - 1) & ~(kHuge - 1);
        std::uintptr_t alignedEnd = (begin + bytes) & ~(kHuge - 1);
        if (alignedEnd > alignedBegin) {
            madvise(reinterpret_cast<void*>(alignedBegin), alignedEnd - alignedBegin,
                    MADV_HUGEPAGE);
        }
    }
#endif
}

class Deriver {
public:
    Deriver(const LSystem& system, const DeriveOptions& options)
        : system_(system),
          rules_(*system.rules),
          matcher_(*system.rules),
          rng_(options.overrideSeed ? options.seed : system.settings.seed),
          // Words index modules and parameters with 32 bits (Module::paramOffset).
          maxModules_(std::min<std::size_t>(options.maxModules, kMaxIndex)),
          maxParams_(std::min<std::size_t>(maxModules_, kMaxIndex / kParamsPerModuleLimit) *
                     kParamsPerModuleLimit),
          maxMemory_(options.maxMemoryBytes),
          steps_(options.derivations < 0 ? system.settings.derivations : options.derivations) {
        if (options.derivations < -1) {
            throw Error(SourceLoc{system.fileName, 0, 0},
                        "derivations must be >= 0 (or -1 for the file's value); got " +
                            std::to_string(options.derivations));
        }
        slots_.assign(std::max<std::size_t>(rules_.maxSlots, 1), 0.0);
    }

    ModuleString run() {
        ModuleString current = system_.axiom;
        if (current.modules.size() > maxModules_ || current.params.size() > maxParams_) {
            failLimit();
        }
        if (wordBytes(current.modules.size(), current.params.size()) > maxMemory_) {
            failMemory(current.modules.size(), current.params.size(), 0, 0);
        }
        ModuleString next;
        double growth = 2.0;
        for (step_ = 1; step_ <= steps_; ++step_) {
            // Reserve by the last step's growth; capacity is kept between steps.
            // Over-estimating costs only address space: untouched pages are never mapped.
            // Never more than the limits allow, so a reservation cannot fail on its own.
            const double left = static_cast<double>(
                maxMemory_ - wordBytes(current.modules.size(), current.params.size()));
            double estimate = static_cast<double>(current.modules.size()) * growth * 1.5 + 64.0;
            estimate = std::min({estimate, static_cast<double>(maxModules_), left / kModuleBytes});
            reserveWord(next.modules, static_cast<std::size_t>(estimate));
            double paramEstimate = static_cast<double>(current.params.size()) * growth * 1.5;
            paramEstimate =
                std::min({paramEstimate, static_cast<double>(maxParams_), left / kParamBytes});
            reserveWord(next.params, static_cast<std::size_t>(paramEstimate));
            rewrite(current, next);
            growth = std::clamp(
                static_cast<double>(next.modules.size()) /
                    static_cast<double>(std::max<std::size_t>(current.modules.size(), 1)),
                1.0, 64.0);
            std::swap(current, next);
        }
        return current;
    }

private:
    void rewrite(const ModuleString& in, ModuleString& out);
    void rewriteGeneral(const ModuleString& in, std::uint32_t index, ModuleString& out);
    void chooseStochastic(const ModuleString& in, std::uint32_t index, std::uint32_t first,
                          ModuleString& out);
    bool matches(const Rule& rule, const ModuleString& in, std::uint32_t index);
    void emit(const Rule& rule, ModuleString& out);
    double evalExpr(std::int32_t expr);
    [[noreturn]] void failEval(std::int32_t expr, detail::EvalStatus status) const;
    [[noreturn]] void failLimit() const;
    [[noreturn]] void failMemory(std::size_t inModules, std::size_t inParams,
                                 std::size_t outModules, std::size_t outParams) const;

    // Room: how far `out` may grow before grow() must look at the capacity and the limits.
    void ensureRoom(ModuleString& out, std::size_t modules, std::size_t params) {
        if (out.modules.size() + modules > moduleRoom_ || out.params.size() + params > paramRoom_) {
            grow(out, modules, params);
        }
    }
    void grow(ModuleString& out, std::size_t modules, std::size_t params);
    void setRoom(const ModuleString& out);

    void copyModule(const ModuleString& in, const Module& m, ModuleString& out) {
        ensureRoom(out, 1, m.paramCount);
        if (m.paramCount == 0) {
            out.modules.push_back(m);
            return;
        }
        Module copy = m;
        copy.paramOffset = static_cast<std::uint32_t>(out.params.size());
        out.modules.push_back(copy);
        const double* p = in.params.data() + m.paramOffset;
        // Room is ensured, so push_back never reallocates; cheaper than insert's memmove
        // call for the usual one or two parameters.
        for (std::uint16_t k = 0; k < m.paramCount; ++k) out.params.push_back(p[k]);
    }

    /// Index of the `]` that closes the branch containing `index`, or the word's end.
    std::uint32_t endOfBranch(const ModuleString& in, std::uint32_t index) const {
        int depth = 0;
        auto n = static_cast<std::uint32_t>(in.modules.size());
        for (std::uint32_t j = index + 1; j < n; ++j) {
            std::uint32_t s = in.modules[j].symbol;
            if (s == rules_.openSymbol) {
                ++depth;
            } else if (s == rules_.closeSymbol) {
                if (depth == 0) return j;
                --depth;
            }
        }
        return n;
    }

    const LSystem& system_;
    const CompiledRules& rules_;
    detail::ContextMatcher matcher_;
    Rng rng_;
    std::size_t maxModules_;
    std::size_t maxParams_;
    std::size_t maxMemory_;
    std::size_t inModules_ = 0, inParams_ = 0;    ///< size of the word being rewritten
    std::size_t moduleRoom_ = 0, paramRoom_ = 0;  ///< see ensureRoom
    int steps_;
    int step_ = 0;
    std::vector<double> slots_;
    std::vector<std::pair<std::uint32_t, double>> candidates_;  ///< stochastic: rule, weight
    std::vector<double> candidateSlots_;  ///< their bound parameters, maxSlots per candidate
};

void Deriver::rewrite(const ModuleString& in, ModuleString& out) {
    out.modules.clear();
    out.params.clear();
    inModules_ = in.modules.size();
    inParams_ = in.params.size();
    setRoom(out);
    if (rules_.hasLeftContext || rules_.hasRightContext) matcher_.build(in);
    const auto n = static_cast<std::uint32_t>(in.modules.size());
    const Module* mods = in.modules.data();
    const detail::SymbolRules* bySymbol = rules_.bySymbol.data();
    for (std::uint32_t i = 0; i < n; ++i) {
        const Module& m = mods[i];
        const detail::SymbolRules& entry = bySymbol[m.symbol];
        switch (entry.kind) {
            case SymbolKind::Identity:
                copyModule(in, m, out);
                break;
            case SymbolKind::Always: {
                const Rule& rule = rules_.rules[entry.ruleBegin];
                if (rule.arity != m.paramCount) {
                    copyModule(in, m, out);
                    break;
                }
                if (rule.arity) {
                    std::memcpy(slots_.data(), in.params.data() + m.paramOffset,
                                sizeof(double) * rule.arity);
                }
                emit(rule, out);
                break;
            }
            case SymbolKind::General:
                rewriteGeneral(in, i, out);
                break;
            case SymbolKind::Cut:
                i = endOfBranch(in, i) - 1;
                break;
        }
    }
}

bool Deriver::matches(const Rule& rule, const ModuleString& in, std::uint32_t index) {
    const Module& m = in.modules[index];
    if (rule.arity != m.paramCount) return false;
    if (rule.arity) {
        std::memcpy(slots_.data(), in.params.data() + m.paramOffset, sizeof(double) * rule.arity);
    }
    if (rule.leftBegin != rule.leftEnd && !matcher_.matchLeft(rule, in, index, slots_.data())) {
        return false;
    }
    if (rule.rightBegin != rule.rightEnd && !matcher_.matchRight(rule, in, index, slots_.data())) {
        return false;
    }
    return rule.condition == kNoExpr || evalExpr(rule.condition) != 0.0;
}

void Deriver::rewriteGeneral(const ModuleString& in, std::uint32_t index, ModuleString& out) {
    const detail::SymbolRules& entry = rules_.bySymbol[in.modules[index].symbol];
    for (std::uint32_t k = entry.ruleBegin; k < entry.ruleEnd; ++k) {
        const Rule& rule = rules_.rules[k];
        if (!matches(rule, in, index)) continue;
        // The first matching rule decides: a plain rule applies; a stochastic one makes all
        // matching stochastic rules of this symbol compete by weight.
        if (rule.weight == kNoExpr) return emit(rule, out);
        return chooseStochastic(in, index, k, out);
    }
    copyModule(in, in.modules[index], out);
}

void Deriver::chooseStochastic(const ModuleString& in, std::uint32_t index, std::uint32_t first,
                               ModuleString& out) {
    const detail::SymbolRules& entry = rules_.bySymbol[in.modules[index].symbol];
    const std::size_t stride = slots_.size();
    candidates_.clear();
    double total = 0.0;
    for (std::uint32_t k = first; k < entry.ruleEnd; ++k) {
        const Rule& rule = rules_.rules[k];
        if (rule.weight == kNoExpr) continue;
        if (k != first && !matches(rule, in, index)) continue;
        double w = evalExpr(rule.weight);
        if (w < 0.0) {
            const detail::ExprInfo& e = rules_.exprs[rule.weight];
            throw Error(SourceLoc{system_.fileName, e.line, e.column},
                        "negative weight " + std::to_string(w) + " from '" + e.text +
                            "' (derivation step " + std::to_string(step_) +
                            "); expected a weight >= 0");
        }
        candidateSlots_.resize((candidates_.size() + 1) * stride);
        std::copy(slots_.begin(), slots_.end(), candidateSlots_.end() - stride);
        candidates_.emplace_back(k, w);
        total += w;
    }
    if (!(total > 0.0)) return copyModule(in, in.modules[index], out);
    double x = rng_.uniform01() * total;
    std::size_t pick = 0;
    double sum = 0.0;
    for (std::size_t c = 0; c < candidates_.size(); ++c) {
        if (candidates_[c].second <= 0.0) continue;
        pick = c;
        sum += candidates_[c].second;
        if (x < sum) break;
    }
    std::copy(candidateSlots_.begin() + pick * stride,
              candidateSlots_.begin() + (pick + 1) * stride, slots_.begin());
    emit(rules_.rules[candidates_[pick].first], out);
}

void Deriver::emit(const Rule& rule, ModuleString& out) {
    const std::size_t count = rule.moduleEnd - rule.moduleBegin;
    const std::size_t paramCount = rule.paramEnd - rule.paramBegin;
    ensureRoom(out, count, paramCount);
    const Module* tmpl = rules_.successorModules.data() + rule.moduleBegin;
    if (!rule.successorHasParams) {
        out.modules.insert(out.modules.end(), tmpl, tmpl + count);
        return;
    }
    // Copy the template, moving parameter offsets to the end of the output's parameters,
    // then fill in the parameters computed from this module's actual values.
    const auto base = static_cast<std::uint32_t>(out.params.size());
    for (std::size_t k = 0; k < count; ++k) {
        Module m = tmpl[k];
        if (m.paramCount) m.paramOffset += base;
        out.modules.push_back(m);
    }
    const double* constants = rules_.successorParams.data() + rule.paramBegin;
    for (std::size_t k = 0; k < paramCount; ++k) out.params.push_back(constants[k]);
    for (std::uint32_t d = rule.dynamicBegin; d < rule.dynamicEnd; ++d) {
        const detail::DynamicParam& dp = rules_.dynamicParams[d];
        out.params[base + dp.paramIndex] = evalExpr(static_cast<std::int32_t>(dp.expr));
    }
}

double Deriver::evalExpr(std::int32_t expr) {
    const detail::ExprInfo& e = rules_.exprs[expr];
    const detail::Instr* code = rules_.code.data();
    double value = 0.0;
    detail::EvalStatus status =
        detail::evaluateExpr(code + e.codeBegin, code + e.codeEnd, slots_.data(), rng_, value);
    if (status != detail::EvalStatus::Ok) failEval(expr, status);
    return value;
}

void Deriver::failEval(std::int32_t expr, detail::EvalStatus status) const {
    const detail::ExprInfo& e = rules_.exprs[expr];
    std::string where = "'" + e.text + "' (derivation step " + std::to_string(step_) + " of " +
                        std::to_string(steps_) + ")";
    if (status == detail::EvalStatus::DivisionByZero) {
        throw Error(SourceLoc{system_.fileName, e.line, e.column},
                    "division by zero in " + where + "; expected a non-zero divisor");
    }
    throw Error(SourceLoc{system_.fileName, e.line, e.column},
                "no finite value (NaN or infinity) in " + where +
                    "; expected arguments inside each function's domain and no overflow");
}

void Deriver::grow(ModuleString& out, std::size_t modules, std::size_t params) {
    std::size_t needModules = out.modules.size() + modules;
    std::size_t needParams = out.params.size() + params;
    if (needModules > maxModules_ || needParams > maxParams_) failLimit();
    if (wordBytes(inModules_, inParams_) + wordBytes(needModules, needParams) > maxMemory_) {
        failMemory(inModules_, inParams_, needModules, needParams);
    }
    if (needModules > out.modules.capacity()) {
        std::size_t cap = std::max(needModules, out.modules.capacity() * 2);
        reserveWord(out.modules, std::min(cap, maxModules_));
    }
    if (needParams > out.params.capacity()) {
        std::size_t cap = std::max(needParams, out.params.capacity() * 2);
        reserveWord(out.params, std::min(cap, maxParams_));
    }
    setRoom(out);
}

// The memory left after both words' contents is split between modules and parameters, so any
// sizes within the room keep the total under maxMemoryBytes; grow() re-splits what is left
// once one of them fills up (a few dozen times per step at most: the room halves each time).
void Deriver::setRoom(const ModuleString& out) {
    const std::size_t used =
        wordBytes(inModules_, inParams_) + wordBytes(out.modules.size(), out.params.size());
    const std::size_t half = (maxMemory_ - std::min(used, maxMemory_)) / 2;
    moduleRoom_ = std::min(out.modules.capacity(), out.modules.size() + half / kModuleBytes);
    paramRoom_ = std::min(out.params.capacity(), out.params.size() + half / kParamBytes);
}

void Deriver::failLimit() const {
    throw Error(SourceLoc{system_.fileName, 0, 0},
                "derivation step " + std::to_string(step_) + " of " + std::to_string(steps_) +
                    " would exceed the module limit of " + std::to_string(maxModules_) +
                    " modules (or " + std::to_string(maxParams_) +
                    " parameter values); expected fewer derivations, or raise the limit with "
                    "--max-modules (DeriveOptions::maxModules)");
}

void Deriver::failMemory(std::size_t inModules, std::size_t inParams, std::size_t outModules,
                         std::size_t outParams) const {
    const auto mib = [](std::size_t bytes) {
        return std::to_string((bytes + (std::size_t{1} << 20) - 1) >> 20) + " MiB";
    };
    throw Error(SourceLoc{system_.fileName, 0, 0},
                "derivation step " + std::to_string(step_) + " of " + std::to_string(steps_) +
                    " would exceed the memory limit of " + mib(maxMemory_) + " (" +
                    std::to_string(maxMemory_) +
                    " bytes) for its words: " + std::to_string(inModules) + " modules with " +
                    std::to_string(inParams) + " parameter values rewritten into at least " +
                    std::to_string(outModules) + " modules with " + std::to_string(outParams) +
                    " values; expected fewer derivations or parameters, or raise the limit "
                    "with --max-memory (DeriveOptions::maxMemoryBytes)");
}

}  // namespace

ModuleString deriveLSystem(const LSystem& system, const DeriveOptions& options) {
    if (!system.rules) {  // a default-constructed LSystem: nothing to rewrite
        return system.axiom;
    }
    Deriver deriver(system, options);
    return deriver.run();
}

}  // namespace ramus
