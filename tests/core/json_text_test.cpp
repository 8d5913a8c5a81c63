// JSON text with located errors (src/core/json_text.hpp), used by every JSON reader.
#include "core/json_text.hpp"

#include <gtest/gtest.h>

namespace ramus::detail {
namespace {

TEST(JsonText, ASyntaxErrorNamesFileLineAndColumn) {
    try {
        parseJsonText("{\n  \"a\": 1,\n  \"b\": ]\n}", "c.json");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().file, "c.json");
        EXPECT_EQ(e.loc().line, 3);
        EXPECT_EQ(e.loc().column, 8);
        EXPECT_NE(std::string(e.what()).find("invalid JSON"), std::string::npos);
    }
}

TEST(JsonText, ANumberBeyondDoubleIsAnErrorAtTheNumber) {
    // nlohmann reports the overflow without a position; found by fuzzing (it escaped as a
    // non-ramus exception before).
    try {
        parseJsonText("{\n  \"influence_radius\": 1e400\n}", "c.json");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_EQ(e.loc().column, 23);
        EXPECT_NE(std::string(e.what()).find("number '1e400' is out of range"), std::string::npos)
            << e.what();
    }
}

// Line 1 "{", line 2 the "a" object, line 3 the list; columns are 1-based.
constexpr const char* kNested =
    "{\n  \"s\": \"x}]\\\"{\", \"a\": {\"b\": 1, \"c\": [10, {\"d\": true}]},\n  \"list\": [ 1,  2 "
    "]\n}";

TEST(JsonText, ValuesAreLocatedByTheirPath) {
    const SourceLoc c = jsonValueLoc(kNested, {"a", "c"}, "f.json");
    EXPECT_EQ(c.file, "f.json");
    EXPECT_EQ(c.line, 2);
    EXPECT_EQ(c.column, 37);
    const SourceLoc d = jsonValueLoc(kNested, {"a", "c", "1", "d"}, "f.json");
    EXPECT_EQ(d.line, 2);
    EXPECT_EQ(d.column, 48);
    const SourceLoc second = jsonValueLoc(kNested, {"list", "1"}, "f.json");
    EXPECT_EQ(second.line, 3);
    EXPECT_EQ(second.column, 17);
}

TEST(JsonText, AMissingKeyIsLocatedAtItsObject) {
    const SourceLoc missing = jsonValueLoc(kNested, {"a", "zzz"}, "f.json");
    EXPECT_EQ(missing.line, 2);
    EXPECT_EQ(missing.column, 23);  // the "a" object's brace
    const SourceLoc past = jsonValueLoc(kNested, {"list", "5"}, "f.json");
    EXPECT_EQ(past.line, 3);
    EXPECT_EQ(past.column, 11);
    const SourceLoc root = jsonValueLoc(kNested, {"nope"}, "f.json");
    EXPECT_EQ(root.line, 1);
    EXPECT_EQ(root.column, 1);
}

}  // namespace
}  // namespace ramus::detail
