// Typed reading of JSON inputs (studio requests, batch manifests): every message names the
// JSON path and what was expected. Errors are ramus::Error.
#pragma once

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "ramus/error.hpp"

namespace ramus::cli {

inline void requireObject(const nlohmann::json& value, const std::string& path) {
    if (!value.is_object()) {
        throw Error(path + ": expected a JSON object, got " + std::string(value.type_name()));
    }
}

/// The member `key` of `object` if present; Error when it has another JSON type.
inline const nlohmann::json* optionalMember(const nlohmann::json& object, const std::string& key,
                                            nlohmann::json::value_t type) {
    const auto it = object.find(key);
    if (it == object.end() || it->is_null()) return nullptr;
    const bool numeric = type == nlohmann::json::value_t::number_float && it->is_number();
    if (it->type() != type && !numeric) {
        throw Error(key + ": expected " + nlohmann::json(type).type_name() + ", got " +
                    std::string(it->type_name()));
    }
    return &*it;
}

inline std::string requiredString(const nlohmann::json& object, const std::string& key) {
    const auto* value = optionalMember(object, key, nlohmann::json::value_t::string);
    if (!value) throw Error(key + ": expected a string, but it is missing");
    return value->get<std::string>();
}

/// A finite number in [lo, hi].
inline double numberIn(const nlohmann::json& value, const std::string& path, double lo, double hi) {
    if (!value.is_number()) {
        throw Error(path + ": expected a number, got " + std::string(value.type_name()));
    }
    const double x = value.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi) {
        throw Error(path + ": expected a number in [" + nlohmann::json(lo).dump() + ", " +
                    nlohmann::json(hi).dump() + "], got " + value.dump());
    }
    return x;
}

/// An integer in [lo, hi].
inline int integerIn(const nlohmann::json& value, const std::string& path, int lo, int hi) {
    if (!value.is_number_integer()) {
        throw Error(path + ": expected an integer in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "], got " + value.dump());
    }
    const auto x = value.get<std::int64_t>();
    if (x < lo || x > hi) {
        throw Error(path + ": expected an integer in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "], got " + value.dump());
    }
    return static_cast<int>(x);
}

inline bool boolean(const nlohmann::json& value, const std::string& path) {
    if (!value.is_boolean()) {
        throw Error(path + ": expected true or false, got " + value.dump());
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
    throw Error(path + ": expected a non-negative integer seed, got " + value.dump());
}

/// An optional string member parsed by `parse` (returning std::optional); `fallback` when
/// absent, Error naming the key and the accepted values when unknown.
template <typename Enum, typename Parse>
Enum choice(const nlohmann::json& object, const std::string& key, Enum fallback, Parse parse,
            const std::string& expected) {
    const auto* value = optionalMember(object, key, nlohmann::json::value_t::string);
    if (!value) return fallback;
    const auto parsed = parse(value->get<std::string>());
    if (!parsed) throw Error(key + ": expected " + expected + ", got " + value->dump());
    return *parsed;
}

}  // namespace ramus::cli
