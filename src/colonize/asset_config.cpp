// The asset keys of colonization configs (issue 9; docs/colonize.md "Leaves, wind, LODs" and
// "Root systems"): the "leaves" object, the asset keys of "mesh", "ground" and "root_growth".
#include <algorithm>

#include "colonize/config_reader.hpp"

namespace ramus::colonize_detail {

void parseLeaves(const ConfigReader& r, const Json& j, LeafParams& l) {
    if (!j.is_object()) r.fail("leaves", "expected an object, got " + j.dump());
    r.checkKeys(j, "leaves",
                {"shape", "per_tip", "per_length", "zone", "size", "width_ratio", "size_variation",
                 "phyllotaxis", "tilt", "jitter", "seed", "atlas"},
                "");
    const double kMax = ConfigReader::kMax;
    if (j.contains("shape")) {
        if (!j["shape"].is_string() || (j["shape"] != "card" && j["shape"] != "blade")) {
            r.fail("leaves.shape", "expected \"card\" or \"blade\", got " + j["shape"].dump());
        }
        l.shape = parseLeafShape(j["shape"].get<std::string>());
    }
    if (j.contains("per_tip")) {
        l.perTip =
            static_cast<int>(r.integer(j["per_tip"], "leaves.per_tip", 0, 1000, "leaves per tip"));
    }
    auto number = [&](const char* key, double& out, double lo, double hi, bool open,
                      const char* units) {
        if (j.contains(key))
            out = r.number(j[key], ConfigReader::join("leaves", key), lo, hi, open, units);
    };
    number("per_length", l.perLength, 0.0, kMax, false, "leaves per model unit");
    number("zone", l.zone, 0.0, kMax, false, "model units from a tip; 0 = 4 leaf lengths");
    number("size", l.size, 0.0, kMax, false, "leaf length, model units; 0 = mean edge length");
    number("width_ratio", l.widthRatio, 0.0, 4.0, true, "width / length");
    number("size_variation", l.sizeVariation, 0.0, 0.999, false, "fraction");
    number("phyllotaxis", l.phyllotaxisDegrees, -360.0, 360.0, false, "degrees");
    number("tilt", l.tiltDegrees, -180.0, 180.0, false, "degrees");
    number("jitter", l.jitterDegrees, 0.0, 180.0, false, "degrees");
    if (j.contains("seed")) l.seed = r.seed(j["seed"], "leaves.seed");
    if (j.contains("atlas")) {
        const Json& a = j["atlas"];
        if (!a.is_array() || a.size() != 4) {
            r.fail("leaves.atlas", "expected [u0, v0, u1, v1], got " + a.dump());
        }
        for (std::size_t i = 0; i < 4; ++i) {
            l.atlas[i] = static_cast<float>(
                r.number(a[i], "leaves.atlas[" + std::to_string(i) + "]", 0.0, 1.0, false, "uv"));
        }
        if (!(l.atlas[2] > l.atlas[0] && l.atlas[3] > l.atlas[1])) {
            r.fail("leaves.atlas", "expected u1 > u0 and v1 > v0, got " + a.dump());
        }
    }
}

void parseMeshAssetKeys(const ConfigReader& r, const Json& j, ColonizeConfig::MeshOverrides& m) {
    if ((m.hasUvAspect = j.contains("uv_aspect"))) {
        m.uvAspect = r.number(j["uv_aspect"], "mesh.uv_aspect", 0.0, 1e6, true,
                              "bark texture height / width");
    }
    if ((m.hasWind = j.contains("wind"))) m.wind = r.boolean(j["wind"], "mesh.wind");
    if ((m.hasTextures = j.contains("textures")))
        m.textures = r.boolean(j["textures"], "mesh.textures");
    if ((m.hasWeld = j.contains("weld"))) m.weld = r.boolean(j["weld"], "mesh.weld");
    if ((m.hasSolidUnion = j.contains("union"))) {
        m.solidUnion = r.boolean(j["union"], "mesh.union");
        if (m.solidUnion && m.hasWeld && !m.weld) {
            r.fail("mesh.union",
                   "unites the welded bark, so expected \"weld\": true or no "
                   "\"weld\" key, got \"weld\": false");
        }
    }
    if ((m.hasConvexJunctions = j.contains("convex_junctions"))) {
        m.convexJunctions = r.boolean(j["convex_junctions"], "mesh.convex_junctions");
    }
    if (j.contains("lods")) {
        const Json& list = j["lods"];
        if (!list.is_array() || list.empty() || list.size() > 16) {
            r.fail("mesh.lods",
                   "expected 1 to 16 triangle ratios, e.g. [1, 0.4, 0.15], got " + list.dump());
        }
        for (std::size_t i = 0; i < list.size(); ++i) {
            m.lods.push_back(r.number(list[i], "mesh.lods[" + std::to_string(i) + "]", 0.0, 1.0,
                                      true, "fraction of LOD 0's triangles"));
        }
    }
}

void parseRootSystem(const ConfigReader& r, const Json& j, ColonizeConfig& c) {
    c.rootGrowth = c.params;
    c.rootGrowth.tropism = Vec3::Zero();
    if ((c.hasGround = j.contains("ground"))) {
        c.ground = r.number(j["ground"], "ground", ConfigReader::kLowest, ConfigReader::kMax, false,
                            "height y of the ground, model units");
    }
    if (!j.contains("root_growth")) return;
    if (!c.hasGround) r.fail("root_growth", "needs \"ground\" (the height below which roots grow)");
    const Json& g = j["root_growth"];
    if (!g.is_object()) r.fail("root_growth", "expected an object, got " + g.dump());
    r.checkKeys(g, "root_growth",
                {"influence_radius", "kill_radius", "step", "tropism", "max_iterations",
                 "max_degree", "max_branch_depth", "max_no_growth", "weighted_growth"},
                "");
    parseGrowthKeys(r, g, c.rootGrowth, "root_growth");
}

}  // namespace ramus::colonize_detail
