// The streaming JSON writer and the validating compact copier used for GLB documents: string
// escaping (RFC 8259 §7), UTF-8 checks (RFC 3629 §4), shortest round-trip numbers, nesting and
// commas, and every kind of invalid extras text.
#include "io/json_writer.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "ramus/error.hpp"
#include "ramus/rng.hpp"

namespace ramus::io {
namespace {

std::string jsonString(std::string_view text) {
    std::string out;
    EXPECT_TRUE(appendJsonString(out, text));
    return out;
}

TEST(JsonWriter, EscapesQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(jsonString("plain"), "\"plain\"");
    EXPECT_EQ(jsonString("a\"b\\c"), R"("a\"b\\c")");
    EXPECT_EQ(jsonString("\b\f\n\r\t"), R"("\b\f\n\r\t")");
    EXPECT_EQ(jsonString(std::string("\x01\x1f\x00", 3)), R"("\u0001\u001f\u0000")");
    EXPECT_EQ(jsonString("/ and \x7f stay"), "\"/ and \x7f stay\"");
}

TEST(JsonWriter, EveryControlCharacterRoundTripsThroughAJsonParser) {
    std::string text;
    for (int c = 0; c < 0x20; ++c) text += static_cast<char>(c);
    text += "\"\\";
    EXPECT_EQ(nlohmann::json::parse(jsonString(text)).get<std::string>(), text);
}

TEST(JsonWriter, PassesValidUtf8Through) {
    // ß (2 bytes), € (3 bytes), U+1F98E (4 bytes), U+10FFFF (the largest code point).
    const std::string text = "Wirbels\u00e4ule \u20ac \U0001F98E \U0010FFFF";
    EXPECT_EQ(jsonString(text), "\"" + text + "\"");
}

TEST(JsonWriter, RejectsInvalidUtf8AndLeavesTheOutputUnchanged) {
    for (const char* bad : {"\x80", "a\xC3", "\xC0\xAF", "\xE0\x80\xAF", "\xED\xA0\x80",
                            "\xF4\x90\x80\x80", "\xF8\x88\x80\x80\x80", "\xE2\x82"}) {
        std::string out = "x";
        EXPECT_FALSE(appendJsonString(out, bad)) << bad;
        EXPECT_EQ(out, "x");
    }
}

TEST(JsonWriter, StringValueWithInvalidUtf8IsAnError) {
    std::string out;
    JsonWriter w(out);
    EXPECT_THROW(w.value(std::string_view("\xFF")), Error);
}

TEST(JsonWriter, NumbersAreShortestAndReadBackExactly) {
    std::string out;
    appendJsonNumber(out, 0.1f);
    out += ' ';
    appendJsonNumber(out, 0.1);
    out += ' ';
    appendJsonNumber(out, -2.0);
    out += ' ';
    appendJsonNumber(out, 1e-8f);
    EXPECT_EQ(out, "0.1 0.1 -2 1e-8");
    Rng rng(11);
    for (int i = 0; i < 2000; ++i) {
        const double d = rng.uniform(-1.0, 1.0) * std::pow(10.0, rng.uniform(-30.0, 30.0));
        const auto f = static_cast<float>(d);
        std::string dt, ft;
        appendJsonNumber(dt, d);
        appendJsonNumber(ft, f);
        double dBack = 0.0;
        float fBack = 0.0f;
        std::from_chars(dt.data(), dt.data() + dt.size(), dBack);
        std::from_chars(ft.data(), ft.data() + ft.size(), fBack);
        EXPECT_EQ(dBack, d) << dt;
        EXPECT_EQ(fBack, f) << ft;
        EXPECT_TRUE(nlohmann::json::accept(dt)) << dt;
        EXPECT_TRUE(nlohmann::json::accept(ft)) << ft;
    }
    std::string extremes;
    appendJsonNumber(extremes, std::numeric_limits<double>::max());
    EXPECT_EQ(nlohmann::json::parse(extremes).get<double>(), std::numeric_limits<double>::max());
}

// Floats go through detail::writeShortest: text that reads back as the same float, whole
// numbers as integers, −0 as "0" (tests/core/float_text_test.cpp checks the formatter itself).
TEST(JsonWriter, FloatsReadBackExactlyWithNegativeZeroAsZero) {
    auto written = [](float f) {
        std::string out;
        appendJsonNumber(out, f);
        return out;
    };
    auto readsBack = [&](float f) {
        const std::string text = written(f);
        EXPECT_TRUE(nlohmann::json::accept(text)) << text;
        EXPECT_EQ(std::strtof(text.c_str(), nullptr), f) << text;
    };
    for (int i = -1200; i <= 1200; ++i) {
        const auto f = static_cast<float>(i);
        if (std::abs(i) < 1000) EXPECT_EQ(written(f), std::to_string(i));
        readsBack(f);
        readsBack(f + 0.5f);
    }
    EXPECT_EQ(written(-0.0f), "0");
    EXPECT_EQ(written(999.0f), "999");
    EXPECT_EQ(written(1e6f), "1e6");  // beyond the integer path: the shorter notation
    Rng rng(12);
    for (int i = 0; i < 2000; ++i) {
        readsBack(
            static_cast<float>(rng.uniform(-1.0, 1.0) * std::pow(10.0, rng.uniform(-20.0, 20.0))));
    }
    std::string array;
    JsonWriter w(array);
    const float values[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.25f, 1e-8f};
    w.numbers(values, 6);
    EXPECT_EQ(array, "[0,0,1,-1,0.25,1e-8]");
}

// numbers() batches its text: arrays longer than one batch (16) keep every element and comma.
TEST(JsonWriter, LongNumberArraysKeepEveryElement) {
    std::vector<double> values;
    for (int i = 0; i < 100; ++i) values.push_back(-std::numeric_limits<double>::max() / (i + 1));
    std::string out;
    JsonWriter w(out);
    w.numbers(values.data(), values.size());
    const nlohmann::json back = nlohmann::json::parse(out);
    ASSERT_EQ(back.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(back[i].get<double>(), values[i]);
}

TEST(JsonWriter, NestsObjectsAndArraysWithCommasInTheRightPlaces) {
    std::string out;
    JsonWriter w(out);
    w.beginObject();
    w.key("a");
    w.value(1);
    w.key("b");
    w.beginArray();
    w.beginArray();
    w.endArray();
    w.beginObject();
    w.endObject();
    w.value(true);
    w.value("s");
    w.endArray();
    w.key("c");
    w.beginObject();
    w.key("d");
    const float v[3] = {0.5f, -1.0f, 2.25f};
    w.numbers(v, 3);
    w.endObject();
    w.key("e");
    w.rawValue(R"({"x":null})");
    w.key("f");
    w.value(std::uint64_t{18446744073709551615u});
    w.endObject();
    EXPECT_EQ(out, R"({"a":1,"b":[[],{},true,"s"],"c":{"d":[0.5,-1,2.25]},"e":{"x":null},)"
                   R"("f":18446744073709551615})");
    EXPECT_TRUE(nlohmann::json::accept(out));
}

TEST(JsonWriter, CompactCopyRemovesWhitespaceOutsideStringsOnly) {
    std::string out;
    EXPECT_EQ(appendCompactJson(out, " { \"a b\" : [ 1 , -2.5e+3 ,\t\"x\\\" y\" ] ,\n\"c\":{} } "),
              "");
    EXPECT_EQ(out, R"({"a b":[1,-2.5e+3,"x\" y"],"c":{}})");
}

TEST(JsonWriter, CompactCopyKeepsCompactTextByteForByte) {
    const std::string text =
        R"({"kind":"vertebra","n":[0,-0.5,1E5,2e-3],"u":"\u00e9\ud83e\udd8e","t":true,"f":false,"z":null})";
    std::string out;
    EXPECT_EQ(appendCompactJson(out, text), "");
    EXPECT_EQ(out, text);
    EXPECT_EQ(nlohmann::json::parse(out), nlohmann::json::parse(text));
}

TEST(JsonWriter, CompactCopyAcceptsExactlyWhatAJsonParserAccepts) {
    const char* cases[] = {"{}",
                           "[]",
                           "0",
                           "-0",
                           "\"\"",
                           "{\"a\":1}",
                           "[1,[2,[3]]]",
                           "",
                           " ",
                           "{",
                           "{\"a\"}",
                           "{\"a\":}",
                           "{\"a\":1,}",
                           "[1,]",
                           "[1 2]",
                           "01",
                           "1.",
                           ".5",
                           "+1",
                           "1e",
                           "-",
                           "tru",
                           "nul",
                           "\"a",
                           "\"\\x\"",
                           "\"\\u12G4\"",
                           "\"\\ud800\"",
                           "\"\\udc00\"",
                           "\"\\ud800\\u0041\"",
                           "\"tab\there\"",
                           "{\"a\":1}}",
                           "[\"\xC3\xA9\"]",
                           "[\"\xC3\"]",
                           "{'a':1}",
                           "[1]x"};
    for (const char* text : cases) {
        std::string out = "keep";
        const std::string error = appendCompactJson(out, text);
        EXPECT_EQ(error.empty(), nlohmann::json::accept(text)) << text << ": " << error;
        if (!error.empty()) EXPECT_EQ(out, "keep") << text;
    }
}

TEST(JsonWriter, CompactCopyErrorNamesTheByteAndWhatWasExpected) {
    std::string out;
    EXPECT_EQ(appendCompactJson(out, R"({"limb": )"),
              "byte 9: expected a JSON value, got the end of the text");
    EXPECT_EQ(appendCompactJson(out, R"({"a":1;})"), "byte 6: expected ',' or '}', got ';'");
    EXPECT_EQ(appendCompactJson(out, "[\"\x01\"]"),
              "byte 2: expected an escaped control character, got byte 0x01");
}

TEST(JsonWriter, CompactCopyLimitsNestingDepth) {
    std::string out;
    EXPECT_EQ(appendCompactJson(out, std::string(256, '[') + std::string(256, ']')), "");
    const std::string error =
        appendCompactJson(out, std::string(100000, '[') + std::string(100000, ']'));
    EXPECT_NE(error.find("at most 256 nested"), std::string::npos) << error;
}

}  // namespace
}  // namespace ramus::io
