// Reading studio requests: typed members with the JSON path in every message, the time budget,
// and ramus::Error → ApiError with the text position (studio_api.hpp).
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "json_inputs.hpp"
#include "ramus/error.hpp"
#include "serve/studio_api.hpp"
#include "tree_output.hpp"

namespace ramus::studio {

using cli::boolean;
using cli::integerIn;
using cli::numberIn;
using cli::optionalMember;
using cli::requiredString;
using cli::requireObject;
using cli::seedFrom;
using cli::StageTimer;

/// A ramus::Error as a 400 ApiError carrying file, line and column when known.
inline ApiError badRequest(const Error& e) {
    nlohmann::json where = nlohmann::json::object();
    if (!e.loc().file.empty()) where["file"] = e.loc().file;
    if (e.loc().line > 0) where["line"] = e.loc().line;
    if (e.loc().column > 0) where["column"] = e.loc().column;
    return ApiError(400, e.what(), std::move(where));
}

/// Runs `work`; a ramus::Error becomes a 400 ApiError carrying file, line and column.
template <typename Work>
auto withTextErrors(Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const Error& e) {
        throw badRequest(e);
    }
}

/// The request's time budget, checked between stages (a stage itself is bounded by the size
/// limits).
class Deadline {
public:
    explicit Deadline(double seconds)
        : seconds_(seconds),
          end_(std::chrono::steady_clock::now() +
               std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                   std::chrono::duration<double>(seconds))) {}
    void check(const std::string& stage) const {
        if (std::chrono::steady_clock::now() > end_) {
            throw ApiError(408, "the request ran past its time budget of " +
                                    nlohmann::json(seconds_).dump() + " s during " + stage +
                                    "; expected a smaller model");
        }
    }

private:
    double seconds_;
    std::chrono::steady_clock::time_point end_;
};

inline void checkTriangles(std::size_t triangles, const StudioLimits& limits) {
    if (triangles > limits.maxTriangles) {
        throw ApiError(413, "the model has " + std::to_string(triangles) +
                                " triangles; the studio allows at most " +
                                std::to_string(limits.maxTriangles) +
                                "; expected fewer derivations or points");
    }
}

/// The head kinds of the bone library, for the examples list.
nlohmann::json headKindNames();

}  // namespace ramus::studio
