// Species vocabulary: class and limb names, lookup by name, the built-in data set.
#include "ramus/species.hpp"

#include <algorithm>
#include <cctype>

namespace ramus {

namespace {
constexpr std::string_view kClassNames[] = {"fish", "amphibian", "reptile", "bird", "mammal"};
constexpr std::string_view kLimbNames[] = {"upper_arm", "forearm", "hand",
                                           "thigh",     "shank",   "foot"};

// ASCII case-insensitive comparison; other bytes (UTF-8 umlauts) must match exactly.
bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const auto ca = static_cast<unsigned char>(a[i]);
        const auto cb = static_cast<unsigned char>(b[i]);
        if (std::tolower(ca) != std::tolower(cb)) return false;
    }
    return true;
}
}  // namespace

std::string_view animalClassName(AnimalClass animalClass) {
    return kClassNames[static_cast<int>(animalClass)];
}

std::optional<AnimalClass> parseAnimalClass(std::string_view name) {
    for (int i = 0; i < 5; ++i) {
        if (kClassNames[i] == name) return static_cast<AnimalClass>(i);
    }
    return std::nullopt;
}

std::string_view limbName(Limb limb) { return kLimbNames[static_cast<int>(limb)]; }

const SpeciesRecord* findSpecies(const std::vector<SpeciesRecord>& species, std::string_view name) {
    const auto it = std::find_if(species.begin(), species.end(), [&](const SpeciesRecord& r) {
        return equalsIgnoreCase(r.name, name) ||
               (!r.nameDe.empty() && equalsIgnoreCase(r.nameDe, name));
    });
    return it == species.end() ? nullptr : &*it;
}

const std::vector<SpeciesRecord>& builtinSpecies() {
    // Parsed once on first use; immutable afterwards (a function-local constant, not mutable
    // global state). The text is checked by tests, so parsing cannot fail.
    static const std::vector<SpeciesRecord> species =
        parseSpeciesJson(builtinSpeciesJson(), "<builtin species.json>");
    return species;
}

}  // namespace ramus
