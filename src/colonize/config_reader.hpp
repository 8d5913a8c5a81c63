// The JSON reader of colonization configs (src/colonize/colonize_config.cpp), shared with the
// parsers of the asset keys (src/colonize/asset_config.cpp): typed values with located errors
// "FILE: KEY.PATH: what; expected …, got …".
#pragma once

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "ramus/colonize.hpp"
#include "ramus/error.hpp"

namespace ramus::colonize_detail {

using Json = nlohmann::json;

class ConfigReader {
public:
    explicit ConfigReader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& message) const {
        throw Error(file_ + ": " + path + ": " + message);
    }

    // Every key of `object` must be in `allowed`.
    void checkKeys(const Json& object, const std::string& path,
                   const std::set<std::string>& allowed, const std::string& context) const {
        for (auto it = object.begin(); it != object.end(); ++it) {
            if (allowed.count(it.key()) == 0) {
                std::string list;
                for (const std::string& k : allowed) list += (list.empty() ? "" : ", ") + k;
                fail(join(path, it.key()), "unknown key" + context + "; expected one of " + list);
            }
        }
    }

    double number(const Json& value, const std::string& path, double lo, double hi, bool loOpen,
                  const std::string& units) const {
        if (!value.is_number())
            fail(path, "expected a number (" + units + "), got " + value.dump());
        const double v = value.get<double>();
        const bool ok = std::isfinite(v) && (loOpen ? v > lo : v >= lo) && v <= hi;
        if (!ok)
            fail(path, "out of range; expected " + range(lo, hi, loOpen) + " (" + units +
                           "), got " + value.dump());
        return v;
    }

    std::int64_t integer(const Json& value, const std::string& path, std::int64_t lo,
                         std::int64_t hi, const std::string& meaning) const {
        if (!value.is_number_integer()) {
            fail(path, "expected an integer (" + meaning + "), got " + value.dump());
        }
        const bool isUnsigned = value.is_number_unsigned();
        const auto v =
            isUnsigned ? static_cast<std::int64_t>(std::min<std::uint64_t>(
                             value.get<std::uint64_t>(), std::numeric_limits<std::int64_t>::max()))
                       : value.get<std::int64_t>();
        if (v < lo || v > hi) {
            fail(path, "out of range; expected an integer in [" + std::to_string(lo) + ", " +
                           std::to_string(hi) + "] (" + meaning + "), got " + value.dump());
        }
        return v;
    }

    std::uint64_t seed(const Json& value, const std::string& path) const {
        if (!value.is_number_unsigned()) {
            fail(path, "expected a non-negative integer seed, got " + value.dump());
        }
        return value.get<std::uint64_t>();
    }

    bool boolean(const Json& value, const std::string& path) const {
        if (!value.is_boolean()) fail(path, "expected true or false, got " + value.dump());
        return value.get<bool>();
    }

    Vec3 vec3(const Json& value, const std::string& path, double lo, bool loOpen,
              const std::string& units) const {
        if (!value.is_array() || value.size() != 3) {
            fail(path,
                 "expected an array of 3 numbers [x, y, z] (" + units + "), got " + value.dump());
        }
        Vec3 v;
        for (std::size_t i = 0; i < 3; ++i) {
            v[static_cast<int>(i)] =
                number(value[i], path + "[" + std::to_string(i) + "]", lo, kMax, loOpen, units);
        }
        return v;
    }

    static std::string join(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }

    static constexpr double kMax = std::numeric_limits<double>::max();
    static constexpr double kLowest = std::numeric_limits<double>::lowest();

private:
    static std::string range(double lo, double hi, bool loOpen) {
        std::ostringstream out;
        if (hi == kMax) {
            out << (loOpen ? "> " : ">= ") << lo;
        } else {
            out << (loOpen ? "(" : "[") << lo << ", " << hi << "]";
        }
        return out.str();
    }

    std::string file_;
};

/// The growth keys (influence_radius … weighted_growth, not the roots) of object `j` into `p`;
/// error paths start with `prefix` ("" for the top level).
void parseGrowthKeys(const ConfigReader& r, const Json& j, ColonizeParams& p,
                     const std::string& prefix);

/// The config's "leaves" object into `leaves` (docs/colonize.md "Leaves").
void parseLeaves(const ConfigReader& r, const Json& j, LeafParams& leaves);

/// The asset keys of the "mesh" object (uv_aspect, wind, textures, lods) into `m`; the other
/// keys of "mesh" are read by colonize_config.cpp.
void parseMeshAssetKeys(const ConfigReader& r, const Json& j, ColonizeConfig::MeshOverrides& m);

/// "ground" and "root_growth": the underground root system.
void parseRootSystem(const ConfigReader& r, const Json& j, ColonizeConfig& c);

}  // namespace ramus::colonize_detail
