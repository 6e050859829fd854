// The one catalogue of the core's messages (common/diagnostic_catalogue.h): every code's English
// template uses each of its arguments, the core renders every one of them with no placeholder
// left, and a place's text is derived from the place.

#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "core/diagnostic_samples.h"

namespace cam {
namespace {

std::set<int> placeholders(const std::string& text) {
    static const std::regex placeholder("%([0-9]+)");
    std::set<int> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), placeholder);
         it != std::sregex_iterator(); ++it) {
        out.insert(std::stoi((*it)[1]));
    }
    return out;
}

TEST(DiagnosticCatalogue, EveryTemplateHasAPlaceholderForEachLetterOfItsSignature) {
    EXPECT_EQ(diagnosticCodeSignature(DiagnosticCode::Unspecified), "");
    for (std::size_t c = 1; c < kDiagnosticCodeCount; ++c) {
        const auto code = static_cast<DiagnosticCode>(c);
        const std::string_view signature = diagnosticCodeSignature(code);
        std::set<int> expected;
        for (std::size_t i = 0; i < signature.size(); ++i) expected.insert(static_cast<int>(i) + 1);
        EXPECT_EQ(placeholders(diagnosticTemplate(code)), expected) << diagnosticCodeName(code);
        EXPECT_EQ(signature.find_first_not_of("nidkafstlr"), std::string_view::npos)
            << diagnosticCodeName(code);
    }
}

TEST(DiagnosticCatalogue, TheCoreRendersEveryCodeWithAllItsArguments) {
    ASSERT_GT(kDiagnosticCodeCount, 150u);
    for (std::size_t c = 1; c < kDiagnosticCodeCount; ++c) {
        const auto code = static_cast<DiagnosticCode>(c);
        const std::string name(diagnosticCodeName(code));
        const Diagnostic d = test::sampleDiagnostic(code);
        ASSERT_TRUE(argumentsFit(code, d.args)) << name;
        EXPECT_EQ(d.code, code);
        EXPECT_EQ(d.location, "machining.step") << name;
        EXPECT_TRUE(placeholders(d.message).empty()) << name << ": " << d.message;
        const std::string_view signature = diagnosticCodeSignature(code);
        std::size_t next = 0;
        for (const char kind : signature) {
            const std::string shown =
                kind == 'r' ? test::sampleReason().text() : englishArgument(kind, d.args[next++]);
            EXPECT_NE(d.message.find(shown), std::string::npos)
                << name << " does not show its " << kind << " argument " << shown << ": "
                << d.message;
        }
    }
}

TEST(DiagnosticCatalogue, ArgumentsAreShownTheCoresWay) {
    EXPECT_EQ(englishArgument('n', 0.1 + 0.2), "0.3");
    EXPECT_EQ(englishArgument('i', 67108865.0), "67108865");
    EXPECT_EQ(englishArgument('d', 64.0), "64.0");
    EXPECT_EQ(englishArgument('k', 3.0), "contour[3]");
    EXPECT_EQ(englishArgument('a', 0.0), "x");
    EXPECT_EQ(englishArgument('f', SegmentPart::PhiEnd), "phi_end");
    EXPECT_EQ(englishArgument('s', std::string("the roller")), "the roller");
    EXPECT_EQ(englishArgument('l', std::string("poly345")), "poly345");
}

TEST(DiagnosticCatalogue, PlaceholdersAreFilledAsQtFillsThem) {
    EXPECT_EQ(fillPlaceholders("%2 before %1, %1 again", {"a", "b"}), "b before a, a again");
    EXPECT_EQ(fillPlaceholders("%3 has no value, 100% stays", {"a"}),
              "%3 has no value, 100% stays");
    EXPECT_EQ(fillPlaceholders("%10", {"1", "2", "3", "4", "5", "6", "7", "8", "9", "ten"}), "ten");
}

TEST(DiagnosticCatalogue, ArgumentsThatDoNotFitTheSignatureAreNoticed) {
    EXPECT_TRUE(argumentsFit(DiagnosticCode::NotPositive, {2.0}));
    EXPECT_FALSE(argumentsFit(DiagnosticCode::NotPositive, {std::string("2")}));
    EXPECT_FALSE(argumentsFit(DiagnosticCode::NotPositive, {}));
    EXPECT_FALSE(argumentsFit(DiagnosticCode::NotPositive, {2.0, 3.0}));
    EXPECT_TRUE(argumentsFit(DiagnosticCode::TangentNoneFits, {}));  // `r` takes the reasons
    EXPECT_TRUE(
        argumentsFit(DiagnosticCode::WindowNotIncreasing, {SegmentPart::PhiStart, 1.0, 2.0}));
}

TEST(DiagnosticCatalogue, TheLocationTextFollowsFromThePlace) {
    EXPECT_EQ(locationText(std::monostate{}), "");
    EXPECT_EQ(locationText(SegmentPlace{3}), "contour[3]");
    EXPECT_EQ(locationText(SegmentPlace{3, SegmentPart::Radius}), "contour[3].radius");
    EXPECT_EQ(locationText(SegmentPlace{3, SegmentPart::Points, 2, 0}), "contour[3].points[2][0]");
    EXPECT_EQ(locationText(SegmentPlace{3, SegmentPart::P0, -1, 1}), "contour[3].p0[1]");
    EXPECT_EQ(locationText(JointPlace{4, 5}), "contour[4]/contour[5]");
    EXPECT_EQ(locationText(TurnPlace{7}), "contour");
    EXPECT_EQ(locationText(FieldPlace{Field::MachiningAxisAccel, 1}), "machining.axis_accel[1]");
    EXPECT_EQ(locationText(FieldPlace{Field::ToleranceOption}), "--tolerance");
    EXPECT_EQ(locationText(FieldPlace{Field::Point, 2}), "point[2]");
    EXPECT_EQ(locationText(DesignSegmentPlace{2, DesignPart::Lift}), "design.segments[2].lift");
    EXPECT_EQ(locationText(DesignSegmentPlace{2}), "design.segments[2]");
    EXPECT_EQ(locationText(DesignJointPlace{2, 3}), "design.segments[2]/design.segments[3]");
    EXPECT_EQ(locationText(FilePositionPlace{3, 14}), "line 3, column 14");
    EXPECT_EQ(locationText(FilePositionPlace{3}), "line 3");
    EXPECT_EQ(locationText(FileKeyPlace{"(top level)"}), "(top level)");
    EXPECT_EQ(locationText(FilePlace{"/tmp/a.cam.json"}), "/tmp/a.cam.json");
    EXPECT_EQ(locationText(SamplePlace{12, "r"}), "sample 12, r");
}

TEST(DiagnosticCatalogue, ThePlaceNamesTheSegmentFieldsATableMarks) {
    EXPECT_EQ(segmentFields(SegmentPlace{3, SegmentPart::Radius}),
              (std::vector<SegmentPlace>{{3, SegmentPart::Radius}}));
    EXPECT_EQ(segmentFields(JointPlace{4, 5}),
              (std::vector<SegmentPlace>{{4, SegmentPart::PhiEnd}, {5, SegmentPart::PhiStart}}));
    EXPECT_EQ(segmentFields(TurnPlace{7}),
              (std::vector<SegmentPlace>{{0, SegmentPart::PhiStart}, {7, SegmentPart::PhiEnd}}));
    EXPECT_TRUE(segmentFields(FieldPlace{Field::FollowerRadius}).empty());
}

}  // namespace
}  // namespace cam
