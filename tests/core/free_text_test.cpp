// Free text on its way into an export (issue 27): export/free_text.h and the cam table's IEC
// 61131-3 identifier. Every expected string is written out here by hand from the rule.

#include <gtest/gtest.h>

#include <string>

#include "contour/contour.h"
#include "export/cam_table.h"
#include "export/free_text.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

using namespace std::string_literals;

TEST(FreeText, OneLineTurnsControlsIntoSpacesAndTrimsTheEnds) {
    EXPECT_EQ(oneLine("a\nb\tc\rd"), "a b c d");
    EXPECT_EQ(oneLine("  cam\n"), "cam");
    EXPECT_EQ(oneLine("a\0b"s), "a b");
    EXPECT_EQ(oneLine("\x1b[31mred\x7f"), "[31mred");
    EXPECT_EQ(oneLine("a\xC2\x85"
                      "b"),
              "a b");                                // NEL, a C1 control
    EXPECT_EQ(oneLine("a\u2028b\u2029c"), "a b c");  // line and paragraph separators
}

TEST(FreeText, OneLineDropsBidiControlsByteOrderMarksAndNoncharacters) {
    EXPECT_EQ(oneLine("\u202Eexe.txt\u200F"), "exe.txt");
    EXPECT_EQ(oneLine("\u2066x\u2069\u061C\u200E"), "x");
    EXPECT_EQ(oneLine("\uFEFFa\uFFFEb\uFFFFc\uFDD0d"), "abcd");
    EXPECT_EQ(oneLine("\xF4\x8F\xBF\xBE"), "");  // U+10FFFE
}

TEST(FreeText, OneLineReplacesInvalidUtf8ByteByByte) {
    const std::string r = "\xEF\xBF\xBD";  // U+FFFD
    EXPECT_EQ(oneLine("a\xFF"
                      "b"),
              "a" + r + "b");
    EXPECT_EQ(oneLine("\xC0\xAF"), r + r);                  // overlong '/'
    EXPECT_EQ(oneLine("\xED\xA0\x80"), r + r + r);          // a surrogate
    EXPECT_EQ(oneLine("\xF4\x90\x80\x80"), r + r + r + r);  // above U+10FFFF
    EXPECT_EQ(oneLine("\xE2\x82"), r + r);                  // cut short
}

TEST(FreeText, OneLineKeepsLettersAndEmojiAndCutsLongTextWithAnEllipsis) {
    EXPECT_EQ(oneLine("Hubstößel \U0001F680 ⚙"), "Hubstößel \U0001F680 ⚙");
    EXPECT_EQ(oneLine(std::string(200, 'x'), 10), "xxxxxxxxx…");
    EXPECT_EQ(oneLine("ääääääääääää", 5), "ääää…");
    EXPECT_EQ(oneLine(std::string(10, 'x'), 10), "xxxxxxxxxx");
    EXPECT_EQ(oneLine(std::string(100000, 'W')).size(), 119u + 3u);  // 119 W and "…"
}

TEST(FreeText, XmlTextEscapesMarkup) {
    EXPECT_EQ(xmlText("Cams & Co <b>\"x\" 'y'"),
              "Cams &amp; Co &lt;b&gt;&quot;x&quot; &apos;y&apos;");
    EXPECT_EQ(xmlText("a]]>b\0c"s), "a]]&gt;b c");
}

TEST(FreeText, CsvCommentTextStartsNoCellWithAFormula) {
    EXPECT_EQ(csvCommentText("=1+1"), "'=1+1");
    EXPECT_EQ(csvCommentText("a,=1; +2,@x, -3,b-c"), "a,'=1; '+2,'@x, '-3,b-c");
    EXPECT_EQ(csvCommentText("\"quoted\",\"=x\""), "'quoted','=x'");
    EXPECT_EQ(csvCommentText("cam\n=1+1"), "cam =1+1");  // one cell: no line break left
    EXPECT_EQ(csvCommentText("a\t=1"), "a =1");
}

/// The CODESYS cam table of the six-lobe example named `name`: the MC_CAM_REF's name.
std::string camVariableOf(const std::string& name) {
    auto project = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    EXPECT_TRUE(project.ok());
    const Contour contour = Contour::build(project.value()).value();
    CamTableOptions options;
    options.dialect = CamTableDialect::Codesys;
    options.points = 4;
    options.name = name;
    auto text = camTableText(contour, options);
    EXPECT_TRUE(text.ok());
    const std::string& st = text.value();
    const std::size_t at = st.find(" : MC_CAM_REF");
    if (at == std::string::npos) return "?";
    const std::size_t begin = st.rfind('\n', at) + 1;
    return st.substr(begin + 4, at - begin - 4);  // after the four spaces of indentation
}

TEST(CamTableIdentifier, AReservedWordOrADigitFirstGetsAPrefix) {
    EXPECT_EQ(camVariableOf("Six lobe"), "Six_lobe");
    EXPECT_EQ(camVariableOf("END_VAR"), "cam_END_VAR");
    EXPECT_EQ(camVariableOf("true"), "cam_true");
    EXPECT_EQ(camVariableOf("Mc_Cam_Ref"), "cam_Mc_Cam_Ref");
    EXPECT_EQ(camVariableOf("12345"), "cam_12345");
    EXPECT_EQ(camVariableOf("(* nested (* comment *) *)"), "nested_comment");
    EXPECT_EQ(camVariableOf("__a__b__"), "a_b");
    EXPECT_EQ(camVariableOf("Hubstößel"), "Hubst_el");
    EXPECT_EQ(camVariableOf("\U0001F680"), "cam");
    EXPECT_EQ(camVariableOf(""), "cam");
    EXPECT_EQ(camVariableOf(std::string(100000, 'W')), std::string(64, 'W'));
}

TEST(CamTableText, TheCsvHeaderKeepsItsLinesWhateverTheName) {
    auto project = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(project.ok());
    const Contour contour = Contour::build(project.value()).value();
    CamTableOptions options;
    options.points = 4;
    options.name = "cam\r\n=1+1,@x\n# points=99";
    auto text = camTableText(contour, options);
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(text.value().substr(0, text.value().find('\n')),
              "# camwright cam table of cam  =1+1,'@x # points=99: master angle -> follower "
              "lift s(phi) - min s");
    // The header's 6 comment lines, the source and 5 of characteristics, the column names and
    // 4 rows: the name added none.
    EXPECT_EQ(std::count(text.value().begin(), text.value().end(), '\n'), 6 + 6 + 1 + 4);
}

}  // namespace
}  // namespace cam
