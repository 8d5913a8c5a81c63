// Based on: seed 002 §2.3.3 (3D turtle, eq 2.7–2.16), §2.4.1 (turtle builds a tree), §2.4.2
// (tropism, eq 2.18–2.19); ABOP §1.5 (brackets), §2.2 (p.57 `$`), §2.3 (p.58 tropism as a
// rotation), §1.9.1 / §5.1 (polygons `{ . }`).
#include "ramus/turtle.hpp"

#include <cmath>
#include <cstring>

#include "ramus/error.hpp"

namespace ramus {

namespace {

enum class Op : std::uint8_t {
    None,
    Draw,        // F
    Move,        // f
    MoveSilent,  // G: moves, never records a polygon vertex
    TurnLeft,    // +
    TurnRight,   // -
    PitchDown,   // &
    PitchUp,     // ^
    RollLeft,    // '\'
    RollRight,   // /
    TurnAround,  // |
    Level,       // $
    Push,        // [
    Pop,         // ]
    Width,       // !
    PolyBegin,   // {
    PolyEnd,     // }
    PolyVertex,  // .
};

Op opForName(const std::string& name) {
    static constexpr struct {
        const char* name;
        Op op;
    } kOps[] = {{"F", Op::Draw},       {"f", Op::Move},      {"G", Op::MoveSilent},
                {"+", Op::TurnLeft},   {"-", Op::TurnRight}, {"&", Op::PitchDown},
                {"^", Op::PitchUp},    {"\\", Op::RollLeft}, {"/", Op::RollRight},
                {"|", Op::TurnAround}, {"$", Op::Level},     {"[", Op::Push},
                {"]", Op::Pop},        {"!", Op::Width},     {"{", Op::PolyBegin},
                {"}", Op::PolyEnd},    {".", Op::PolyVertex}};
    for (const auto& entry : kOps) {
        if (name == entry.name) return entry.op;
    }
    return Op::None;
}

// `!` without a parameter thins the branch (ABOP fig 1.25 uses it that way).
constexpr double kWidthDecay = 0.7;
// Rotations are exact, but rounding drifts R away from orthonormal over millions of steps.
constexpr int kRotationsBetweenOrthonormalize = 64;

struct State {
    Vec3 position;
    Mat3 frame;  // columns H, L, U in world coordinates (seed 002 §2.3.3)
    NodeId node;
    double width;
};

// R_H, R_L, R_U of seed 002 eq 2.7–2.9, applied on the right: R' = R · R_axis(angle).
void rotateAboutHeading(Mat3& r, double c, double s) {
    const Vec3 l = r.col(1), u = r.col(2);
    r.col(1) = c * l - s * u;
    r.col(2) = s * l + c * u;
}
void rotateAboutLeft(Mat3& r, double c, double s) {
    const Vec3 h = r.col(0), u = r.col(2);
    r.col(0) = c * h - s * u;
    r.col(2) = s * h + c * u;
}
void rotateAboutUp(Mat3& r, double c, double s) {
    const Vec3 h = r.col(0), l = r.col(1);
    r.col(0) = c * h + s * l;
    r.col(1) = -s * h + c * l;
}

void orthonormalize(Mat3& r) {
    Vec3 h = r.col(0).normalized();
    Vec3 l = (r.col(1) - h * h.dot(r.col(1))).normalized();
    r.col(0) = h;
    r.col(1) = l;
    r.col(2) = h.cross(l);
}

// Interprets one word; owns the scratch state so the loop body stays small.
class Interpreter {
public:
    Interpreter(const SymbolTable& symbols, const TurtleParams& params) : params_(params) {
        ops_.reserve(symbols.names.size());
        for (const std::string& name : symbols.names) ops_.push_back(opForName(name));
        defaultCos_ = std::cos(degToRad(params.defaultAngleDegrees));
        defaultSin_ = std::sin(degToRad(params.defaultAngleDegrees));
        tropismDirection_ = params.tropism;
    }

    TurtleResult run(const ModuleString& word) {
        result_.tree.reserve(countDraws(word) + 1);
        state_.position = Vec3::Zero();
        state_.frame << 0, -1, 0,  // H = +Y (up), L = −X, U = +Z
            1, 0, 0,               //
            0, 0, 1;
        state_.width = params_.initialWidth;
        state_.node = result_.tree.addRoot(state_.position, state_.width * 0.5);
        for (const Module& m : word.modules) {
            const Op op = m.symbol < ops_.size() ? ops_[m.symbol] : Op::None;
            if (op != Op::None) apply(op, m, word);
        }
        return std::move(result_);
    }

private:
    std::size_t countDraws(const ModuleString& word) const {
        std::size_t n = 0;
        for (const Module& m : word.modules) {
            const Op op = m.symbol < ops_.size() ? ops_[m.symbol] : Op::None;
            n += (op == Op::Draw || op == Op::Move);
        }
        return n;
    }

    void apply(Op op, const Module& m, const ModuleString& word) {
        const double* args = word.paramsOf(m);
        const bool hasArg = m.paramCount > 0;
        switch (op) {
            case Op::Draw:
            case Op::Move:
            case Op::MoveSilent:
                forward(op, hasArg ? args[0] : params_.defaultStep);
                break;
            case Op::TurnLeft:
            case Op::TurnRight:
            case Op::PitchDown:
            case Op::PitchUp:
            case Op::RollLeft:
            case Op::RollRight:
                turn(op, hasArg, hasArg ? args[0] : 0.0);
                break;
            case Op::TurnAround:
                rotateAboutUp(state_.frame, -1.0, 0.0);
                break;
            case Op::Level:
                level();
                break;
            case Op::Push:
                stack_.push_back(state_);
                break;
            case Op::Pop:
                if (!stack_.empty()) {  // an unbalanced `]` is ignored
                    state_ = stack_.back();
                    stack_.pop_back();
                }
                break;
            case Op::Width:
                state_.width = hasArg ? args[0] : state_.width * kWidthDecay;
                break;
            case Op::PolyBegin:
            case Op::PolyEnd:
            case Op::PolyVertex:
                polygon(op);
                break;
            case Op::None:
                break;
        }
    }

    void forward(Op op, double length) {
        const Vec3 heading = state_.frame.col(0);
        Vec3 direction = heading;
        if (params_.susceptibility != 0.0 && params_.tropismMode == TropismMode::Blend) {
            // seed 002 eq 2.18: the step bends, the heading does not.
            const Vec3 bent = heading + params_.susceptibility * tropismDirection_;
            const double norm = bent.norm();
            if (norm > 1e-12) direction = bent / norm;
        }
        state_.position += length * direction;

        if (!polygonStarts_.empty()) {
            // Inside `{ }` moves only trace the polygon (ABOP §1.9.1); G traces silently.
            if (op != Op::MoveSilent) polygonScratch_.push_back(state_.position);
        } else if (op != Op::MoveSilent) {
            state_.node = result_.tree.addChild(state_.node, state_.position, state_.width * 0.5);
            if (op == Op::Move) result_.tree.node(state_.node).hidden = true;
        }
        if (op == Op::Draw && params_.susceptibility != 0.0 &&
            params_.tropismMode == TropismMode::Rotate) {
            bendTowardsTropism();
        }
    }

    // ABOP p.58: rotate the turtle by α = e·|H × T| about H × T after each drawn step.
    void bendTowardsTropism() {
        const Vec3 axis = state_.frame.col(0).cross(tropismDirection_);
        const double sinLike = axis.norm();
        if (sinLike < 1e-12) return;
        const double angle = params_.susceptibility * sinLike;
        const Mat3 rotation = Eigen::AngleAxisd(angle, axis / sinLike).toRotationMatrix();
        state_.frame = rotation * state_.frame;
        countRotation();
    }

    void turn(Op op, bool hasArg, double angleDegrees) {
        double c = defaultCos_, s = defaultSin_;
        if (hasArg) {
            if (angleDegrees != cachedAngle_) {
                cachedAngle_ = angleDegrees;
                cachedCos_ = std::cos(degToRad(angleDegrees));
                cachedSin_ = std::sin(degToRad(angleDegrees));
            }
            c = cachedCos_;
            s = cachedSin_;
        }
        switch (op) {
            case Op::TurnLeft:
                rotateAboutUp(state_.frame, c, s);
                break;
            case Op::TurnRight:
                rotateAboutUp(state_.frame, c, -s);
                break;
            case Op::PitchDown:
                rotateAboutLeft(state_.frame, c, s);
                break;
            case Op::PitchUp:
                rotateAboutLeft(state_.frame, c, -s);
                break;
            case Op::RollLeft:
                rotateAboutHeading(state_.frame, c, s);
                break;
            case Op::RollRight:
                rotateAboutHeading(state_.frame, c, -s);
                break;
            default:
                break;
        }
        countRotation();
    }

    // ABOP p.57: roll about H so that L is horizontal: L = V × H / |V × H|, U = H × L,
    // with V the world's up (+Y).
    void level() {
        const Vec3 heading = state_.frame.col(0);
        const Vec3 left = Vec3::UnitY().cross(heading);
        const double norm = left.norm();
        if (norm < 1e-9) return;  // heading vertical: every roll is level
        state_.frame.col(1) = left / norm;
        state_.frame.col(2) = heading.cross(state_.frame.col(1));
    }

    void polygon(Op op) {
        if (op == Op::PolyBegin) {
            polygonStarts_.push_back(polygonScratch_.size());
            polygonScratch_.push_back(state_.position);
            return;
        }
        if (polygonStarts_.empty()) return;  // `.` or `}` outside a polygon mean nothing
        if (op == Op::PolyVertex) {
            polygonScratch_.push_back(state_.position);
            return;
        }
        emitPolygon(polygonStarts_.back());
        polygonScratch_.resize(polygonStarts_.back());
        polygonStarts_.pop_back();
    }

    void emitPolygon(std::size_t first) {
        std::vector<Vec3>& out = result_.polygonVertices;
        const std::size_t begin = out.size();
        for (std::size_t i = first; i < polygonScratch_.size(); ++i) {
            // `{.` and `.` after a traced move record the same point twice: keep it once.
            if (out.size() > begin && (out.back() - polygonScratch_[i]).norm() < 1e-12) continue;
            out.push_back(polygonScratch_[i]);
        }
        if (out.size() - begin >= 2 && (out.back() - out[begin]).norm() < 1e-12) out.pop_back();
        if (out.size() - begin < 3) {
            out.resize(begin);
            return;
        }
        result_.polygonOffsets.push_back(static_cast<std::uint32_t>(out.size()));
        result_.polygonNodes.push_back(state_.node);
    }

    void countRotation() {
        if (++rotationsSinceOrthonormalize_ >= kRotationsBetweenOrthonormalize) {
            orthonormalize(state_.frame);
            rotationsSinceOrthonormalize_ = 0;
        }
    }

    const TurtleParams& params_;
    std::vector<Op> ops_;
    double defaultCos_ = 1.0, defaultSin_ = 0.0;
    double cachedAngle_ = std::nan(""), cachedCos_ = 1.0, cachedSin_ = 0.0;
    Vec3 tropismDirection_;
    State state_{};
    std::vector<State> stack_;
    std::vector<std::size_t> polygonStarts_;
    std::vector<Vec3> polygonScratch_;
    int rotationsSinceOrthonormalize_ = 0;
    TurtleResult result_;
};

}  // namespace

TurtleParams turtleParamsFrom(const LSystemSettings& settings) {
    TurtleParams params;
    params.defaultStep = settings.step;
    params.defaultAngleDegrees = settings.angleDegrees;
    params.initialWidth = settings.width;
    params.tropism = settings.tropism;
    params.susceptibility = settings.susceptibility;
    params.tropismMode = settings.tropismMode;
    return params;
}

TurtleResult interpretTurtle(const ModuleString& word, const SymbolTable& symbols,
                             const TurtleParams& params) {
    return Interpreter(symbols, params).run(word);
}

}  // namespace ramus
