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

}  // namespace
}  // namespace ramus::detail
