// Based on: a plain switch-dispatched stack machine over postfix code (Aho, Lam, Sethi, Ullman,
// "Compilers", §2.8). Trigonometric functions take and return degrees, as in cpfg.
#include <cmath>

#include "lsystem/expression.hpp"

namespace ramus::detail {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

double unaryFunction(Op op, double x) {
    switch (op) {
        case Op::Sin:
            return std::sin(x * kDegToRad);
        case Op::Cos:
            return std::cos(x * kDegToRad);
        case Op::Tan:
            return std::tan(x * kDegToRad);
        case Op::Asin:
            return std::asin(x) * kRadToDeg;
        case Op::Acos:
            return std::acos(x) * kRadToDeg;
        case Op::Atan:
            return std::atan(x) * kRadToDeg;
        case Op::Sqrt:
            return std::sqrt(x);
        case Op::Abs:
            return std::fabs(x);
        case Op::Exp:
            return std::exp(x);
        case Op::Log:
            return std::log(x);
        case Op::Floor:
            return std::floor(x);
        case Op::Ceil:
            return std::ceil(x);
        case Op::Round:
            return std::round(x);
        default:
            return x;
    }
}

}  // namespace

EvalStatus evaluate(const Instr* pc, const Instr* end, const double* slots, Rng& rng,
                    double& result) {
    double stack[kEvalStackSize];
    double* sp = stack;  // next free entry; every value on the stack is finite
    while (pc != end) {
        switch (pc->op) {
            case Op::Const:
                *sp++ = pc->value;
                break;
            case Op::Slot:
                *sp++ = slots[pc->arg];
                break;
            case Op::Neg:
                sp[-1] = -sp[-1];
                break;
            case Op::Not:
                sp[-1] = sp[-1] == 0.0 ? 1.0 : 0.0;
                break;
            case Op::ToBool:
                sp[-1] = sp[-1] != 0.0 ? 1.0 : 0.0;
                break;
            case Op::Add:
                --sp;
                sp[-1] += sp[0];
                break;
            case Op::Sub:
                --sp;
                sp[-1] -= sp[0];
                break;
            case Op::Mul:
                --sp;
                sp[-1] *= sp[0];
                break;
            case Op::Div:
                --sp;
                if (sp[0] == 0.0) return EvalStatus::DivisionByZero;
                sp[-1] /= sp[0];
                break;
            case Op::Mod:
                --sp;
                if (sp[0] == 0.0) return EvalStatus::DivisionByZero;
                sp[-1] = std::fmod(sp[-1], sp[0]);
                break;
            case Op::Pow:
                --sp;
                sp[-1] = std::pow(sp[-1], sp[0]);
                break;
            case Op::Lt:
                --sp;
                sp[-1] = sp[-1] < sp[0] ? 1.0 : 0.0;
                break;
            case Op::Le:
                --sp;
                sp[-1] = sp[-1] <= sp[0] ? 1.0 : 0.0;
                break;
            case Op::Gt:
                --sp;
                sp[-1] = sp[-1] > sp[0] ? 1.0 : 0.0;
                break;
            case Op::Ge:
                --sp;
                sp[-1] = sp[-1] >= sp[0] ? 1.0 : 0.0;
                break;
            case Op::Eq:
                --sp;
                sp[-1] = sp[-1] == sp[0] ? 1.0 : 0.0;
                break;
            case Op::Ne:
                --sp;
                sp[-1] = sp[-1] != sp[0] ? 1.0 : 0.0;
                break;
            case Op::AndJump:
                if (sp[-1] == 0.0) {
                    pc += pc->arg;
                    continue;
                }
                --sp;  // the stack may now be empty: skip the finiteness check
                ++pc;
                continue;
            case Op::OrJump:
                if (sp[-1] != 0.0) {
                    sp[-1] = 1.0;
                    pc += pc->arg;
                    continue;
                }
                --sp;
                ++pc;
                continue;
            case Op::Atan2:
                --sp;
                sp[-1] = std::atan2(sp[-1], sp[0]) * kRadToDeg;
                break;
            case Op::Min:
                --sp;
                sp[-1] = sp[0] < sp[-1] ? sp[0] : sp[-1];
                break;
            case Op::Max:
                --sp;
                sp[-1] = sp[0] > sp[-1] ? sp[0] : sp[-1];
                break;
            case Op::Rand:
                *sp++ = rng.uniform01();
                break;
            case Op::Uniform:
                --sp;
                sp[-1] = rng.uniform(sp[-1], sp[0]);
                break;
            case Op::Gauss:
                --sp;
                sp[-1] = rng.gauss(sp[-1], sp[0]);
                break;
            case Op::AddSC:
                *sp++ = slots[pc->arg] + pc->value;
                break;
            case Op::SubSC:
                *sp++ = slots[pc->arg] - pc->value;
                break;
            case Op::MulSC:
                *sp++ = slots[pc->arg] * pc->value;
                break;
            case Op::DivSC:
                *sp++ = slots[pc->arg] / pc->value;
                break;  // value != 0 (compiler)
            case Op::RSubSC:
                *sp++ = pc->value - slots[pc->arg];
                break;
            case Op::RDivSC:
                if (slots[pc->arg] == 0.0) return EvalStatus::DivisionByZero;
                *sp++ = pc->value / slots[pc->arg];
                break;
            default:
                sp[-1] = unaryFunction(pc->op, sp[-1]);
                break;
        }
        // Arithmetic can overflow and functions can leave their domain: stop at the first
        // non-finite value so it never reaches a module parameter or a comparison.
        if (!std::isfinite(sp[-1])) return EvalStatus::NonFinite;
        ++pc;
    }
    result = sp[-1];
    return EvalStatus::Ok;
}

}  // namespace ramus::detail
