// The window words the core's diagnostics itself (messages/diagnostic_text.h): every code in
// German, places as the table names them, numbers with the user's decimal separator. The
// expected texts are written from what the messages say, not copied from the program's output.

#include <gtest/gtest.h>

#include <QFile>
#include <QLabel>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <tuple>

#include "app_test_support.h"
#include "common/cancel.h"
#include "construction/tangents.h"
#include "contour/contour.h"
#include "core/diagnostic_samples.h"
#include "core/test_projects.h"
#include "design/exact_profile.h"
#include "design/synthesis.h"
#include "fillet/fillet.h"
#include "follower/follower.h"
#include "mainwindow.h"
#include "messages/diagnostic_text.h"
#include "models/segment_table_model.h"
#include "project/validate.h"
#include "spline/circle_approximation.h"
#include "spline/teach_in.h"
#include "toolpath/tool_path.h"
#include "translations.h"
#include "views/kinematics_plots.h"

namespace cam {
namespace {

const QLocale kGerman(QLocale::German, QLocale::Germany);
const QLocale kEnglish(QLocale::English, QLocale::UnitedStates);

/// The window's language and number format for one test, restored after it.
struct Language {
    explicit Language(const QLocale& locale) : translations(locale) { QLocale::setDefault(locale); }
    ~Language() { QLocale::setDefault(QLocale::c()); }
    Translations translations;
};

/// How the window shows a sample argument (core/diagnostic_samples.h): in English or in
/// German. Written from what the table and the panels show, not from the program's output.
QString windowForm(char kind, const DiagnosticArg& arg, bool german) {
    if (const auto* text = std::get_if<std::string>(&arg)) {
        if (kind == 'l') return german ? QStringLiteral("Zykloide") : QStringLiteral("Cycloidal");
        return QString::fromStdString(*text);
    }
    if (std::holds_alternative<SegmentPart>(arg)) {
        return german ? QStringLiteral("φ Anfang") : QStringLiteral("φ start");
    }
    const double v = std::get<double>(arg);
    switch (kind) {
        case 'k':
            return (german ? QStringLiteral("Segment %1") : QStringLiteral("segment %1")).arg(v);
        case 'a':
            return QStringLiteral("Z");
        case 'i':
            return QString::number(v);
        default: {
            const QString text = QString::number(v, 'f', kind == 'd' ? 1 : 2);
            return german ? QString(text).replace('.', ',') : text;
        }
    }
}

/// The window's forms of a diagnostic's arguments, a reason as its line, in signature order.
std::vector<QString> windowForms(const Diagnostic& d, bool german) {
    std::vector<QString> out;
    std::size_t next = 0;
    for (const char kind : diagnosticCodeSignature(d.code)) {
        out.push_back(kind == 'r'
                          ? (german ? QStringLiteral("Segment 2, Radius [mm]: muss > 0 sein "
                                                     "(ist -2,5)")
                                    : QStringLiteral("Segment 2, Radius [mm]: must be > 0 "
                                                     "(got -2.5)"))
                          : windowForm(kind, d.args[next++], german));
    }
    return out;
}

/// The codes whose window wording is the window's own, not the catalogue's template.
bool wordedByTheWindow(DiagnosticCode code) {
    return code == DiagnosticCode::ContourNeverSynthesised;
}

QString englishMessage(const Diagnostic& d) {
    const Language english(kEnglish);
    return DiagnosticText::message(d);
}

TEST(DiagnosticText, TheEnglishWindowSaysWhatTheCoreSaysWithItsOwnArgumentForms) {
    for (std::size_t c = 1; c < kDiagnosticCodeCount; ++c) {
        const auto code = static_cast<DiagnosticCode>(c);
        if (wordedByTheWindow(code)) continue;
        const std::string name(diagnosticCodeName(code));
        const Diagnostic d = test::sampleDiagnostic(code);
        ASSERT_TRUE(DiagnosticText::translatable(d)) << name;
        // The core fills the template with its forms of the arguments, the window with its own.
        std::vector<std::string> core, window;
        std::size_t next = 0;
        for (const char kind : diagnosticCodeSignature(code)) {
            core.push_back(kind == 'r' ? test::sampleReason().text()
                                       : englishArgument(kind, d.args[next++]));
        }
        for (const QString& form : windowForms(d, false)) window.push_back(form.toStdString());
        const std::string text = diagnosticTemplate(code);
        EXPECT_EQ(d.message, fillPlaceholders(text, core)) << name;
        EXPECT_EQ(englishMessage(d).toStdString(), fillPlaceholders(text, window)) << name;
    }
    const Diagnostic never = contourNeverSynthesised();
    EXPECT_EQ(englishMessage(never),
              "is empty: the design's contour was never synthesised (Synthesize Contour, F6, "
              "makes it)");
}

TEST(DiagnosticText, EveryCodeHasAGermanTextThatUsesAllItsArguments) {
    std::map<DiagnosticCode, QString> english;
    for (std::size_t c = 1; c < kDiagnosticCodeCount; ++c) {
        const auto code = static_cast<DiagnosticCode>(c);
        english[code] = englishMessage(test::sampleDiagnostic(code));
    }
    const Language german(kGerman);
    ASSERT_TRUE(german.translations.appTranslated());
    static const QRegularExpression placeholder(QStringLiteral("%[0-9]"));
    for (std::size_t c = 1; c < kDiagnosticCodeCount; ++c) {
        const auto code = static_cast<DiagnosticCode>(c);
        const std::string name(diagnosticCodeName(code));
        const Diagnostic d = test::sampleDiagnostic(code);
        const QString text = DiagnosticText::message(d);
        EXPECT_NE(text, english[code]) << name << ": no German text";
        EXPECT_FALSE(placeholder.match(text).hasMatch()) << name << ": " << text.toStdString();
        for (const QString& form : windowForms(d, true)) {
            EXPECT_TRUE(text.contains(form))
                << name << " does not show " << form.toStdString() << ": " << text.toStdString();
        }
    }
}

TEST(DiagnosticText, WithoutACodeOrWithArgumentsThatDoNotFitItIsTheCoreText) {
    const Language german(kGerman);
    const Diagnostic plain("contour[2]", "some problem");
    EXPECT_EQ(DiagnosticText::line(plain), QStringLiteral("contour[2]: some problem"));
    Diagnostic wrong("contour[2]", "some problem");
    wrong.code = DiagnosticCode::NotPositive;
    wrong.args = {std::string("x")};
    EXPECT_EQ(DiagnosticText::line(wrong), QStringLiteral("contour[2]: some problem"));
    EXPECT_EQ(DiagnosticText::message(wrong), QStringLiteral("some problem"));
}

TEST(DiagnosticText, EveryKindOfPlaceIsNamedAsTheWindowShowsIt) {
    const Language english(kEnglish);
    const auto where = [](Place place) {
        return DiagnosticText::location(
            Diagnostic::make(std::move(place), DiagnosticCode::NotPositive, {1.0}));
    };
    EXPECT_EQ(where(SegmentPlace{3, SegmentPart::Radius}), "Segment 3, Radius [mm]");
    EXPECT_EQ(where(SegmentPlace{3, SegmentPart::Points, 2, 0}), "Segment 3, control point P2, x");
    EXPECT_EQ(where(JointPlace{4, 5}), "Joint between segments 4 and 5");
    EXPECT_EQ(where(TurnPlace{7}), "Contour");
    EXPECT_EQ(where(FieldPlace{Field::MachiningAxisAccel, 1}), "Machining, acceleration of axis Y");
    EXPECT_EQ(where(FieldPlace{Field::FollowerRadius}), "Follower, roller radius");
    EXPECT_EQ(where(FieldPlace{Field::Point, 2}), "Point 2");
    EXPECT_EQ(where(FieldPlace{Field::ToleranceOption}), "--tolerance");
    EXPECT_EQ(where(DesignSegmentPlace{2, DesignPart::Lift}), "Motion design, segment 2, lift");
    EXPECT_EQ(where(DesignSegmentPlace{2, DesignPart::V0}), "Motion design, segment 2, v0");
    EXPECT_EQ(where(DesignSegmentPlace{2}), "Motion design, segment 2");
    EXPECT_EQ(where(DesignJointPlace{2, 3}), "Motion design, joint between segments 2 and 3");
    EXPECT_EQ(where(FilePositionPlace{3, 14}), "line 3, column 14");
    EXPECT_EQ(where(FileKeyPlace{"contour[3].radius"}), "contour[3].radius");
    EXPECT_EQ(where(FilePlace{"/tmp/a.cam.json"}), "/tmp/a.cam.json");
    EXPECT_EQ(where(SamplePlace{12, "r"}), "sample 12, r");
    EXPECT_EQ(where(std::monostate{}), "");
    const Language german(kGerman);
    EXPECT_EQ(where(FilePositionPlace{3, 14}), "Zeile 3, Spalte 14");
    EXPECT_EQ(where(DesignSegmentPlace{2, DesignPart::Lift}), "Bewegungsentwurf, Segment 2, Hub");
}

/// A three-arc contour whose second arc has a negative radius and whose first joint has a gap
/// of 0.5° (the first window ends at 120°, the second starts at 120.5°).
QString writeInvalidProject(const QTemporaryDir& dir) {
    const QString path = dir.filePath(QStringLiteral("invalid.cam.json"));
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({
  "format": "camwright", "version": 1, "name": "Invalid",
  "units": { "length": "mm", "angle": "deg" },
  "motion": { "period_s": 0.4 },
  "contour": [
    { "type": "arc", "center": [0, 0], "radius": 20, "branch": "outer",
      "phi_start": 0, "phi_end": 120 },
    { "type": "arc", "center": [0, 0], "radius": -2.5, "branch": "outer",
      "phi_start": 120.5, "phi_end": 240 },
    { "type": "arc", "center": [0, 0], "radius": 20, "branch": "outer",
      "phi_start": 240, "phi_end": 360 }
  ]
})");
    return path;
}

/// What the window shows of the project's problems: the status label, its tooltip, the
/// tooltips of the cells they mark, and the label over the plots' out-of-date curves.
struct Shown {
    QString label, labelTip, radiusTip, phiEndTip, phiStartTip, stale;
};

Shown showInvalidProject(MainWindow& window) {
    const QTemporaryDir dir;
    EXPECT_TRUE(window.loadFile(writeInvalidProject(dir)).isEmpty());
    const auto* label = window.findChild<QLabel*>(QStringLiteral("validationLabel"));
    const auto* model = window.tableModel();
    auto tip = [&](int row, int column) {
        return model->data(model->index(row, column), Qt::ToolTipRole).toString();
    };
    EXPECT_TRUE(window.waitForCurrentResult(10000));
    const auto* stale = window.plots()->findChild<QLabel*>(QStringLiteral("staleLabel"));
    return {label->text(),
            label->toolTip(),
            tip(1, SegmentTableModel::Radius),
            tip(0, SegmentTableModel::PhiEnd),
            tip(1, SegmentTableModel::PhiStart),
            stale ? stale->text() : QString()};
}

void expectNoFileKeys(const QString& text) {
    for (const char* key : {"phi_start", "phi_end", "contour[", "radius:", "phi in"}) {
        EXPECT_FALSE(text.contains(QLatin1String(key))) << key << " in " << text.toStdString();
    }
}

TEST(DiagnosticText, TheGermanWindowShowsAnInvalidProjectInGerman) {
    const Language german(kGerman);
    MainWindow window;
    const Shown shown = showInvalidProject(window);

    const QString radius = QStringLiteral("Segment 1, Radius [mm]: muss > 0 sein (ist -2,5)");
    const QString gap = QStringLiteral(
        "Übergang zwischen Segment 0 und 1: Lücke von 0,5° zwischen φ Ende 120° und φ Anfang "
        "120,5°");
    EXPECT_TRUE(shown.label.contains(radius)) << shown.label.toStdString();
    EXPECT_TRUE(shown.labelTip.contains(radius)) << shown.labelTip.toStdString();
    EXPECT_TRUE(shown.labelTip.contains(gap)) << shown.labelTip.toStdString();
    EXPECT_EQ(shown.radiusTip, radius);
    EXPECT_EQ(shown.phiEndTip, gap);
    EXPECT_EQ(shown.phiStartTip, gap);
    EXPECT_EQ(shown.stale, "Nicht berechnet: " + radius +
                               " (und 1 weiterer)\nGrau: der zuletzt berechnete Stand, veraltet.");
    for (const QString& text : {shown.label, shown.labelTip, shown.radiusTip, shown.phiEndTip,
                                shown.phiStartTip, shown.stale}) {
        expectNoFileKeys(text);
        EXPECT_FALSE(text.contains(QStringLiteral("must"))) << text.toStdString();
        EXPECT_FALSE(text.contains(QStringLiteral("2.5"))) << text.toStdString();
    }
}

TEST(DiagnosticText, TheEnglishWindowNamesTheTableColumnsToo) {
    const Language english(kEnglish);
    MainWindow window;
    const Shown shown = showInvalidProject(window);

    const QString radius = QStringLiteral("Segment 1, Radius [mm]: must be > 0 (got -2.5)");
    const QString gap = QStringLiteral(
        "Joint between segments 0 and 1: gap of 0.5° between φ end 120 and φ start 120.5");
    EXPECT_TRUE(shown.labelTip.contains(radius)) << shown.labelTip.toStdString();
    EXPECT_TRUE(shown.labelTip.contains(gap)) << shown.labelTip.toStdString();
    EXPECT_EQ(shown.radiusTip, radius);
    EXPECT_EQ(shown.phiEndTip, gap);
    for (const QString& text : {shown.label, shown.labelTip, shown.radiusTip, shown.phiEndTip})
        expectNoFileKeys(text);
}

TEST(DiagnosticText, TheCoreKeepsItsEnglishForTheCommandLine) {
    // The same problems as the core words them (the CLI prints these; cli_tests check the
    // CLI itself).
    const QTemporaryDir dir;
    const auto loaded = loadProjectFile(writeInvalidProject(dir).toStdString());
    ASSERT_FALSE(loaded.ok());
    std::vector<std::string> lines;
    for (const Diagnostic& d : loaded.errors()) lines.push_back(d.text());
    EXPECT_EQ(lines, (std::vector<std::string>{
                         "contour[1].radius: must be > 0 (got -2.5)",
                         "contour[0]/contour[1]: gap of 0.5° between phi_end 120 and "
                         "phi_start 120.5"}));
}

/// The window's line of a diagnostic in German.
QString germanLine(const Diagnostic& d) {
    const Language german(kGerman);
    return DiagnosticText::line(d);
}

TEST(DiagnosticText, ARoundCornerTooTightForTheRadiusIsExplainedInGerman) {
    // The square |x|, |y| <= 10: at its right-angled corners the tangent points sit rho from
    // the corner, so the 20 mm sides allow radii below 20 mm; 25 mm would leave the side before.
    const Eigen::Vector2d corners[] = {{10, -10}, {10, 10}, {-10, 10}, {-10, -10}};
    std::vector<SegmentSpec> square;
    double near = -45.0;
    for (int k = 0; k < 4; ++k) {
        SegmentSpec side{Line{corners[k], corners[(k + 1) % 4]}};
        std::tie(side.phiStartDeg, side.phiEndDeg) = lineWindowDeg(side, near);
        square.push_back(side);
        near = side.phiEndDeg;
    }
    const auto rounded = filletJoint(square, 1, 25.0);
    ASSERT_FALSE(rounded.ok());
    const Diagnostic& d = rounded.errors().front();
    EXPECT_EQ(d.text(),
              "contour[0]/contour[1]: radius 25 mm is too large: only radii below 20 mm fit (the "
              "tangent point would leave contour[0])");
    EXPECT_EQ(germanLine(d),
              QStringLiteral("Übergang zwischen Segment 0 und 1: Radius 25 mm ist zu groß: nur "
                             "Radien unter 20 mm passen (der Berührpunkt würde Segment 0 "
                             "verlassen)"));
}

TEST(DiagnosticText, AToolWiderThanAConcaveArcIsExplainedInGerman) {
    // The six-lobe cam's notches are concave arcs of radius 4.840705970000002 mm (its file),
    // shown to 10 significant digits; segment 0 is one.
    const auto path = toolPathFromContour(test::sixLobe(), 6.0);
    ASSERT_FALSE(path.ok());
    const Diagnostic& d = path.errors().front();
    EXPECT_EQ(
        d.text(),
        "contour[0]: the tool radius 6 mm is not smaller than the radius 4.84070597 mm of this "
        "concave arc: the offset path degenerates");
    EXPECT_EQ(germanLine(d),
              QStringLiteral("Segment 0: der Werkzeugradius 6 mm ist nicht kleiner als der "
                             "Radius 4,84070597 mm dieses konkaven Bogens: die versetzte Bahn "
                             "entartet"));
}

TEST(DiagnosticText, ARollerWiderThanAConcaveArcIsExplainedInGerman) {
    // A 5 mm roller does not fit the six-lobe cam's concave arcs of radius 4.840705970000002 mm.
    FollowerSpec spec;
    spec.type = FollowerType::Roller;
    spec.radius = 5.0;
    const auto model = FollowerModel::build(test::sixLobe(), spec);
    ASSERT_FALSE(model.ok());
    const Diagnostic& d = model.errors().front();
    EXPECT_EQ(d.text(),
              "contour[0].radius: the roller radius 5 mm is not smaller than this concave arc's "
              "radius 4.84070597 mm: the roller cannot follow it");
    EXPECT_EQ(
        germanLine(d),
        QStringLiteral("Segment 0, Radius [mm]: der Rollenradius 5 mm ist nicht kleiner "
                       "als der Radius 4,84070597 mm dieses konkaven Bogens: die Rolle kann ihm "
                       "nicht folgen"));
}

TEST(DiagnosticText, AnArmTooShortForTheCamIsExplainedInGerman) {
    // The six-lobe cam reaches out to 29 mm; from a pivot 60 mm out a 20 mm arm with a 2 mm
    // roller reaches 22 mm, short of the cam.
    const FollowerSpec spec =
        test::armSpec(FollowerType::Roller, 2.0, {60.0, 0.0}, 20.0, ArmSide::Ccw);
    const auto model = FollowerModel::build(test::sixLobe(), spec);
    ASSERT_FALSE(model.ok());
    const Diagnostic& d = model.errors().front();
    ASSERT_EQ(d.code, DiagnosticCode::ArmTooShort);
    const std::string english = d.message;
    EXPECT_EQ(english.rfind("is too short: at ", 0), 0u) << english;
    EXPECT_NE(english.find(" mm from the pivot, and the roller reaches only 22 mm"),
              std::string::npos)
        << english;
    const QString german = germanLine(d);
    EXPECT_TRUE(german.startsWith(QStringLiteral("Stößel, Hebellänge: ist zu kurz: bei ")))
        << german.toStdString();
    EXPECT_TRUE(
        german.contains(QStringLiteral("vom Drehpunkt entfernt, und die Rolle reicht "
                                       "nur 22 mm weit")))
        << german.toStdString();
}

TEST(DiagnosticText, EveryDroppedTangentIsExplainedInGerman) {
    // A base circle R20 at the origin and a nose R6 at (0, 24) on the inner branch. Their two
    // outer tangents touch the base at 20·(±cos θ, sin θ) and the nose at (0, 24) + 6·(±cos θ,
    // sin θ), sin θ = 14/24, cos θ = √380/24: (±16.2447, 11.6667) and (±4.8734, 27.5). The
    // left one runs clockwise; the right one touches the nose on its far side, where the inner
    // branch does not run.
    const std::vector<SegmentSpec> lobe{SegmentSpec{Arc{{0, 0}, 20, Branch::Outer}, -90.0, 90.0},
                                        SegmentSpec{Arc{{0, 24}, 6, Branch::Inner}, 90.0, 270.0}};
    const auto joined = tangentLineJoint(lobe, 1);
    ASSERT_FALSE(joined.ok());
    const Diagnostic& d = joined.errors().front();
    EXPECT_EQ(d.text(),
              "contour[0]/contour[1]: no tangent line fits: the outer tangent from (-16.2447, "
              "11.6667) on contour[0] to (-4.8734, 27.5) on contour[1] runs clockwise around the "
              "rotation centre (its polar angle would not grow from contour[0] to contour[1]); "
              "the outer tangent from (16.2447, 11.6667) on contour[0] to (4.8734, 27.5) on "
              "contour[1] touches contour[1] on the far side of its circle, but the arc follows "
              "the near side (inner branch)");
    EXPECT_EQ(germanLine(d),
              QStringLiteral(
                  "Übergang zwischen Segment 0 und 1: keine Tangente passt: die äußere Tangente "
                  "von (-16,2447; 11,6667) auf Segment 0 nach (-4,8734; 27,5) auf Segment 1 "
                  "läuft im Uhrzeigersinn um das Drehzentrum (ihr Polarwinkel würde von Segment "
                  "0 bis Segment 1 nicht wachsen); die äußere Tangente von (16,2447; 11,6667) "
                  "auf Segment 0 nach (4,8734; 27,5) auf Segment 1 berührt Segment 1 auf der "
                  "fernen Seite seines Kreises, aber der Bogen folgt der nahen Seite (Zweig "
                  "„innen“)"));
}

TEST(DiagnosticText, TooFewOrRepeatedTeachInPointsAreExplainedInGerman) {
    const auto one = contourThroughPoints({{20.0, 0.0}}, HandleRule::Oval);
    ASSERT_FALSE(one.ok());
    EXPECT_EQ(one.errors().front().text(), "points: a closed spline needs at least three points");
    EXPECT_EQ(germanLine(one.errors().front()),
              QStringLiteral("Punkte: ein geschlossener Spline braucht mindestens drei "
                             "Stützpunkte"));

    const auto open = splineThroughPoints({{20.0, 0.0}}, false, HandleRule::Chord);
    ASSERT_FALSE(open.ok());
    EXPECT_EQ(germanLine(open.errors().front()),
              QStringLiteral("Punkte: ein Spline braucht mindestens zwei Stützpunkte"));

    // Points 1 and 2 coincide: point 2 is named, counted from 0 as in the list.
    const auto repeated = contourThroughPoints(
        {{20.0, 0.0}, {0.0, 20.0}, {0.0, 20.0}, {-20.0, 0.0}, {0.0, -20.0}}, HandleRule::Oval);
    ASSERT_FALSE(repeated.ok());
    EXPECT_EQ(repeated.errors().front().text(), "point[2]: repeats the previous point");
    EXPECT_EQ(germanLine(repeated.errors().front()),
              QStringLiteral("Punkt 2: wiederholt den vorigen Punkt"));

    const auto flat =
        contourThroughPoints({{20.0, 0.0}, {0.0, 20.0}, {-20.0, 0.0}}, HandleRule::Oval, -0.5);
    ASSERT_FALSE(flat.ok());
    EXPECT_EQ(flat.errors().front().text(), "bulge: must be a finite factor > 0 (got -0.5)");
    EXPECT_EQ(germanLine(flat.errors().front()),
              QStringLiteral("Wölbungsfaktor: muss ein endlicher Faktor > 0 sein (ist -0,5)"));
}

TEST(DiagnosticText, AnArcApproximationItCannotMakeIsExplainedInGerman) {
    // A circle of radius 20 about the origin in two windows, and a line.
    std::vector<SegmentSpec> contour = test::splitCircle(0.0, 20.0, {0.0, 180.0, 360.0}).contour;
    const auto exact = approximateArcSegment(contour, 0, 0.0);
    ASSERT_FALSE(exact.ok());
    EXPECT_EQ(exact.errors().front().text(), "error: the admissible radial error must be > 0 mm");
    EXPECT_EQ(germanLine(exact.errors().front()),
              QStringLiteral("Zulässiger radialer Fehler: der zulässige radiale Fehler muss "
                             "> 0 mm sein"));

    const auto beyond = approximateArcSegment(contour, 5, 0.001);
    ASSERT_FALSE(beyond.ok());
    EXPECT_EQ(beyond.errors().front().text(), "contour[5]: no such segment");
    EXPECT_EQ(germanLine(beyond.errors().front()),
              QStringLiteral("Segment 5: dieses Segment gibt es nicht"));

    contour[1] = SegmentSpec{Line{{-20.0, 0.0}, {20.0, -20.0}}, 180.0, 360.0};
    const auto line = approximateArcSegment(contour, 1, 0.001);
    ASSERT_FALSE(line.ok());
    EXPECT_EQ(line.errors().front().text(), "contour[1].type: is not an arc");
    EXPECT_EQ(germanLine(line.errors().front()), QStringLiteral("Segment 1, Typ: ist kein Bogen"));
}

TEST(DiagnosticText, AFollowerLineBesideTheBaseCircleIsExplainedInGerman) {
    // A 5 mm roller on a line 50.5 mm off the centre misses the 45 mm circle its centre runs
    // on at lift 0 (base radius 40 mm + roller radius).
    FollowerSpec follower;
    follower.type = FollowerType::Roller;
    follower.radius = 5.0;
    follower.offset = 50.5;
    const auto design = MotionDesign::build(test::cycloidalDesign());
    ASSERT_TRUE(design.ok());
    const auto roller = ExactProfile::build(design.value(), follower);
    ASSERT_FALSE(roller.ok());
    EXPECT_EQ(roller.errors().front().text(),
              "design.base_radius: the follower's line (offset 50.5 mm) passes outside the base "
              "circle of radius 45 mm (base radius + roller radius): make the base radius larger "
              "than the offset");
    EXPECT_EQ(germanLine(roller.errors().front()),
              QStringLiteral("Bewegungsentwurf, Grundkreisradius: die Stößelgerade (Versatz "
                             "50,5 mm) verläuft außerhalb des Grundkreises mit Radius "
                             "45 mm (Grundkreisradius + Rollenradius): den Grundkreisradius "
                             "größer als den Versatz wählen"));

    // A knife edge has no roller radius to add.
    follower.type = FollowerType::Knife;
    const auto knife = ExactProfile::build(design.value(), follower);
    ASSERT_FALSE(knife.ok());
    EXPECT_EQ(germanLine(knife.errors().front()),
              QStringLiteral("Bewegungsentwurf, Grundkreisradius: die Stößelgerade (Versatz "
                             "50,5 mm) verläuft außerhalb des Grundkreises mit Radius "
                             "40 mm: den Grundkreisradius größer als den Versatz wählen"));
}

TEST(DiagnosticText, AnUndercutIsExplainedInGermanWithItsAngles) {
    // A steep, high rise on a small base circle: near the top of the rise the pitch curve bends
    // tighter than a roller of 16 mm (the core's Synthesis.UndercutIsRefusedWithItsAngles).
    Project p;
    p.design = test::cycloidalDesign();
    p.design->baseRadius = 10.0;
    p.design->segments[0] = {MotionLawType::Cycloidal, 60.0, 30.0};
    p.design->segments[1].lift = 30.0;
    FollowerSpec roller;
    roller.type = FollowerType::Roller;
    roller.radius = 16.0;
    p.follower = roller;
    const auto made = synthesize(p, 0.01);
    ASSERT_FALSE(made.ok());
    const Diagnostic& d = made.errors().front();
    ASSERT_EQ(d.code, DiagnosticCode::UndercutRoller);
    const std::string english = d.text();
    EXPECT_EQ(english.rfind("follower.radius: undercut: the pitch curve bends tighter than the "
                            "roller radius 16 mm from ",
                            0),
              0u)
        << english;
    // The angles are the core's, in the German number format.
    static const QRegularExpression german(QStringLiteral(
        R"(^Stößel, Rollenradius: Unterschnitt: von (\d+(,\d+)?)° bis (\d+(,\d+)?)° ist die )"
        R"(Rollenmittelpunktsbahn enger gekrümmt als der Rollenradius 16 mm$)"));
    const QString line = germanLine(d);
    const auto m = german.match(line);
    ASSERT_TRUE(m.hasMatch()) << line.toStdString();
    const double from = std::get<double>(d.args[1]), to = std::get<double>(d.args[2]);
    EXPECT_EQ(m.captured(1), kGerman.toString(from, 'g', kMessageDigits));
    EXPECT_EQ(m.captured(3), kGerman.toString(to, 'g', kMessageDigits));
    EXPECT_LT(from, to);
    EXPECT_NE(english.find(formatNumber(from) + "° to " + formatNumber(to) + "°"),
              std::string::npos)
        << english;

    // Without a design there is nothing to synthesise.
    const auto none = synthesize(Project{}, std::nullopt);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(germanLine(none.errors().front()),
              QStringLiteral("Bewegungsentwurf: das Projekt hat keinen Bewegungsentwurf, aus dem "
                             "sich eine Kontur synthetisieren ließe"));
}

TEST(DiagnosticText, ACancelledComputationSaysSoInGerman) {
    const Diagnostic d = cancelledDiagnostics().front();
    EXPECT_EQ(d.text(), "cancelled");
    EXPECT_EQ(germanLine(d), QStringLiteral("abgebrochen"));
}

TEST(DiagnosticText, AFileThatCannotBeOpenedKeepsTheSystemsWords) {
    const std::string path = "/nonexistent-camwright-folder/cam.cam.json";
    const auto loaded = loadProjectFile(path);
    ASSERT_FALSE(loaded.ok());
    const Diagnostic& d = loaded.errors().front();
    // The operating system's reason (ENOENT, in the C library's English) is an argument as it
    // is; the rest is the window's.
    EXPECT_EQ(d.text(), path + ": cannot open: No such file or directory");
    EXPECT_EQ(germanLine(d),
              QString::fromStdString(path) +
                  QStringLiteral(": kann nicht geöffnet werden: No such file or directory"));
}

}  // namespace
}  // namespace cam
