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

#include "ramus/error.hpp"
#include "serve/studio_api.hpp"
#include "tree_output.hpp"

namespace ramus::studio {

using cli::StageTimer;

inline void requireObject(const nlohmann::json& value, const std::string& path) {
    if (!value.is_object()) {
        throw ApiError(400,
                       path + ": expected a JSON object, got " + std::string(value.type_name()));
    }
}

/// The member `key` of `object` if present; ApiError when it has another JSON type.
inline const nlohmann::json* optionalMember(const nlohmann::json& object, const std::string& key,
                                            nlohmann::json::value_t type) {
    const auto it = object.find(key);
    if (it == object.end() || it->is_null()) return nullptr;
    const bool numeric = type == nlohmann::json::value_t::number_float && it->is_number();
    if (it->type() != type && !numeric) {
        throw ApiError(400, key + ": expected " + nlohmann::json(type).type_name() + ", got " +
                                std::string(it->type_name()));
    }
    return &*it;
}

inline std::string requiredString(const nlohmann::json& object, const std::string& key) {
    const auto* value = optionalMember(object, key, nlohmann::json::value_t::string);
    if (!value) throw ApiError(400, key + ": expected a string, but it is missing");
    return value->get<std::string>();
}

/// A finite number in [lo, hi].
inline double numberIn(const nlohmann::json& value, const std::string& path, double lo, double hi) {
    if (!value.is_number()) {
        throw ApiError(400, path + ": expected a number, got " + std::string(value.type_name()));
    }
    const double x = value.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi) {
        throw ApiError(400, path + ": expected a number in [" + nlohmann::json(lo).dump() + ", " +
                                nlohmann::json(hi).dump() + "], got " + value.dump());
    }
    return x;
}

/// An integer in [lo, hi].
inline int integerIn(const nlohmann::json& value, const std::string& path, int lo, int hi) {
    if (!value.is_number_integer()) {
        throw ApiError(400, path + ": expected an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got " + value.dump());
    }
    const auto x = value.get<std::int64_t>();
    if (x < lo || x > hi) {
        throw ApiError(400, path + ": expected an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got " + value.dump());
    }
    return static_cast<int>(x);
}

inline bool boolean(const nlohmann::json& value, const std::string& path) {
    if (!value.is_boolean()) {
        throw ApiError(400, path + ": expected true or false, got " + value.dump());
    }
    return value.get<bool>();
}

/// A seed: a non-negative integer, or a decimal string for values above 2^53.
inline std::uint64_t seedFrom(const nlohmann::json& value, const std::string& path) {
    if (value.is_number_unsigned()) return value.get<std::uint64_t>();
    if (value.is_string()) {
        const std::string text = value.get<std::string>();
        std::size_t used = 0;
        try {
            const unsigned long long seed = std::stoull(text, &used);
            if (used == text.size() && !text.empty() && text[0] != '-') return seed;
        } catch (const std::exception&) {
        }
    }
    throw ApiError(400, path + ": expected a non-negative integer seed, got " + value.dump());
}

/// Runs `work`; a ramus::Error becomes a 400 ApiError carrying file, line and column.
template <typename Work>
auto withTextErrors(Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const Error& e) {
        nlohmann::json where = nlohmann::json::object();
        if (!e.loc().file.empty()) where["file"] = e.loc().file;
        if (e.loc().line > 0) where["line"] = e.loc().line;
        if (e.loc().column > 0) where["column"] = e.loc().column;
        throw ApiError(400, e.what(), std::move(where));
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
