#include "ramus/file_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ramus/error.hpp"

namespace ramus {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("ramus_test_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(FileUtil, WriteThenReadRoundTripsAndLeavesNoTempFile) {
    const fs::path dir = scratchDir("roundtrip");
    const std::string path = (dir / "a.bin").string();
    writeFileAtomic(path, std::string("he\0llo", 6));
    EXPECT_EQ(readFile(path), std::string("he\0llo", 6));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(FileUtil, WritingPartsWritesTheirConcatenation) {
    const fs::path dir = scratchDir("parts");
    const std::string path = (dir / "a.bin").string();
    const std::string_view parts[] = {"head", "", std::string_view("\0bin", 4)};
    writeFileAtomic(path, parts);
    EXPECT_EQ(readFile(path), std::string("head\0bin", 8));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// More pieces than one writev takes (64), empty ones among them, and one of several MB.
TEST(FileUtil, ManyPartsAreWrittenInOrder) {
    const fs::path dir = scratchDir("many_parts");
    const std::string path = (dir / "a.bin").string();
    std::vector<std::string> texts;
    for (int i = 0; i < 300; ++i) texts.push_back(i % 7 == 3 ? "" : std::to_string(i) + ",");
    texts[150] = std::string(std::size_t{5} << 20, 'x');
    std::vector<std::string_view> parts(texts.begin(), texts.end());
    std::string expected;
    for (const std::string& t : texts) expected += t;
    writeFileAtomic(path, parts);
    EXPECT_EQ(readFile(path, std::size_t{64} << 20), expected);
}

TEST(FileUtil, FailedWriteKeepsTheOldFileAndLeavesNothingBehind) {
    const fs::path dir = scratchDir("failed");
    const std::string path = (dir / "missing_dir" / "a.bin").string();
    EXPECT_THROW(writeFileAtomic(path, "x"), Error);
    EXPECT_FALSE(fs::exists(dir / "missing_dir"));
}

TEST(FileUtil, ReadingAMissingFileNamesIt) {
    try {
        readFile("/nonexistent/ramus.lsys");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/ramus.lsys"), std::string::npos);
    }
}

TEST(Error, MessageStartsWithFileLineAndColumn) {
    const Error e(SourceLoc{"tree.lsys", 3, 14}, "unknown symbol 'Q'; expected a module");
    EXPECT_STREQ(e.what(), "tree.lsys:3:14: unknown symbol 'Q'; expected a module");
    EXPECT_EQ(e.loc().line, 3);
}

}  // namespace
}  // namespace ramus

namespace ramus {
namespace {

TEST(FileUtilLimits, AFileUpToTheLimitIsReadAndALargerOneIsRefused) {
    const fs::path dir = scratchDir("read_limit");
    const std::string path = (dir / "ten.txt").string();
    writeFileAtomic(path, "0123456789");
    EXPECT_EQ(readFile(path, 10), "0123456789");
    try {
        readFile(path, 9);
        FAIL() << "expected the size limit";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": the file is larger than the input limit "
                                                     "of 9 bytes; expected a smaller file",
                                              0),
                  0u)
            << e.what();
    }
}

}  // namespace
}  // namespace ramus
