// Project files: load, save, round trip, unit conversion, forward compatibility.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "common/angles.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

const std::string kMinimal = R"({
  "format": "camwright", "version": 1, "name": "disc",
  "motion": { "rpm": 120 },
  "contour": [ { "type": "arc", "center": [5, 0], "radius": 20, "branch": "outer",
                 "phi_start": 0, "phi_end": 360 } ]
})";

std::string withReplaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST(ProjectJson, LoadsTheBundledExample) {
    const auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    EXPECT_EQ(p.value().contour.size(), 13u);
    EXPECT_EQ(p.value().motion.unit, SpeedUnit::PeriodS);
    EXPECT_DOUBLE_EQ(p.value().motion.value, 0.4);
    EXPECT_EQ(std::get<Arc>(p.value().contour[0].shape).branch, Branch::Inner);
    EXPECT_DOUBLE_EQ(std::get<Arc>(p.value().contour[1].shape).radius, 8.103180550000001);
}

TEST(ProjectJson, AWholeNumberIsSavedAsTyped) {
    // The probe's "rpm": 60 came back as 60.0.
    const auto p = parseProject(kMinimal);
    ASSERT_TRUE(p.ok());
    const std::string saved = serializeProject(p.value());
    EXPECT_NE(saved.find("\"rpm\": 120\n"), std::string::npos) << saved;
    EXPECT_NE(saved.find("\"radius\": 20,"), std::string::npos) << saved;
    EXPECT_EQ(saved.find(".0"), std::string::npos) << saved;
    // What is not a whole number, or too large for every integer to be exact, stays as it is.
    Project q = p.value();
    q.motion.value = 0.5;
    std::get<Arc>(q.contour[0].shape).center.x() = 1e300;
    const std::string other = serializeProject(q);
    EXPECT_NE(other.find("\"rpm\": 0.5\n"), std::string::npos) << other;
    EXPECT_NE(other.find("1e+300"), std::string::npos) << other;
    // And it reads back to the same doubles.
    const auto back = parseProjectStructure(other);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back.value(), q);
}

TEST(ProjectJson, SaveLoadSaveIsByteStable) {
    const auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(p.ok());
    const std::string first = serializeProject(p.value());
    const auto again = parseProject(first);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again.value(), p.value());
    EXPECT_EQ(serializeProject(again.value()), first);
}

TEST(ProjectJson, KeepsEveryFollowerField) {
    auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    ASSERT_TRUE(p.ok());
    Project project = p.value();
    FollowerSpec swinging;
    swinging.type = FollowerType::Roller;
    swinging.motion = FollowerMotion::Oscillating;
    swinging.radius = 2.5;
    swinging.pivot = {70.0, -12.5};
    swinging.armLength = 61.0;
    swinging.arm = ArmSide::Cw;
    swinging.maxPressureAngleDeg = 40.0;
    FollowerSpec offset;
    offset.type = FollowerType::Flat;
    offset.offset = -3.25;
    for (const FollowerSpec& f : {swinging, offset}) {
        project.follower = f;
        const std::string text = serializeProject(project);
        const auto again = parseProject(text);
        ASSERT_TRUE(again.ok()) << text;
        EXPECT_EQ(again.value().follower, f) << text;
    }
    EXPECT_EQ(swinging.maxPressureAngleOrDefault(), 40.0);
    EXPECT_EQ(offset.maxPressureAngleOrDefault(), 30.0);
    offset.motion = FollowerMotion::Oscillating;
    EXPECT_EQ(offset.maxPressureAngleOrDefault(), 45.0);
}

TEST(ProjectJson, WritesFieldsInTheDocumentedOrder) {
    std::string text = withReplaced(kMinimal, R"("name": "disc",)",
                                    R"("name": "disc", "sampling": {"samples_per_turn": 720},)");
    const auto p = parseProject(text);
    ASSERT_TRUE(p.ok());
    const std::string out = serializeProject(p.value());
    std::size_t last = 0;
    for (const char* key : {"\"format\"", "\"version\"", "\"name\"", "\"units\"", "\"motion\"",
                            "\"contour\"", "\"sampling\""}) {
        const std::size_t at = out.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        EXPECT_GT(at, last) << key;
        last = at;
    }
}

TEST(ProjectJson, PreservesUnknownTopLevelKeys) {
    const std::string text = withReplaced(
        kMinimal, R"("name": "disc",)",
        R"("name": "disc", "x-vendor": {"b": [1, 2.5, "three"], "a": null}, "zeta": true,)");
    const auto p = parseProject(text);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    ASSERT_EQ(p.value().extraKeys.size(), 2u);
    const std::string out = serializeProject(p.value());
    EXPECT_NE(out.find(R"("x-vendor": {
    "b": [
      1,
      2.5,
      "three"
    ],
    "a": null
  })"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find(R"("zeta": true)"), std::string::npos);
    EXPECT_EQ(serializeProject(parseProject(out).value()), out);
}

TEST(ProjectJson, ConvertsMetresAndRadiansOnLoadAndKeepsThemOnSave) {
    // A project written in metres and radians (radius 20 mm, centre 5 mm, two half turns).
    const std::string text = test::readFile(test::dataPath("io/metres-radians.cam.json"));
    const auto p = parseProject(text);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    const Arc& arc = std::get<Arc>(p.value().contour[0].shape);
    EXPECT_DOUBLE_EQ(arc.center.x(), 5.0);
    EXPECT_DOUBLE_EQ(arc.radius, 20.0);
    EXPECT_DOUBLE_EQ(p.value().contour[0].phiEndDeg, 180.0);
    EXPECT_DOUBLE_EQ(p.value().contour[1].phiEndDeg, 360.0);
    EXPECT_DOUBLE_EQ(p.value().machining->axisAccel[2], 200.0);
    EXPECT_DOUBLE_EQ(p.value().machining->feedMax, 100.0);
    EXPECT_DOUBLE_EQ(p.value().machining->toolRadius, 3.0);
    // Saved in the file's own units, every value as it was written there (not 0.0050000000001
    // from mm → m), so saving an untouched file changes nothing.
    const std::string out = serializeProject(p.value());
    EXPECT_NE(out.find(R"("length": "m")"), std::string::npos) << out;
    EXPECT_NE(out.find(R"("angle": "rad")"), std::string::npos);
    for (const char* written :
         {R"("center": [
        0.005,
        0
      ])",
          R"("radius": 0.02)", R"("phi_end": 3.141592653589793)", R"("phi_end": 6.283185307179586)",
          R"("tool_radius": 0.003)", R"("feed_max": 0.1)"}) {
        EXPECT_NE(out.find(written), std::string::npos) << written << "\n" << out;
    }
    const auto again = parseProject(out);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again.value(), p.value());
    EXPECT_EQ(serializeProject(again.value()), out);
}

TEST(ProjectJson, AValueTypedInMetresIsWrittenBackAsTyped) {
    // Values as a user types them in a metre file: up to seven significant digits. Reading
    // multiplies by 1000; writing must find the typed decimal again, not x/1000's rounding.
    std::uint64_t state = 12345;
    auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return state >> 33;
    };
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const int digits = 1 + static_cast<int>(next() % 7);
        const int exponent = -6 + static_cast<int>(next() % 9);
        std::string typed = std::to_string(next() % 10'000'000);
        typed = typed.substr(0, static_cast<std::size_t>(digits)) + "e" + std::to_string(exponent);
        const double value = std::stod(typed);
        const double mm = value * 1000.0;  // what the reader stores
        EXPECT_EQ(fileValue(mm, 1000.0), value) << typed;
        const double deg = value * (180.0 / kPi);
        EXPECT_EQ(fileValue(deg, 180.0 / kPi) * (180.0 / kPi), deg) << typed;
        ++checked;
    }
    EXPECT_EQ(checked, 20000);
}

TEST(ProjectJson, LineWindowDefaultsToThePolarAnglesOfItsEnds) {
    // A square of four lines without windows; the first starts at -45°.
    const std::string text = R"({
      "format": "camwright", "version": 1, "motion": {"omega_rad_s": -3},
      "contour": [ {"type": "line", "from": [10, -10], "to": [10, 10]},
                   {"type": "line", "from": [10, 10], "to": [-10, 10]},
                   {"type": "line", "from": [-10, 10], "to": [-10, -10]},
                   {"type": "line", "from": [-10, -10], "to": [10, -10]} ]
    })";
    const auto p = parseProject(text);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    const double expected[][2] = {{-45, 45}, {45, 135}, {135, 225}, {225, 315}};
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(p.value().contour[k].phiStartDeg, expected[k][0], 1e-12) << k;
        EXPECT_NEAR(p.value().contour[k].phiEndDeg, expected[k][1], 1e-12) << k;
    }
    EXPECT_DOUBLE_EQ(p.value().motion.omegaRadS(), -3.0);
}

TEST(ProjectJson, AcceptsAByteOrderMark) {
    EXPECT_TRUE(parseProject("\xEF\xBB\xBF" + kMinimal).ok());
}

TEST(ProjectJson, RefusesANewerVersionWithoutGuessing) {
    const auto p = parseProject(withReplaced(kMinimal, R"("version": 1)", R"("version": 2)"));
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.errors().front().location, "version");
    EXPECT_NE(p.errors().front().message.find("newer Camwright"), std::string::npos);
}

TEST(ProjectJson, NamesTheDuplicatedKey) {
    const auto p =
        parseProject(withReplaced(kMinimal, R"("radius": 20,)", R"("radius": 20, "radius": 21,)"));
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.errors().front().text(), "contour[0].radius: duplicated key");
}

TEST(ProjectJson, ReportsEveryStructuralProblemAtOnce) {
    std::string text = withReplaced(kMinimal, R"("radius": 20)", R"("radius": "20")");
    text = withReplaced(text, R"("branch": "outer")", R"("branch": "up", "colour": 3)");
    const auto p = parseProject(text);
    ASSERT_FALSE(p.ok());
    std::vector<std::string> texts;
    for (const auto& d : p.errors()) texts.push_back(d.text());
    EXPECT_EQ(texts, (std::vector<std::string>{
                         "contour[0].colour: unknown key",
                         "contour[0].radius: must be a number (got a string)",
                         "contour[0].branch: must be \"outer\" or \"inner\" (got \"up\")"}));
}

TEST(ProjectJson, SyntaxErrorsCarryLineAndColumn) {
    const auto p = parseProject("{\n  \"format\": \"camwright\",\n  \"version\": NaN\n}");
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.errors().front().location, "line 3, column 14");  // the N of NaN
    const auto huge = parseProject(withReplaced(kMinimal, "\"radius\": 20", "\"radius\": 1e400"));
    ASSERT_FALSE(huge.ok());
    EXPECT_EQ(huge.errors().front().location, "line 4, column 61");
    EXPECT_NE(huge.errors().front().message.find("too large"), std::string::npos);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(SyntaxLocations, HostileTokensAreLocatedAndQuotedShortly) {
    // Each of these crashed both programs (std::regex recursion over the parser's message, whose
    // length grows with the last token) or was located "line ?". The place now comes from the
    // parser's byte position — the last character it read, as nlohmann's own messages count — and
    // at most 40 characters of a token are quoted. The columns are counted by hand: the head is
    // 23 characters.
    struct Case {
        std::string text;
        std::string location;
    };
    const std::string head = R"({"format": "camwright",)";
    const std::vector<Case> cases{
        {head + std::string(3500, '\t') + "#", "line 1, column 3524"},  // the '#'
        {head + "\"name\": \"" + std::string(30000, 'x'), "line 1, column 30033"},
        {head + "\"version\": 1" + std::string(40000, '7') + "e400}", "line 1, column 35"},
        {"{\n  \"a\": [1, 2,\n  ]\n}", "line 3, column 3"},
        {"{\"a\": 1 \"b\": 2}", "line 1, column 11"},  // the end of the unexpected "b"
    };
    for (const Case& c : cases) {
        const auto p = parseProject(c.text);
        ASSERT_FALSE(p.ok());
        const Diagnostic& d = p.errors().front();
        EXPECT_EQ(d.location, c.location) << d.text().substr(0, 200);
        EXPECT_LT(d.message.size(), 200u) << d.message.substr(0, 300);
    }
}

TEST(SyntaxLocations, AQuoteIsCutBetweenCharactersNeverInsideOne) {
    // A string broken by a raw tab after 36 characters (nlohmann quotes it as "<U+0009>", bytes
    // 37 to 45 of the token) and an unterminated one of 'é' (2 bytes each): the 40-byte cut
    // used to split "<U+0…" and the UTF-8 bytes.
    const std::string head = R"({"format": "camwright", "name": ")";
    for (const std::string& body : {std::string(36, 'x') + "\t", [] {
                                        std::string s;
                                        for (int i = 0; i < 100; ++i) s += "\xc3\xa9";
                                        return s;
                                    }()}) {
        const auto p = parseProject(head + body);
        ASSERT_FALSE(p.ok());
        const std::string& m = p.errors().front().message;
        const std::size_t open = m.find("last read: '");
        ASSERT_NE(open, std::string::npos) << m;
        const std::string quoted = m.substr(open + 12, m.rfind("…'") - open - 12);
        EXPECT_LE(quoted.size(), 40u) << m;
        EXPECT_GE(quoted.size(), 30u) << m;  // cut near the limit, not far before it
        // Whole escapes only, and whole UTF-8 characters only.
        std::size_t escapes = 0;
        for (std::size_t i = quoted.find("<U+"); i != std::string::npos;
             i = quoted.find("<U+", i + 1)) {
            EXPECT_EQ(quoted.substr(i, 8), "<U+0009>") << m;
            ++escapes;
        }
        std::size_t continuation = 0, lead = 0;
        for (unsigned char c : quoted) {
            continuation += (c & 0xC0) == 0x80;
            lead += (c & 0xE0) == 0xC0;
        }
        EXPECT_EQ(continuation, lead) << m;
        EXPECT_EQ(quoted.find('<'), std::string::npos) << m;  // the escape did not fit: left out
    }
}

TEST(SyntaxLocations, ANulByteIsAnErrorAtItsOffsetNotTheEndOfTheFile) {
    // nlohmann reads NUL as the end of the input: everything after it used to be ignored.
    std::string text = kMinimal;
    text += '\0';
    text += "garbage";
    const auto p = parseProject(text);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.errors().front().message, "a NUL byte (at byte offset " +
                                              std::to_string(kMinimal.size()) +
                                              "): a project file is text");
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// kMinimal with a design (math.md §8's cycloidal cam, a poly5 return) in the given units; the
/// poly5 ends at rest with a curvature the harmonic after it takes up (a note, not an error).
std::string withDesign(const std::string& units, const std::string& follower) {
    std::string text = kMinimal;
    text.insert(text.rfind('}'), R"(,
  "units": )" + units + follower + R"(,
  "design": { "base_radius": 40, "tolerance": 0.01, "segments": [
    { "law": "cycloidal", "to_deg": 120, "lift": 10 },
    { "law": "dwell", "to_deg": 180 },
    { "law": "poly5", "to_deg": 300, "lift": 0, "v0": 0, "a0": 0, "v1": 0, "a1": 0.002 },
    { "law": "harmonic", "to_deg": 330, "lift": 2 },
    { "law": "modified-sine", "to_deg": 360, "lift": 0 } ] })");
    return text;
}

TEST(ProjectJsonDesign, ReadsEveryFieldAndWritesItBackAsTyped) {
    const auto p = parseProject(withDesign(R"({ "length": "mm" })", ""));
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    ASSERT_TRUE(p.value().design);
    const DesignSpec& d = *p.value().design;
    EXPECT_EQ(d.baseRadius, 40.0);
    EXPECT_EQ(d.tolerance, 0.01);
    ASSERT_EQ(d.segments.size(), 5u);
    EXPECT_EQ(d.segments[0].law, MotionLawType::Cycloidal);
    EXPECT_EQ(d.segments[0].toDeg, 120.0);
    EXPECT_EQ(d.segments[0].lift, 10.0);
    // A dwell keeps the lift it starts with.
    EXPECT_EQ(d.segments[1].law, MotionLawType::Dwell);
    EXPECT_EQ(d.segments[1].lift, 10.0);
    EXPECT_EQ(d.segments[2].law, MotionLawType::Poly5);
    EXPECT_EQ(d.segments[2].v1, 0.0);
    EXPECT_EQ(d.segments[2].a1, 0.002);
    EXPECT_EQ(d.segments[3].law, MotionLawType::Harmonic);
    EXPECT_EQ(d.segments[4].law, MotionLawType::ModifiedSine);
    const std::string out = serializeProject(p.value());
    const auto again = parseProject(out);
    ASSERT_TRUE(again.ok()) << out;
    EXPECT_EQ(again.value(), p.value());
    EXPECT_EQ(serializeProject(again.value()), out);
    EXPECT_NE(out.find(R"("law": "modified-sine")"), std::string::npos) << out;
    // Strictness is written only when asked for, and read back.
    EXPECT_FALSE(d.strictPressureAngle);
    EXPECT_EQ(out.find("strict_pressure_angle"), std::string::npos) << out;
    Project strict = p.value();
    strict.design->strictPressureAngle = true;
    const std::string strictOut = serializeProject(strict);
    EXPECT_NE(strictOut.find(R"("strict_pressure_angle": true)"), std::string::npos);
    EXPECT_EQ(parseProject(strictOut).value(), strict);
}

TEST(ProjectJsonDesign, LengthsFollowTheFileUnitsAndAnArmsLiftIsInDegrees) {
    // In metres the base radius, tolerance, lifts and poly5 slopes are lengths.
    const auto m = parseProject(withDesign(R"({ "length": "m" })", ""));
    ASSERT_TRUE(m.ok()) << m.errors().front().text();
    EXPECT_DOUBLE_EQ(m.value().design->baseRadius, 40000.0);
    EXPECT_DOUBLE_EQ(m.value().design->tolerance, 10.0);
    EXPECT_DOUBLE_EQ(m.value().design->segments[0].lift, 10000.0);
    EXPECT_DOUBLE_EQ(m.value().design->segments[2].a1, 2.0);
    // On a swinging arm a lift is the angle swung, in degrees whatever the length unit.
    const auto arm = parseProject(withDesign(
        R"({ "length": "m" }, "follower": { "type": "roller", "radius": 0.002, "motion": )"
        R"("oscillating", "pivot": [0.06, 0], "arm_length": 0.05 })",
        ""));
    ASSERT_TRUE(arm.ok()) << arm.errors().front().text();
    EXPECT_DOUBLE_EQ(arm.value().design->baseRadius, 40000.0);
    EXPECT_DOUBLE_EQ(arm.value().design->segments[0].lift, 10.0);
    EXPECT_DOUBLE_EQ(arm.value().design->segments[2].a1, 0.002);
    const std::string out = serializeProject(arm.value());
    EXPECT_EQ(parseProject(out).value(), arm.value());
    EXPECT_NE(out.find(R"("lift": 10)"), std::string::npos) << out;
}

TEST(ProjectJsonDesign, EveryProblemIsNamedWithItsPlace) {
    const std::string good = withDesign(R"({ "length": "mm" })", "");
    const std::pair<std::string, std::string> cases[][2] = {
        {{R"("law": "harmonic")", R"("law": "sinus")"}, {"design.segments[3].law", "sinus"}},
        {{R"("base_radius": 40)", R"("base_radius": -4)"}, {"design.base_radius", "-4"}},
        {{R"("to_deg": 330)", R"("to_deg": 290)"}, {"design.segments[3].to_deg", "300"}},
        {{R"("to_deg": 360)", R"("to_deg": 350)"}, {"design.segments[4].to_deg", "360"}},
        {{R"("law": "dwell", "to_deg": 180)", R"("law": "dwell", "to_deg": 180, "lift": 9)"},
         {"design.segments[1].lift", "dwell"}},
        {{R"("law": "modified-sine", "to_deg": 360, "lift": 0)",
          R"("law": "modified-sine", "to_deg": 360, "lift": 1)"},
         {"design.segments[4].lift", "0"}},
        {{R"("law": "cycloidal", "to_deg": 120, "lift": 10)",
          R"("law": "cycloidal", "to_deg": 120, "lift": 10, "v0": 1)"},
         {"design.segments[0].v0", "unknown key"}},
        {{R"("tolerance": 0.01)", R"("tolerance": 0.01, "tolerances": 1)"},
         {"design.tolerances", "unknown key"}},
    };
    for (const auto& [edit, expected] : cases) {
        const std::string text = withReplaced(good, edit.first, edit.second);
        const auto p = parseProject(text);
        ASSERT_FALSE(p.ok()) << edit.second;
        bool found = false;
        for (const Diagnostic& d : p.errors()) {
            if (d.location == expected.first &&
                d.message.find(expected.second) != std::string::npos)
                found = true;
        }
        std::string all;
        for (const Diagnostic& d : p.errors()) all += d.text() + "\n";
        EXPECT_TRUE(found) << edit.second << " → expected " << expected.first << " (\""
                           << expected.second << "\"), got:\n"
                           << all;
    }
}

TEST(ProjectJsonDesign, AConstantVelocityLawIsReadAndWrittenAsLine) {
    // A line of 0.1 mm/° blended from rest and back to rest by poly5s that meet its slope.
    std::string text = kMinimal;
    text.insert(text.rfind('}'), R"(,
  "design": { "base_radius": 40, "segments": [
    { "law": "poly5", "to_deg": 60, "lift": 2, "v0": 0, "a0": 0, "v1": 0.1, "a1": 0 },
    { "law": "line", "to_deg": 180, "lift": 14 },
    { "law": "poly5", "to_deg": 240, "lift": 16, "v0": 0.1, "a0": 0, "v1": 0, "a1": 0 },
    { "law": "modified-sine", "to_deg": 360, "lift": 0 } ] })");
    const auto p = parseProject(text);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    const DesignSpec& d = *p.value().design;
    ASSERT_EQ(d.segments.size(), 4u);
    EXPECT_EQ(d.segments[1].law, MotionLawType::ConstantVelocity);
    EXPECT_EQ(d.segments[1].toDeg, 180.0);
    EXPECT_EQ(d.segments[2].v0, 0.1);
    const std::string out = serializeProject(p.value());
    EXPECT_NE(out.find(R"("law": "line")"), std::string::npos) << out;
    const auto again = parseProject(out);
    ASSERT_TRUE(again.ok()) << out;
    EXPECT_EQ(again.value(), p.value());
    EXPECT_EQ(serializeProject(again.value()), out);
    // An unknown law's message lists it with the others (read from the laws' table).
    const auto unknown = parseProject(
        withReplaced(text, R"("law": "line", "to_deg": 180)", R"("law": "lines", "to_deg": 180)"));
    ASSERT_FALSE(unknown.ok());
    const auto law = std::ranges::find(unknown.errors(), std::string("design.segments[1].law"),
                                       &Diagnostic::location);
    ASSERT_NE(law, unknown.errors().end()) << unknown.errors().front().text();
    EXPECT_NE(law->message.find(R"("poly5", "line")"), std::string::npos) << law->message;
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

// The dynamics section (project-format.md, math.md §9): read, written back as typed, and
// each rule of its values located at its key.
const std::string kWithDynamics = R"({
  "format": "camwright", "version": 1, "name": "disc",
  "motion": { "rpm": 300 },
  "contour": [ { "type": "arc", "center": [5, 0], "radius": 30, "branch": "outer",
                 "phi_start": 0, "phi_end": 360 } ],
  "follower": { "type": "roller", "radius": 8 },
  "dynamics": { "mass_kg": 0.5, "spring_rate_N_per_mm": 2, "spring_preload_N": 20,
                "external_force_N": -5.25, "damping_Ns_per_m": 0, "contact_width_mm": 12,
                "cam_material": { "E_MPa": 210000, "poisson": 0.3 },
                "follower_material": { "E_MPa": 2800, "poisson": 0.35 },
                "allowable_contact_stress_MPa": 900, "spring_safety_factor": 1.5 }
})";

TEST(ProjectJsonDynamics, ReadsEveryKeyAndWritesItBackAsTyped) {
    const auto p = parseProject(kWithDynamics);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    ASSERT_TRUE(p.value().dynamics);
    const DynamicsSpec& d = *p.value().dynamics;
    EXPECT_EQ(d[DynamicsKey::MassKg], 0.5);
    EXPECT_EQ(d[DynamicsKey::ExternalForceN], -5.25);
    EXPECT_EQ(d[DynamicsKey::DampingNsPerM], 0.0);
    EXPECT_EQ(d[DynamicsKey::FollowerModulusMpa], 2800.0);
    EXPECT_EQ(d[DynamicsKey::FollowerPoisson], 0.35);
    EXPECT_EQ(d[DynamicsKey::SpringSafetyFactor], 1.5);
    EXPECT_FALSE(d[DynamicsKey::InertiaKgM2]);  // absent stays absent
    const std::string saved = serializeProject(p.value());
    const Json written = Json::parse(saved)["dynamics"];
    EXPECT_EQ(written, Json::parse(kWithDynamics)["dynamics"]);
    EXPECT_EQ(written["spring_rate_N_per_mm"].dump(), "2");  // a whole number as typed
    EXPECT_FALSE(written.contains("inertia_kg_m2"));
    const auto again = parseProject(saved);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(serializeProject(again.value()), saved);
    // A project without the section writes none.
    const auto plain = parseProject(kMinimal);
    ASSERT_TRUE(plain.ok());
    EXPECT_FALSE(Json::parse(serializeProject(plain.value())).contains("dynamics"));
}

/// The first problem's location and text when `from` in kWithDynamics becomes `to`.
std::string problemWith(const std::string& from, const std::string& to) {
    const auto p = parseProject(withReplaced(kWithDynamics, from, to));
    if (p.ok()) return "(no problem)";
    return p.errors().front().text();
}

TEST(ProjectJsonDynamics, EveryRuleIsLocatedAtItsKey) {
    EXPECT_EQ(problemWith("\"mass_kg\": 0.5", "\"mass_kg\": -1"),
              "dynamics.mass_kg: must be > 0 (got -1)");
    EXPECT_EQ(problemWith("\"mass_kg\": 0.5", "\"mass_kg\": 0"),
              "dynamics.mass_kg: must be > 0 (got 0)");
    EXPECT_EQ(problemWith("\"damping_Ns_per_m\": 0", "\"damping_Ns_per_m\": -2"),
              "dynamics.damping_Ns_per_m: must be between 0 and 1e+12 N·s/m (got -2)");
    EXPECT_EQ(problemWith("\"poisson\": 0.35", "\"poisson\": 0.5"),
              "dynamics.follower_material.poisson: must be at least 0 and below 0.5 (got 0.5)");
    EXPECT_EQ(problemWith("\"spring_preload_N\": 20", "\"spring_preload_N\": 1e13"),
              "dynamics.spring_preload_N: must be between -1e+12 and 1e+12 N (got 1e+13)");
    EXPECT_EQ(problemWith("\"mass_kg\": 0.5", "\"mass_kg\": \"0.5\""),
              "dynamics.mass_kg: must be a number (got a string)");
    EXPECT_EQ(problemWith("\"mass_kg\": 0.5", "\"mass\": 0.5"), "dynamics.mass: unknown key");
    EXPECT_EQ(problemWith("{ \"E_MPa\": 2800, \"poisson\": 0.35 }", "{ \"E_MPa\": 2800 }"),
              "dynamics.follower_material.poisson: missing");
    EXPECT_EQ(problemWith("{ \"E_MPa\": 2800, \"poisson\": 0.35 }", "\"POM\""),
              "dynamics.follower_material: must be an object (got a string)");
    // An arm's keys on a translating follower, and the other way round.
    EXPECT_EQ(problemWith("\"mass_kg\": 0.5", "\"inertia_kg_m2\": 0.01"),
              "dynamics.inertia_kg_m2: is for a swinging arm; this project's follower "
              "translates");
    const std::string arm =
        withReplaced(kWithDynamics, R"("follower": { "type": "roller", "radius": 8 })",
                     R"("follower": { "type": "roller", "radius": 8, "motion": "oscillating",
                                      "pivot": [80, 0], "arm_length": 60 })");
    const auto swinging = parseProject(arm);
    ASSERT_FALSE(swinging.ok());
    EXPECT_EQ(swinging.errors().front().text(),
              "dynamics.mass_kg: is for a translating follower; this project's follower swings "
              "on an arm");
}

// The groove (issue 32): closure, clearance and land radii are read, written back as typed,
// in millimetres whatever the project's length unit, and every rule is located at its key.
const std::string kGrooved = R"({
  "format": "camwright", "version": 1, "name": "disc",
  "motion": { "rpm": 300 },
  "contour": [ { "type": "arc", "center": [5, 0], "radius": 30, "branch": "outer",
                 "phi_start": 0, "phi_end": 360 } ],
  "follower": { "type": "roller", "radius": 8, "closure": "groove", "groove_clearance_mm": 0.05,
                "inner_land_radius_mm": 12.5, "outer_land_radius_mm": 70 }
})";

TEST(ProjectJsonGroove, ReadsEveryKeyAndWritesItBackAsTyped) {
    const auto p = parseProject(kGrooved);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    const FollowerSpec& f = *p.value().follower;
    EXPECT_EQ(f.closure, Closure::Groove);
    EXPECT_TRUE(f.grooved());
    EXPECT_EQ(f.grooveClearance, 0.05);
    EXPECT_EQ(f.innerLandRadius, 12.5);
    EXPECT_EQ(f.outerLandRadius, 70.0);
    const std::string saved = serializeProject(p.value());
    const Json written = Json::parse(saved)["follower"];
    const Json typed = Json::parse(kGrooved)["follower"];
    for (const auto& [key, value] : typed.items()) EXPECT_EQ(written[key], value) << key;
    EXPECT_EQ(written.size(), typed.size() + 1) << saved;  // and a translating line's offset
    EXPECT_EQ(written["offset"], 0);
    const auto again = parseProject(saved);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again.value(), p.value());
    // Spring closure is the default and is not written; a groove's keys stay millimetres in a
    // project in metres (their names say so) while the roller's radius is converted.
    const auto plain = parseProject(kWithDynamics);
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ(plain.value().follower->closure, Closure::Spring);
    EXPECT_FALSE(Json::parse(serializeProject(plain.value()))["follower"].contains("closure"));
    const auto metres = parseProject(
        withReplaced(withReplaced(withReplaced(kGrooved, R"("name": "disc",)",
                                               R"("name": "disc", "units": { "length": "m" },)"),
                                  R"("center": [5, 0], "radius": 30)",
                                  R"("center": [0.005, 0], "radius": 0.03)"),
                     R"("radius": 8,)", R"("radius": 0.008,)"));
    ASSERT_TRUE(metres.ok()) << metres.errors().front().text();
    EXPECT_DOUBLE_EQ(metres.value().follower->radius, 8.0);
    EXPECT_EQ(metres.value().follower->grooveClearance, 0.05);
    EXPECT_EQ(metres.value().follower->outerLandRadius, 70.0);
}

std::string grooveProblem(const std::string& from, const std::string& to) {
    const auto p = parseProject(withReplaced(kGrooved, from, to));
    if (p.ok()) return "(no problem)";
    return p.errors().front().text();
}

TEST(ProjectJsonGroove, EveryRuleIsLocatedAtItsKey) {
    EXPECT_EQ(grooveProblem(R"("closure": "groove")", R"("closure": "grooved")"),
              "follower.closure: must be \"spring\", \"groove\" or \"conjugate\" (got "
              "\"grooved\")");
    EXPECT_EQ(grooveProblem(R"("groove_clearance_mm": 0.05,)", ""),
              "follower.groove_clearance_mm: missing");
    EXPECT_EQ(grooveProblem(R"("groove_clearance_mm": 0.05)", R"("groove_clearance_mm": -0.01)"),
              "follower.groove_clearance_mm: must be between 0 and 1000000 mm (got -0.01)");
    EXPECT_EQ(grooveProblem(R"("type": "roller", "radius": 8,)", R"("type": "knife",)"),
              "follower.closure: a groove needs a roller follower: a knife or a flat face cannot "
              "run in a groove; choose a roller or the spring closure");
    EXPECT_EQ(grooveProblem(R"("inner_land_radius_mm": 12.5)", R"("inner_land_radius_mm": 0)"),
              "follower.inner_land_radius_mm: must be > 0 (got 0)");
    EXPECT_EQ(grooveProblem(R"("outer_land_radius_mm": 70)", R"("outer_land_radius_mm": 12)"),
              "follower.outer_land_radius_mm: must be larger than the inner land radius 12.5 mm "
              "(got 12 mm): the groove runs between the two");
    // Without the groove the clearance is not needed, and a spring-closed cam may be checked
    // against its lands too.
    EXPECT_EQ(grooveProblem(R"("closure": "groove", "groove_clearance_mm": 0.05,)",
                            R"("closure": "spring",)"),
              "(no problem)");
}

TEST(ProjectJsonConjugate, ReadsItsKeysWritesThemBackAndLocatesEveryRule) {
    const std::string conjugate = withReplaced(
        kGrooved, R"("closure": "groove", "groove_clearance_mm": 0.05,)",
        R"("closure": "conjugate", "conjugate_distance_mm": 80, "conjugate_radius_mm": 6.5,)");
    const auto p = parseProject(conjugate);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    const FollowerSpec& f = *p.value().follower;
    EXPECT_TRUE(f.conjugate());
    EXPECT_EQ(f.conjugateDistance, 80.0);
    EXPECT_EQ(f.conjugateRadius, 6.5);
    const std::string saved = serializeProject(p.value());
    EXPECT_EQ(Json::parse(saved)["follower"]["conjugate_radius_mm"], 6.5);
    EXPECT_EQ(parseProject(saved).value(), p.value());
    const auto problem = [&](const std::string& from, const std::string& to) {
        const auto q = parseProject(withReplaced(conjugate, from, to));
        return q.ok() ? std::string("(no problem)") : q.errors().front().text();
    };
    EXPECT_EQ(problem(R"("conjugate_radius_mm": 6.5,)", ""),
              "follower.conjugate_radius_mm: missing");
    EXPECT_EQ(problem(R"("conjugate_distance_mm": 80)", R"("conjugate_distance_mm": -80)"),
              "follower.conjugate_distance_mm: must be > 0 (got -80)");
    EXPECT_EQ(problem(R"("type": "roller", "radius": 8,)", R"("type": "knife",)"),
              "follower.closure: a conjugate pair needs a roller follower: its second roller "
              "runs on the same line (a yoke) or on a second arm of the same pivot (a bell "
              "crank)");
    // A bell crank's keys belong to an arm.
    EXPECT_EQ(problem(R"("conjugate_distance_mm": 80)",
                      R"("conjugate_distance_mm": 80, "conjugate_angle_deg": -40)"),
              "follower.conjugate_angle_deg: is for a swinging arm; this project's follower "
              "translates");
}

TEST(ProjectJsonConjugate, ABellCrankTakesTheSecondArmsAngleAndLength) {
    const std::string crank = withReplaced(
        kGrooved,
        R"("type": "roller", "radius": 8, "closure": "groove", "groove_clearance_mm": 0.05,)",
        R"("type": "roller", "radius": 4, "motion": "oscillating", "pivot": [70, 0],
           "arm_length": 60, "closure": "conjugate", "conjugate_angle_deg": -48,
           "conjugate_arm_length_mm": 60, "conjugate_radius_mm": 5,)");
    const auto p = parseProject(crank);
    ASSERT_TRUE(p.ok()) << p.errors().front().text();
    const FollowerSpec& f = *p.value().follower;
    EXPECT_EQ(f.conjugateAngleDeg, -48.0);
    EXPECT_EQ(f.conjugateArmLength, 60.0);
    const Json saved = Json::parse(serializeProject(p.value()));
    EXPECT_EQ(saved["follower"]["conjugate_angle_deg"], -48.0);
    EXPECT_EQ(saved["follower"]["conjugate_arm_length_mm"], 60.0);
    EXPECT_FALSE(saved["follower"].contains("conjugate_distance_mm"));
    EXPECT_EQ(parseProject(saved.dump()).value(), p.value());
    const auto problem = [&](const std::string& from, const std::string& to) {
        const auto q = parseProject(withReplaced(crank, from, to));
        return q.ok() ? std::string("(no problem)") : q.errors().front().text();
    };
    EXPECT_EQ(problem(R"("conjugate_arm_length_mm": 60,)", ""),
              "follower.conjugate_arm_length_mm: missing");
    EXPECT_EQ(problem(R"("conjugate_angle_deg": -48,)", R"("conjugate_angle_deg": 400,)"),
              "follower.conjugate_angle_deg: must be between -360 and 360° (got 400)");
    EXPECT_EQ(problem(R"("conjugate_angle_deg": -48,)",
                      R"("conjugate_angle_deg": -48, "conjugate_distance_mm": 80,)"),
              "follower.conjugate_distance_mm: is for a translating follower; this project's "
              "follower swings on an arm");
}

}  // namespace
}  // namespace cam
