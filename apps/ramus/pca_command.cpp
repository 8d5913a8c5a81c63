// `ramus pca report|sample`: the skeleton statistics' figures and plots, and random feature
// points (optionally conditioned) for exploring the model.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "ramus/error.hpp"
#include "ramus/skeleton_stats.hpp"

namespace ramus::cli {

namespace {

struct PcaOptions {
    std::string speciesFile;  // empty = built-in data
    bool json = false;
    std::string plotsDir;
    // sample
    int count = 1;
    std::uint64_t seed = 1;
    std::vector<std::string> conditions;
    double jitter = 1.0;
    std::string example;
    bool vary = false;
    std::string spread = "model";
};

SkeletonStats loadStats(const PcaOptions& o) {
    return o.speciesFile.empty() ? SkeletonStats::builtin() : SkeletonStats::load(o.speciesFile);
}

std::string sourceName(const PcaOptions& o) {
    return o.speciesFile.empty() ? "built-in (seed 000 appendix A.1)" : o.speciesFile;
}

nlohmann::ordered_json reportJson(const PcaReport& r, const PcaOptions& o,
                                  const std::vector<std::string>& plots) {
    nlohmann::ordered_json j;
    j["species_source"] = sourceName(o);
    j["species_count"] = r.speciesCount;
    j["eigenvalues"] = r.eigenvalues;
    j["eigenvalues_above_0_01"] = r.eigenvaluesAbove001;
    j["eigenvalues_above_0_001"] = r.eigenvaluesAbove0001;
    j["explained_6"] = r.explained6;
    j["explained_10"] = r.explained10;
    j["explained_20"] = r.explained20;
    j["mean_wings"] = r.meanFeatures.wings;
    j["mean_legs"] = r.meanFeatures.legs;
    j["mean_weight_kg"] = r.meanFeatures.weightKg;
    j["nearest"] = r.nearest;
    j["nearest_distance"] = r.nearestDistance;
    j["farthest"] = r.farthest;
    j["farthest_distance"] = r.farthestDistance;
    j["second_farthest"] = r.secondFarthest;
    j["second_farthest_distance"] = r.secondFarthestDistance;
    nlohmann::ordered_json top = nlohmann::ordered_json::array();
    for (const auto& entries : r.topEntries) {
        nlohmann::ordered_json axis = nlohmann::ordered_json::array();
        for (const EigenvectorEntry& e : entries) {
            axis.push_back({{"feature", featureName(e.feature)}, {"value", e.value}});
        }
        top.push_back(axis);
    }
    j["top_eigenvector_entries"] = top;
    if (!plots.empty()) j["plots"] = plots;
    return j;
}

void printReport(const PcaReport& r, const PcaOptions& o, const std::vector<std::string>& plots) {
    std::printf("species: %d, %s\n", r.speciesCount, sourceName(o).c_str());
    std::printf("eigenvalues (descending):");
    for (std::size_t i = 0; i < r.eigenvalues.size(); ++i) {
        std::printf("%s%.5g", i % 8 == 0 ? "\n  " : " ", r.eigenvalues[i]);
    }
    std::printf("\neigenvalues > 0.01: %d, > 0.001: %d\n", r.eigenvaluesAbove001,
                r.eigenvaluesAbove0001);
    std::printf("explained variance: 6 components %.2f %%, 10: %.2f %%, 20: %.2f %%\n",
                100 * r.explained6, 100 * r.explained10, 100 * r.explained20);
    std::printf("mean: wings %.3f, legs %.2f, weight %.1f kg\n", r.meanFeatures.wings,
                r.meanFeatures.legs, r.meanFeatures.weightKg);
    std::printf("nearest to the mean: %s (distance %.4f)\n", r.nearest.c_str(), r.nearestDistance);
    std::printf("farthest from the mean: %s (%.4f), then %s (%.4f)\n", r.farthest.c_str(),
                r.farthestDistance, r.secondFarthest.c_str(), r.secondFarthestDistance);
    std::printf("largest entries of the first %zu eigenvectors:\n", r.topEntries.size());
    for (std::size_t i = 0; i < r.topEntries.size(); ++i) {
        std::printf("  %zu (eigenvalue %.5g):", i + 1, r.eigenvalues[i]);
        for (const EigenvectorEntry& e : r.topEntries[i]) {
            std::printf(" %s %+.3f", featureName(e.feature).c_str(), e.value);
        }
        std::printf("\n");
    }
    for (const std::string& p : plots) std::printf("wrote %s\n", p.c_str());
}

void runReport(const PcaOptions& o) {
    const SkeletonStats stats = loadStats(o);
    const PcaReport report = makePcaReport(stats);
    std::vector<std::string> plots;
    if (!o.plotsDir.empty()) plots = writePcaPlots(stats, o.plotsDir);
    if (o.json) {
        std::printf("%s\n", reportJson(report, o, plots).dump(2).c_str());
    } else {
        printReport(report, o, plots);
    }
}

// "legs=1" → Condition in user units; the names are featureName()s.
Condition parseCondition(const std::string& text, double jitter) {
    const std::size_t eq = text.find('=');
    const std::string name = text.substr(0, eq);
    const auto feature = parseFeatureName(name);
    std::size_t used = 0;
    double value = 0;
    if (eq != std::string::npos) {
        try {
            value = std::stod(text.substr(eq + 1), &used);
        } catch (const std::exception&) {
            used = 0;
        }
    }
    if (!feature || eq == std::string::npos || used == 0 || used != text.size() - eq - 1) {
        throw Error("--condition: invalid condition '" + text +
                    "'; expected FEATURE=VALUE in the feature's unit, e.g. legs=1, wings=0, "
                    "neck_y_length=150, tail_x_length=300, weight=50");
    }
    if (!std::isfinite(value)) {
        throw Error("--condition: the value of '" + text +
                    "' is not finite; expected a finite number");
    }
    return Condition{*feature, value, jitter};
}

nlohmann::ordered_json pointJson(const Eigen::VectorXd& point) {
    const SkeletonFeatures f = fromFeaturePoint(point);
    nlohmann::ordered_json j;
    j["point"] = std::vector<double>(point.data(), point.data() + point.size());
    nlohmann::ordered_json spine = nlohmann::ordered_json::array();
    for (const Vec2& p : f.spine) spine.push_back({p.x(), p.y()});
    j["spine"] = spine;
    j["wings"] = f.wings;
    j["legs"] = f.legs;
    nlohmann::ordered_json limbs;
    for (int i = 0; i < kLimbCount; ++i)
        limbs[std::string(limbName(static_cast<Limb>(i)))] = f.limbs[i];
    j["limbs"] = limbs;
    j["weight_kg"] = f.weightKg;
    return j;
}

void runSample(const PcaOptions& o) {
    const SkeletonStats stats = loadStats(o);
    std::vector<Condition> conditions;
    for (const std::string& c : o.conditions) conditions.push_back(parseCondition(c, o.jitter));
    if (!o.example.empty() && !conditions.empty()) {
        throw Error("--example and --condition cannot be combined; expected one of them");
    }
    const ConditionalModel model = stats.condition(conditions);
    const Eigen::VectorXd example =
        o.example.empty() ? Eigen::VectorXd() : stats.fromExample(o.example);
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (int i = 0; i < o.count; ++i) {
        Rng rng = Rng::forStream(o.seed, static_cast<std::uint64_t>(i));
        Eigen::VectorXd point;
        if (!o.example.empty()) {
            point = o.vary ? stats.vary(example, rng) : example;
        } else {
            point = model.sample(rng,
                                 o.spread == "thesis" ? SampleSpread::Thesis : SampleSpread::Model);
        }
        out.push_back(pointJson(point));
    }
    std::printf("%s\n", out.dump(o.json ? 2 : -1).c_str());
}

}  // namespace

void addPcaCommand(CLI::App& app) {
    auto o = std::make_shared<PcaOptions>();
    CLI::App* cmd = app.add_subcommand("pca", "skeleton statistics: PCA over the species data");
    cmd->require_subcommand(1);

    CLI::App* report = cmd->add_subcommand(
        "report", "eigenvalues, explained variance, mean, nearest/farthest species, plots");
    report->add_option("--species", o->speciesFile, "species file (default: the built-in data)");
    report->add_flag("--json", o->json, "print one JSON object");
    report->add_option("--plots", o->plotsDir, "write the diagnostic figures (SVG) into DIR");
    report->callback([o] { runReport(*o); });

    CLI::App* sample = cmd->add_subcommand(
        "sample",
        "random skeleton feature points as JSON (one per --count), deterministic per seed");
    sample->add_option("--species", o->speciesFile, "species file (default: the built-in data)");
    sample->add_option("-n,--count", o->count, "how many points")->check(CLI::Range(1, 1000000));
    sample->add_option("--seed", o->seed, "seed; point i uses stream i")->capture_default_str();
    sample->add_option("--condition", o->conditions,
                       "FEATURE=VALUE in user units (px, pairs, kg), e.g. legs=1 (repeatable)");
    sample
        ->add_option("--jitter", o->jitter,
                     "width of the uniform offset added to each condition (thesis: 1)")
        ->check(finiteNumber(0.0, true, kHugeNumber, "a finite number >= 0"))
        ->capture_default_str();
    sample->add_option("--example", o->example, "the feature point of a species (by name)");
    sample->add_flag("--vary", o->vary, "with --example: variations N(q_i, lambda_i/2)");
    sample
        ->add_option("--spread", o->spread,
                     "model: q_i ~ N(0, lambda_i) (default); thesis: q_i = lambda_i N(0, 1), as "
                     "the thesis's implementation (closer to the mean)")
        ->check(CLI::IsMember({"model", "thesis"}));
    sample->add_flag("--pretty", o->json, "indent the JSON");
    sample->callback([o] { runSample(*o); });
}

}  // namespace ramus::cli
