// Point lists and teach-in points share one reader: headers, byte-order marks and bad cells are
// handled the same way for both.

#include <gtest/gtest.h>

#include "io/number_rows.h"
#include "io/path_csv.h"

namespace cam {
namespace {

const RowShape kPlane{{"x", "y"}, 2};

TEST(NumberRows, AByteOrderMarkIsSkippedNotTakenForAHeader) {
    // Before, the BOM made the first line non-numeric, so it was dropped as a header: the path
    // lost its first point and came out 100 mm long instead of 200 mm.
    const auto points = parsePathCsv(
        "\xEF\xBB\xBF"
        "0,0,0\n100,0,0\n200,0,0\n");
    ASSERT_TRUE(points.ok()) << points.errors().front().text();
    ASSERT_EQ(points.value().size(), 3u);
    EXPECT_EQ(points.value().front().position.x(), 0.0);
}

TEST(NumberRows, OnlyALineWithoutAnyNumberIsAHeader) {
    const auto withHeader = parseNumberRows("x, y\n1, 2\n3, 4\n", kPlane);
    ASSERT_TRUE(withHeader.ok());
    EXPECT_EQ(withHeader.value(), (std::vector<std::vector<double>>{{1, 2}, {3, 4}}));
    // A letter O for a zero is a typing mistake, not a header: it is reported where it is.
    const auto typo = parseNumberRows("O,0,0\n10,0,0\n", {{"x", "y", "z", "bulge"}, 3});
    ASSERT_FALSE(typo.ok());
    EXPECT_EQ(typo.errors().front().text(), "line 1: x must be a finite number (got \"O\")");
}

TEST(NumberRows, CountsAndBadCellsAreLocatedByLine) {
    const auto rows = parseNumberRows("1, 2\n\n3\n4, nan\n5, 6, 7\n", kPlane);
    ASSERT_FALSE(rows.ok());
    std::vector<std::string> texts;
    for (const Diagnostic& d : rows.errors()) texts.push_back(d.text());
    EXPECT_EQ(texts, (std::vector<std::string>{"line 3: expected x,y (got 1 values)",
                                               "line 4: y must be a finite number (got \"nan\")",
                                               "line 5: expected x,y (got 3 values)"}));
    const auto path = parsePathCsv("0,0,0,1,9\n");
    ASSERT_FALSE(path.ok());
    EXPECT_EQ(path.errors().front().text(), "line 1: expected x,y,z or x,y,z,bulge (got 5 values)");
}

}  // namespace
}  // namespace cam
