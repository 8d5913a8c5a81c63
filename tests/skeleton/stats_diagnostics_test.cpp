// Diagnostics: the normal quantile function against known values, rankit Q-Q positions, the
// report, and the SVG figures (well-formed, deterministic).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "ramus/error.hpp"
#include "ramus/file_util.hpp"
#include "ramus/skeleton_stats.hpp"
#include "skeleton/svg_xml.hpp"

namespace ramus {
namespace {

TEST(StatsDiagnostics, NormalQuantileMatchesKnownValues) {
    EXPECT_DOUBLE_EQ(normalQuantile(0.5), 0.0);
    EXPECT_NEAR(normalQuantile(0.975), 1.959963984540054, 1e-15);
    EXPECT_NEAR(normalQuantile(0.025), -1.959963984540054, 1e-15);
    EXPECT_NEAR(normalQuantile(0.8413447460685429), 1.0, 1e-14);    // Φ(1)
    EXPECT_NEAR(normalQuantile(0.15), -1.0364333894937898, 1e-14);  // central/tail boundary
    EXPECT_NEAR(normalQuantile(1e-10), -6.361340902404056, 1e-12);
    // Far tail (r > 5); value from Python's statistics.NormalDist().inv_cdf.
    EXPECT_NEAR(normalQuantile(1e-300), -37.0470962993612, 1e-12);
    EXPECT_EQ(normalQuantile(0.0), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(normalQuantile(1.0), std::numeric_limits<double>::infinity());
}

TEST(StatsDiagnostics, QqPointsUseRankitPositions) {
    const std::vector<double> values = {3.0, 1.0, 2.0, 4.0};
    const QqPoints qq = qqPoints(values);
    EXPECT_EQ(qq.sample, (std::vector<double>{1, 2, 3, 4}));
    ASSERT_EQ(qq.theoretical.size(), 4u);
    EXPECT_NEAR(qq.theoretical[0], normalQuantile(0.125), 1e-15);  // (1 − 0.5)/4
    EXPECT_NEAR(qq.theoretical[3], normalQuantile(0.875), 1e-15);
    EXPECT_NEAR(qq.theoretical[1], -qq.theoretical[2], 1e-15);
    EXPECT_TRUE(qqPoints(std::vector<double>{}).sample.empty());
}

TEST(StatsDiagnostics, ReportCarriesTheThesisFigures) {
    const PcaReport r = makePcaReport(SkeletonStats::builtin());
    EXPECT_EQ(r.speciesCount, 44);
    ASSERT_EQ(r.eigenvalues.size(), 29u);
    EXPECT_EQ(r.eigenvaluesAbove001, 7);
    EXPECT_EQ(r.eigenvaluesAbove0001, 17);
    EXPECT_NEAR(r.explained6, 0.9224, 5e-5);
    EXPECT_NEAR(r.explained10, 0.9693, 5e-5);
    EXPECT_NEAR(r.explained20, 0.9980, 5e-5);
    EXPECT_EQ(r.nearest, "Rock hyrax");
    EXPECT_EQ(r.farthest, "Snake");
    EXPECT_LT(r.nearestDistance, r.secondFarthestDistance);
    EXPECT_LT(r.secondFarthestDistance, r.farthestDistance);
    for (const auto& entries : r.topEntries) {
        ASSERT_EQ(entries.size(), 4u);
        for (std::size_t i = 1; i < entries.size(); ++i) {
            EXPECT_GE(std::abs(entries[i - 1].value), std::abs(entries[i].value));
        }
    }
}

TEST(StatsDiagnostics, PlotsAreWellFormedAndDeterministic) {
    const std::filesystem::path dir =
        std::filesystem::path(RAMUS_BINARY_DIR) / "test_output" / "pca_plots";
    const SkeletonStats stats = SkeletonStats::builtin();
    const std::vector<std::string> files = writePcaPlots(stats, dir.string());
    ASSERT_EQ(files.size(), 10u);
    for (const std::string& file : files) {
        const std::string text = readFile(file);
        const detail::XmlDocument doc = detail::parseXml(text, file);
        EXPECT_EQ(doc.elements.front().name, "svg") << file;
        EXPECT_GT(doc.elements.size(), 20u) << file;
        EXPECT_EQ(text.find("nan"), std::string::npos) << file;
        EXPECT_EQ(text.find("inf"), std::string::npos) << file;
    }
    const std::vector<std::string> again = writePcaPlots(stats, (dir / "again").string());
    for (std::size_t i = 0; i < files.size(); ++i)
        EXPECT_EQ(readFile(files[i]), readFile(again[i]));
    if (const char* out = std::getenv("RAMUS_TEST_OUTPUT")) writePcaPlots(stats, out);
}

TEST(StatsDiagnostics, PlotsIntoAnUnwritablePlaceFail) {
    EXPECT_THROW(writePcaPlots(SkeletonStats::builtin(), "/proc/ramus-cannot-write-here"), Error);
}

}  // namespace
}  // namespace ramus
