// The species file format: the shipped data, exact round trips, and one test per error case,
// each checking that the message names the file, the record and the field.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/species.hpp"

namespace ramus {
namespace {

using Json = nlohmann::ordered_json;

const std::string kDataFile = std::string(RAMUS_SOURCE_DIR) + "/data/species/species.json";

Json validFile() {
    return Json::parse(R"({
      "format": "ramus-species", "version": 1,
      "species": [{
        "name": "Test animal", "name_de": "Testtier", "class": "mammal",
        "wings": 0, "legs": 2, "weight_kg": 12.5,
        "spine": [[0, 1], [2, 3], [4, 5], [6, 7], [8, 9], [10, 11], [12, 13], [14, 15],
                  [16, 17], [18, 19]],
        "limbs": {"upper_arm": 1, "forearm": 2, "hand": 3, "thigh": 4, "shank": 5, "foot": 6}
      }]})");
}

// The error message for a file edited by `edit`, or "(no error)".
std::string errorFor(const std::function<void(Json&)>& edit) {
    Json file = validFile();
    edit(file);
    try {
        parseSpeciesJson(file.dump(2), "test.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

std::string errorForText(const std::string& text) {
    try {
        parseSpeciesJson(text, "test.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

#define EXPECT_CONTAINS(text, part) \
    EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)

TEST(SpeciesJson, ValidFileParses) {
    const auto species = parseSpeciesJson(validFile().dump(), "test.json");
    ASSERT_EQ(species.size(), 1u);
    EXPECT_EQ(species[0].name, "Test animal");
    EXPECT_EQ(species[0].nameDe, "Testtier");
    EXPECT_EQ(species[0].animalClass, AnimalClass::Mammal);
    EXPECT_EQ(species[0].features.spine[9], Vec2(18, 19));
    EXPECT_EQ(species[0].features.limb(Limb::Foot), 6);
    EXPECT_EQ(species[0].features.weightKg, 12.5);
}

TEST(SpeciesJson, EmptySpeciesListIsValid) {
    EXPECT_TRUE(parseSpeciesJson(R"({"format":"ramus-species","version":1,"species":[]})", "e.json")
                    .empty());
}

TEST(SpeciesJson, BuiltinDataIsTheShippedFile) {
    EXPECT_EQ(builtinSpeciesJson(), readFile(kDataFile))
        << "data/species/species.json changed: run data/species/embed.sh";
    EXPECT_EQ(builtinSpecies(), loadSpeciesFile(kDataFile));
}

TEST(SpeciesJson, ShippedFileHasTheThesisSpecies) {
    const auto& species = builtinSpecies();
    ASSERT_EQ(species.size(), 44u);
    int winged = 0;
    for (const SpeciesRecord& r : species) winged += r.features.wings > 0;
    EXPECT_EQ(winged, 7);
    const SpeciesRecord* hyrax = findSpecies(species, "klippschliefer");
    ASSERT_NE(hyrax, nullptr);
    EXPECT_EQ(hyrax->name, "Rock hyrax");
    EXPECT_EQ(hyrax->features.weightKg, 4);
    EXPECT_EQ(findSpecies(species, "SNAKE")->animalClass, AnimalClass::Reptile);
    EXPECT_EQ(findSpecies(species, "Dodo"), nullptr);
}

TEST(SpeciesJson, WriterReproducesTheShippedFileByteForByte) {
    const Json header = Json::parse(readFile(kDataFile));
    EXPECT_EQ(writeSpeciesJson(builtinSpecies(), header["attribution"].get<std::string>()),
              readFile(kDataFile));
}

TEST(SpeciesJson, WriteThenParseIsLossless) {
    std::vector<SpeciesRecord> species = builtinSpecies();
    species[0].notes = "quotes \" and \\ and ünïcode";
    species[1].features.spine[4] = Vec2(0.1 + 0.2, 1.0 / 3.0);
    species[2].features.weightKg = 1e-7;
    EXPECT_EQ(parseSpeciesJson(writeSpeciesJson(species), "w.json"), species);
}

TEST(SpeciesJson, LoadReportsAMissingFile) {
    EXPECT_THROW(loadSpeciesFile("/nonexistent/species.json"), Error);
}

TEST(SpeciesJson, MalformedJsonGivesLineAndColumn) {
    const std::string message = errorForText("{\n  \"format\": ,\n}");
    EXPECT_CONTAINS(message, "test.json:2:");
    EXPECT_CONTAINS(message, "invalid JSON");
}

TEST(SpeciesJson, NumberOutOfRangeIsAnError) {
    EXPECT_CONTAINS(errorForText(R"({"format":"ramus-species","version":1e999})"), "test.json");
}

TEST(SpeciesJson, RootMustBeAnObject) {
    EXPECT_CONTAINS(errorForText("[1, 2]"), "expected a JSON object, got [1,2]");
}

TEST(SpeciesJson, FormatIsRequired) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f.erase("format"); }),
                    "test.json: species file: format: missing field");
}

TEST(SpeciesJson, FormatMustBeRamusSpecies) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["format"] = "csv"; }),
                    "expected \"ramus-species\", got \"csv\"");
}

TEST(SpeciesJson, VersionMustBeOne) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["version"] = 2; }), "version: expected 1");
}

TEST(SpeciesJson, UnknownTopLevelFieldIsAnError) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["specis"] = 1; }), "specis: unknown field");
}

TEST(SpeciesJson, OnlyTheThesisFrameIsSupported) {
    EXPECT_CONTAINS(
        errorFor([](Json& f) {
            f["frame"] = {{"width", 500}, {"height", 1000}, {"y_axis", "up"}, {"head", "-x"}};
        }),
        "frame: expected");
}

TEST(SpeciesJson, SpeciesListIsRequired) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f.erase("species"); }), "species: missing field");
}

TEST(SpeciesJson, SpeciesMustBeAnArray) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"] = Json::object(); }),
                    "species: expected an array");
}

TEST(SpeciesJson, RecordMustBeAnObject) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"].push_back(3); }),
                    "species[1]: expected an object, got 3");
}

TEST(SpeciesJson, NameIsRequired) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0].erase("name"); }),
                    "species[0]: name: missing field");
}

TEST(SpeciesJson, NameMustNotBeEmpty) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["name"] = ""; }),
                    "name: expected a non-empty string");
}

TEST(SpeciesJson, UnknownRecordFieldNamesTheRecord) {
    EXPECT_CONTAINS(
        errorFor([](Json& f) { f["species"][0]["wingz"] = 1; }),
        "test.json: species[0] (Test animal): wingz: unknown field; expected one of name, name_de");
}

TEST(SpeciesJson, ClassMustBeKnown) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["class"] = "insect"; }),
                    "class: expected fish, amphibian, reptile, bird or mammal, got \"insect\"");
}

TEST(SpeciesJson, WingsAreRequired) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0].erase("wings"); }),
                    "(Test animal): wings: missing field");
}

TEST(SpeciesJson, LegsMustNotBeNegative) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["legs"] = -1; }),
                    "legs: expected a number >= 0, got -1");
}

TEST(SpeciesJson, WeightMustBeANumber) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["weight_kg"] = "4 t"; }),
                    "weight_kg: expected a number, got \"4 t\"");
}

TEST(SpeciesJson, SpineNeedsTenPoints) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["spine"].erase(0); }),
                    "spine: expected an array of 10 [x, y] points");
}

TEST(SpeciesJson, SpinePointNeedsTwoCoordinates) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["spine"][4] = {1}; }),
                    "spine[4]: expected [x, y] with two numbers, got [1]");
}

TEST(SpeciesJson, SpineCoordinateMustBeANumber) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["spine"][2][1] = nullptr; }),
                    "spine[2].y: expected a number, got null");
}

TEST(SpeciesJson, LimbsMustBeAnObject) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["limbs"] = {1, 2, 3, 4, 5, 6}; }),
                    "limbs: expected an object");
}

TEST(SpeciesJson, EveryLimbIsRequired) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["limbs"].erase("shank"); }),
                    "limbs.shank: missing field (0 = bone absent)");
}

TEST(SpeciesJson, UnknownLimbIsAnError) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["limbs"]["tibia"] = 3; }),
                    "limbs.tibia: unknown field; expected one of upper_arm");
}

TEST(SpeciesJson, LimbLengthMustNotBeNegative) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["limbs"]["hand"] = -0.5; }),
                    "limbs.hand: expected a number >= 0, got -0.5");
}

TEST(SpeciesJson, NotesMustBeAString) {
    EXPECT_CONTAINS(errorFor([](Json& f) { f["species"][0]["notes"] = 5; }),
                    "notes: expected a string, got 5");
}

TEST(SpeciesJson, DuplicateNamesAreRejectedCaseInsensitively) {
    const std::string message = errorFor([](Json& f) {
        Json copy = f["species"][0];
        copy["name"] = "TEST ANIMAL";
        copy["name_de"] = "Anderes";
        f["species"].push_back(copy);
    });
    EXPECT_CONTAINS(message,
                    "species[1] (TEST ANIMAL): name: duplicate species name \"TEST ANIMAL\"");
}

TEST(SpeciesJson, GermanNameMayNotRepeatAnotherRecordsName) {
    const std::string message = errorFor([](Json& f) {
        Json copy = f["species"][0];
        copy["name"] = "Other";
        copy["name_de"] = "test animal";
        f["species"].push_back(copy);
    });
    EXPECT_CONTAINS(message, "duplicate species name \"test animal\"");
}

TEST(SpeciesJson, ClassNamesRoundTrip) {
    for (AnimalClass c : {AnimalClass::Fish, AnimalClass::Amphibian, AnimalClass::Reptile,
                          AnimalClass::Bird, AnimalClass::Mammal}) {
        EXPECT_EQ(parseAnimalClass(animalClassName(c)), c);
    }
    EXPECT_FALSE(parseAnimalClass("Mammal").has_value());
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

TEST(SpeciesJsonNonFinite, ASpineCoordinateBeyondDoubleRangeIsLocatedAtTheNumber) {
    std::string text = validFile().dump(2);
    const std::size_t at = text.find("12.5");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 4, "1e999");
    const std::string message = errorForText(text);
    EXPECT_CONTAINS(message, "test.json:");
    EXPECT_CONTAINS(message, "number '1e999' is out of range");
}

TEST(SpeciesJsonNonFinite, NanIsNotJson) {
    const std::string message = errorForText("{\"format\": \"ramus-species\",\n \"version\": NaN}");
    EXPECT_CONTAINS(message, "test.json:2:");
}

}  // namespace
}  // namespace ramus
