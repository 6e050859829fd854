#include "views/follower_panel.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "document/commands.h"
#include "messages/diagnostic_text.h"
#include "models/delegates.h"
#include "project/follower_kind.h"
#include "views/check_list.h"
#include "views/plot_redraw.h"
#include "views/plot_setup.h"
#include "views/turning_picture.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

NumberSpinBox* spinBox(QWidget* parent, const char* name, const QString& suffix, const QString& tip,
                       double minimum) {
    auto* s = new NumberSpinBox(parent);
    s->setObjectName(name);
    s->setSuffix(suffix);
    s->setToolTip(tip);
    s->setMinimum(minimum);
    s->setMaximum(1e6);
    return s;
}

QString millimetres(double mm) { return formatQuantity(DisplayQuantity::Length, mm); }

}  // namespace

FollowerPanel::FollowerPanel(ProjectDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_form = form;
    m_type = new QComboBox(this);
    m_type->setObjectName("followerTypeComboBox");
    for (const FollowerKind& kind : followerKinds()) {
        m_type->addItem(QCoreApplication::translate("FollowerKind", kind.title));
    }
    m_type->setToolTip(tr("What touches the cam (math.md §7)"));
    m_motion = new QComboBox(this);
    m_motion->setObjectName("followerMotionComboBox");
    m_motion->addItems({tr("Translating"), tr("Swinging arm")});
    m_motion->setToolTip(tr("A follower sliding on a line, or swinging on an arm about a pivot"));
    m_radius = spinBox(this, "followerRadiusSpinBox", " mm", tr("Radius of the roller"), 0.001);
    m_radius->setSingleStep(0.5);
    m_radius->setValue(5.0);
    m_offset = spinBox(
        this, "followerOffsetSpinBox", " mm",
        tr("Offset e of the follower's line of motion from the cam's centre: positive to the "
           "left of its direction as seen from the centre, negative to the right "
           "(the Turning picture shows it). A positive offset lowers the "
           "rise's pressure angle when the cam turns clockwise, a "
           "negative one when it turns counter-clockwise; either raises the return's"),
        -1e6);
    m_offset->setSingleStep(0.5);
    m_pivotX = spinBox(this, "pivotXSpinBox", " mm",
                       tr("Pivot of the arm, x (in the cam's frame at 0°)"), -1e6);
    m_pivotY = spinBox(this, "pivotYSpinBox", " mm",
                       tr("Pivot of the arm, y (in the cam's frame at 0°)"), -1e6);
    m_armLength = spinBox(this, "armLengthSpinBox", " mm",
                          tr("From the pivot to the roller centre or the tip"), 0.001);
    m_side = new QComboBox(this);
    m_side->setObjectName("armSideComboBox");
    m_side->addItems({tr("Counter-clockwise"), tr("Clockwise")});
    m_side->setToolTip(tr("The side of the line pivot → cam centre the arm lies on"));
    m_limit = spinBox(this, "pressureLimitSpinBox", "°",
                      tr("Largest pressure angle allowed (default: 30° translating, 45° "
                         "swinging)"),
                      0.0);
    m_limit->setMaximum(89.0);
    m_limit->setSpecialValueText(tr("default"));
    m_closure = new QComboBox(this);
    m_closure->setObjectName("followerClosureComboBox");
    m_closure->addItems({tr("Spring"), tr("Groove"), tr("Conjugate plates")});
    m_closure->setToolTip(
        tr("What keeps the roller on the cam: a spring; a groove milled into the disc (the "
           "contour is its inner flank, the outer flank lies twice the roller radius plus the "
           "clearance beyond it); or conjugate plates (a second plate on the same shaft drives a "
           "second roller on the same line, across the cam centre)"));
    m_conjugateDistance = spinBox(
        this, "conjugateDistanceSpinBox", " mm",
        tr("From the first roller's centre back along the line to the second roller's: it must "
           "put the second roller beyond the cam centre at every angle"),
        0.001);
    m_conjugateDistance->setSingleStep(1.0);
    m_conjugateDistance->setValue(100.0);
    m_conjugateRadius =
        spinBox(this, "conjugateRadiusSpinBox", " mm", tr("The second roller's radius"), 0.001);
    m_conjugateRadius->setSingleStep(0.5);
    m_conjugateRadius->setValue(5.0);
    m_conjugateAngle =
        spinBox(this, "conjugateAngleSpinBox", "°",
                tr("A bell crank: the second arm's angle from the first about the pivot, "
                   "counter-clockwise positive"),
                -360.0);
    m_conjugateAngle->setMaximum(360.0);
    m_conjugateArm =
        spinBox(this, "conjugateArmSpinBox", " mm",
                tr("A bell crank: from the pivot to the second roller's centre"), 0.001);
    m_clearance = spinBox(this, "grooveClearanceSpinBox", " mm",
                          tr("The roller's play between the groove's flanks"), 0.0);
    m_clearance->setDecimals(3);
    m_clearance->setSingleStep(0.01);
    m_clearance->setValue(0.05);
    m_innerLand =
        spinBox(this, "innerLandSpinBox", " mm",
                tr("The smallest radius the groove's inner flank may come to: the bore or hub plus "
                   "the wall it needs (none: not checked)"),
                0.0);
    m_outerLand =
        spinBox(this, "outerLandSpinBox", " mm",
                tr("The largest radius the groove's outer flank may reach: the disc's rim less the "
                   "wall it needs (none: not checked)"),
                0.0);
    form->addRow(tr("Type"), m_type);
    form->addRow(tr("Motion"), m_motion);
    form->addRow(tr("Roller radius"), m_radius);
    form->addRow(tr("Offset"), m_offset);
    // Pairs share a row (the dock holds its checks and two plots too): each box is named.
    const auto pair = [this](QWidget* a, QWidget* b) {
        auto* row = new QWidget(this);
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->addWidget(a, 1);
        layout->addWidget(b, 1);
        return row;
    };
    m_pivotX->setAccessibleName(tr("Pivot x"));
    m_pivotY->setAccessibleName(tr("Pivot y"));
    m_pivotX->setPrefix(QStringLiteral("x "));
    m_pivotY->setPrefix(QStringLiteral("y "));
    form->addRow(tr("Pivot"), pair(m_pivotX, m_pivotY));
    form->addRow(tr("Arm length"), m_armLength);
    form->addRow(tr("Arm side"), m_side);
    form->addRow(tr("Pressure-angle limit"), m_limit);
    m_clearance->setAccessibleName(tr("Groove clearance"));
    m_clearance->setPrefix(tr("play "));
    m_innerLand->setAccessibleName(tr("Inner land radius"));
    m_outerLand->setAccessibleName(tr("Outer land radius"));
    m_innerLand->setPrefix(tr("inner "));
    m_outerLand->setPrefix(tr("outer "));
    m_innerLand->setSpecialValueText(tr("inner: none"));
    m_outerLand->setSpecialValueText(tr("outer: none"));
    form->addRow(tr("Closure"), pair(m_closure, m_clearance));
    form->addRow(tr("Groove lands"), pair(m_innerLand, m_outerLand));
    m_conjugateDistance->setAccessibleName(tr("Second roller's distance"));
    m_conjugateRadius->setAccessibleName(tr("Second roller's radius"));
    m_conjugateDistance->setPrefix(tr("distance "));
    m_conjugateRadius->setPrefix(tr("radius "));
    form->addRow(tr("Second roller"), pair(m_conjugateDistance, m_conjugateRadius));
    m_conjugateAngle->setAccessibleName(tr("Second arm's angle"));
    m_conjugateArm->setAccessibleName(tr("Second arm's length"));
    m_conjugateAngle->setPrefix(tr("angle "));
    m_conjugateArm->setPrefix(tr("length "));
    form->addRow(tr("Second arm"), pair(m_conjugateAngle, m_conjugateArm));
    // How the cam turns against this follower: the offset's sign only means something with
    // it. The picture is the setting: a click turns the cam round (the speed's sign).
    m_turning = new TurningPicture(this);
    m_turning->setAccessibleName(tr("Turning clockwise"));
    m_turningText = new QLabel(this);
    m_turningText->setObjectName("turningText");
    m_turningText->setWordWrap(true);
    auto* turning = new QWidget(this);
    auto* turningRow = new QHBoxLayout(turning);
    turningRow->setContentsMargins(0, 0, 0, 0);
    turningRow->addWidget(m_turning);
    turningRow->addWidget(m_turningText, 1);
    form->addRow(tr("Turning"), turning);
    // The settings keep their height (squeezed, a box's text was cut off); the checks and the
    // plots below share what is left.
    auto* settings = new QWidget(this);
    settings->setLayout(form);
    settings->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    form->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(settings);

    m_checks = new CheckList(
        tr("Design checks (click one to go there):"), "designChecksList", "designChecksSummary",
        tr("The follower over the turn: click a line to put the cursor there"), this);
    layout->addWidget(m_checks, 1);
    connect(m_checks, &CheckList::anglePicked, this, &FollowerPanel::anglePicked);

    m_pressurePlot = newAlongXPlot(this, "pressureAnglePlot", tr("Pressure angle [°]"));
    m_pressurePlot->setMinimumHeight(110);
    m_pressurePlot->setToolTip(tr("Pressure angle over the turn; dashed: the limit; red: beyond"));
    QCPGraph* angle = m_pressurePlot->addGraph();
    // One pixel wide, as the kinematics curves: Qt strokes a wider pen through its general
    // stroker, and at 1.3 px this curve took 2 to 3 ms of every edit's redraw (0.3 ms now).
    angle->setPen(QPen(QColor(20, 90, 160), 1.0));
    QCPGraph* beyond = m_pressurePlot->addGraph();
    beyond->setPen(QPen(QColor(200, 30, 30), 2.5));
    for (auto& line : m_limitLines) {
        line = new QCPItemStraightLine(m_pressurePlot);
        line->setPen(QPen(QColor(200, 30, 30), 1, Qt::DashLine));
    }
    m_cursor = addCursorLine(m_pressurePlot);
    layout->addWidget(m_pressurePlot, 1);

    m_curvaturePlot = newAlongXPlot(this, "curvaturePlot", tr("ρ [mm]"));
    m_curvaturePlot->setMinimumHeight(110);
    m_curvaturePlot->setToolTip(
        tr("Radius of curvature over the turn, positive where convex, negative where hollow; "
           "clipped at twice the cam's largest radius (a straight stretch reads as the clip). "
           "Blue: the profile; grey: the roller's pitch curve; dashed: the roller's radius and "
           "minus the tool's"));
    m_curvaturePlot->addGraph()->setPen(QPen(QColor(20, 90, 160), 1.0));
    m_curvaturePlot->addGraph()->setPen(QPen(QColor(120, 120, 120), 1.0));
    for (auto& line : m_radiusLines) {
        line = new QCPItemStraightLine(m_curvaturePlot);
        line->setPen(QPen(QColor(200, 30, 30), 1, Qt::DashLine));
    }
    m_curvatureCursor = addCursorLine(m_curvaturePlot);
    layout->addWidget(m_curvaturePlot, 1);

    const auto choice = [this](QComboBox* box, std::function<void(FollowerSpec&, int)> set) {
        connect(box, &QComboBox::currentIndexChanged, this, [this, set](int index) {
            if (m_refreshing) return;
            m_gesture = 0;
            edit([&](FollowerSpec& f) { set(f, index); });
        });
    };
    // A first roller fits the cam: 5 mm, or less than half its smallest arc.
    const auto fittingRadius = [this] {
        double radius = 5.0;
        for (const SegmentSpec& segment : m_document->project().contour) {
            if (const Arc* arc = segment.as<Arc>()) {
                radius = std::min(radius, std::floor(arc->radius * 5.0) / 10.0);
            }
        }
        return std::max(radius, 0.1);
    };
    choice(m_type, [fittingRadius](FollowerSpec& f, int i) {
        f.type = static_cast<FollowerType>(i);
        if (followerKind(f.type).hasRadius && !(f.radius > 0.0)) f.radius = fittingRadius();
        if (!followerKind(f.type).canSwing) f.motion = FollowerMotion::Translating;
        // Only a roller runs in a groove.
        if (f.type != FollowerType::Roller) f.closure = Closure::Spring;
    });
    choice(m_closure, [this](FollowerSpec& f, int i) {
        f.closure = static_cast<Closure>(i);
        if (f.closure == Closure::Conjugate) {
            // A pair takes a roller; its second roller the same radius, on a yoke or a bell
            // crank as conjugateDefaults() makes it.
            if (f.type != FollowerType::Roller) {
                f.type = FollowerType::Roller;
                if (!(f.radius > 0.0)) f.radius = m_radius->value();
            }
            conjugateDefaults(f);
            return;
        }
        if (f.closure != Closure::Groove) return;
        f.grooveClearance = m_clearance->value();
        // A groove takes a roller: the one the follower has, or a first whose groove, twice
        // its radius plus the clearance, fits into every concave arc: 5 mm at most.
        if (f.type != FollowerType::Roller) {
            f.type = FollowerType::Roller;
            if (!(f.radius > 0.0)) {
                double radius = 5.0;
                for (const SegmentSpec& segment : m_document->project().contour) {
                    if (const Arc* arc = segment.as<Arc>()) {
                        const double room = (arc->radius - f.grooveClearance) / 2.0;
                        radius = std::min(radius, std::floor(room * 10.0) / 10.0);
                    }
                }
                f.radius = std::max(radius, 0.1);
            }
        }
    });
    choice(m_motion, [this, fittingRadius](FollowerSpec& f, int i) {
        f.motion = static_cast<FollowerMotion>(i);
        if (f.motion == FollowerMotion::Oscillating) {
            if (!followerKind(f.type).canSwing) f.type = FollowerType::Roller;
            if (followerKind(f.type).hasRadius && !(f.radius > 0.0)) f.radius = fittingRadius();
        }
        // A conjugate pair keeps its second roller: on a yoke or a bell crank now.
        if (f.conjugate()) conjugateDefaults(f);
    });
    choice(m_side, [](FollowerSpec& f, int i) { f.arm = static_cast<ArmSide>(i); });
    const auto number = [this](NumberSpinBox* box, std::function<void(FollowerSpec&, double)> set) {
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, set](double v) {
            if (m_refreshing) return;
            if (m_gesture == 0) m_gesture = nextGestureId();
            edit([&](FollowerSpec& f) { set(f, v); });
        });
        connect(box, &QDoubleSpinBox::editingFinished, this, [this] { m_gesture = 0; });
    };
    number(m_radius, [](FollowerSpec& f, double v) { f.radius = v; });
    number(m_offset, [](FollowerSpec& f, double v) { f.offset = v; });
    number(m_pivotX, [](FollowerSpec& f, double v) { f.pivot.x() = v; });
    number(m_pivotY, [](FollowerSpec& f, double v) { f.pivot.y() = v; });
    number(m_armLength, [](FollowerSpec& f, double v) { f.armLength = v; });
    number(m_clearance, [](FollowerSpec& f, double v) { f.grooveClearance = v; });
    number(m_innerLand, [](FollowerSpec& f, double v) {
        f.innerLandRadius = v > 0.0 ? std::optional<double>(v) : std::nullopt;
    });
    number(m_outerLand, [](FollowerSpec& f, double v) {
        f.outerLandRadius = v > 0.0 ? std::optional<double>(v) : std::nullopt;
    });
    number(m_conjugateDistance, [](FollowerSpec& f, double v) { f.conjugateDistance = v; });
    number(m_conjugateRadius, [](FollowerSpec& f, double v) { f.conjugateRadius = v; });
    number(m_conjugateAngle, [](FollowerSpec& f, double v) { f.conjugateAngleDeg = v; });
    number(m_conjugateArm, [](FollowerSpec& f, double v) { f.conjugateArmLength = v; });
    number(m_limit, [](FollowerSpec& f, double v) {
        f.maxPressureAngleDeg = v > 0.0 ? std::optional<double>(v) : std::nullopt;
    });
    connect(m_turning, &QAbstractButton::clicked, this,
            [this](bool clockwise) { turnRound(clockwise); });
    connect(document, &ProjectDocument::followerChanged, this, &FollowerPanel::refresh);
    connect(document, &ProjectDocument::motionChanged, this, &FollowerPanel::refresh);
    refresh();
}

void FollowerPanel::conjugateDefaults(FollowerSpec& f) const {
    if (!(f.conjugateRadius > 0.0)) f.conjugateRadius = f.radius > 0.0 ? f.radius : 5.0;
    const double reach = m_largestRadius > 0.0 ? m_largestRadius : 50.0;
    if (f.motion != FollowerMotion::Oscillating) {
        f.conjugateAngleDeg = f.conjugateArmLength = 0.0;
        // Beyond the centre at every angle, with room to spare.
        if (!(f.conjugateDistance > 0.0)) f.conjugateDistance = std::ceil(2.0 * (reach + f.radius));
        return;
    }
    f.conjugateDistance = 0.0;
    if (f.conjugateArmLength > 0.0) return;
    // The first arm mirrored about the line from the pivot to the cam centre: the first roller
    // at the cam's largest radius lies γ from that line (law of cosines), the second −γ.
    f.conjugateArmLength = f.armLength;
    const double a = f.pivot.norm(), L = f.armLength, r = reach + f.radius;
    const double cosine = std::clamp((a * a + L * L - r * r) / (2.0 * a * L), -1.0, 1.0);
    const double gamma = std::acos(cosine) * 180.0 / kPi;
    f.conjugateAngleDeg = std::round(f.arm == ArmSide::Ccw ? -2.0 * gamma : 2.0 * gamma);
}

void FollowerPanel::turnRound(bool clockwise) {
    const MotionSpec& now = m_document->project().motion;
    if (!std::isfinite(now.value) || now.value == 0.0) return;
    if (clockwise == turnsClockwise(now)) return;
    // The same speed the other way. A period has no sign: counter-clockwise is written in rpm.
    MotionSpec m = now;
    if (now.unit == SpeedUnit::PeriodS) {
        m.unit = SpeedUnit::Rpm;
        m.value = -60.0 / now.value;
    } else {
        m.value = -now.value;
    }
    m_document->undoStack()->push(new SetMotion(m_document, m));
}

void FollowerPanel::edit(const std::function<void(FollowerSpec&)>& change) {
    const std::optional<FollowerSpec>& before = m_document->project().follower;
    FollowerSpec spec = before.value_or(FollowerSpec{});
    if (!before) {
        // A first swinging arm needs a pivot and an arm: one beside the cam, reaching it.
        spec.pivot = {m_pivotX->value(), m_pivotY->value()};
        spec.armLength = m_armLength->value();
    }
    change(spec);
    if (before && spec == *before) return;
    m_document->undoStack()->push(new SetFollower(m_document, spec, m_gesture));
}

void FollowerPanel::refresh() {
    m_refreshing = true;
    const FollowerSpec f = m_document->project().follower.value_or(FollowerSpec{});
    m_type->setCurrentIndex(static_cast<int>(f.type));
    m_motion->setCurrentIndex(static_cast<int>(f.motion));
    const bool arm = f.motion == FollowerMotion::Oscillating;
    m_radius->setValue(followerKind(f.type).hasRadius ? f.radius : m_radius->value());
    m_offset->setValue(f.offset);
    if (arm || m_document->project().follower) {
        if (f.armLength > 0.0) {
            m_pivotX->setValue(f.pivot.x());
            m_pivotY->setValue(f.pivot.y());
            m_armLength->setValue(f.armLength);
        }
    }
    if (!(m_armLength->value() > 0.001)) {
        // Defaults for a first arm: a pivot well outside a cam of the usual size.
        m_pivotX->setValue(60.0);
        m_pivotY->setValue(0.0);
        m_armLength->setValue(50.0);
    }
    m_side->setCurrentIndex(static_cast<int>(f.arm));
    m_limit->setValue(f.maxPressureAngleDeg.value_or(0.0));
    m_closure->setCurrentIndex(static_cast<int>(f.closure));
    if (f.grooved()) m_clearance->setValue(f.grooveClearance);
    m_innerLand->setValue(f.innerLandRadius.value_or(0.0));
    m_outerLand->setValue(f.outerLandRadius.value_or(0.0));
    m_clearance->setEnabled(f.grooved());
    m_innerLand->setEnabled(f.grooved());
    m_outerLand->setEnabled(f.grooved());
    m_form->setRowVisible(m_offset, !arm);
    m_form->setRowVisible(m_pivotX->parentWidget(), arm);
    m_form->setRowVisible(m_armLength, arm);
    m_form->setRowVisible(m_side, arm);
    m_form->setRowVisible(m_innerLand->parentWidget(), f.grooved());
    const bool crank = f.conjugate() && arm;
    if (f.conjugate()) {
        if (!crank) m_conjugateDistance->setValue(f.conjugateDistance);
        m_conjugateRadius->setValue(f.conjugateRadius);
    }
    if (crank) {
        m_conjugateAngle->setValue(f.conjugateAngleDeg);
        m_conjugateArm->setValue(f.conjugateArmLength);
    }
    m_conjugateDistance->setEnabled(f.conjugate() && !crank);
    m_conjugateDistance->setVisible(!crank);
    m_conjugateRadius->setEnabled(f.conjugate());
    m_conjugateAngle->setEnabled(crank);
    m_conjugateArm->setEnabled(crank);
    m_form->setRowVisible(m_conjugateDistance->parentWidget(), f.conjugate());
    m_form->setRowVisible(m_conjugateAngle->parentWidget(), crank);
    m_radius->setEnabled(followerKind(f.type).hasRadius);
    m_offset->setEnabled(!arm);
    m_pivotX->setEnabled(arm);
    m_pivotY->setEnabled(arm);
    m_armLength->setEnabled(arm);
    m_side->setEnabled(arm);
    const MotionSpec& m = m_document->project().motion;
    const bool valid = std::isfinite(m.value) && m.value != 0.0;
    const bool clockwise = valid && turnsClockwise(m);
    m_turning->setEnabled(valid);
    m_turning->show(clockwise, m_document->project().follower);
    m_turningText->setText(clockwise ? tr("clockwise (click the picture: the other way)")
                                     : tr("counter-clockwise (click the picture: the other way)"));
    m_refreshing = false;
}

void FollowerPanel::setCursorX(double x) {
    moveCursorLine(m_cursor, x);
    moveCursorLine(m_curvatureCursor, x);
}

void FollowerPanel::showCurvature(const ComputeResultPtr& result) {
    // Clipped at twice the cam's largest radius: a radius beyond that is as good as straight
    // for every check, and both signs stay readable beside the +∞ of a straight stretch.
    double size = 1.0;
    for (const QVector<QPointF>& outline : result->outlines) {
        for (const QPointF& p : outline) size = std::max(size, std::hypot(p.x(), p.y()));
    }
    m_curvatureClip = 2.0 * size;
    m_largestRadius = size;
    const double clip = m_curvatureClip;
    const auto clipped = [clip](const std::vector<double>& rho) {
        QVector<double> y(static_cast<qsizetype>(rho.size()));
        for (std::size_t k = 0; k < rho.size(); ++k) {
            y[static_cast<qsizetype>(k)] =
                std::isnan(rho[k]) ? rho[k] : std::clamp(rho[k], -clip, clip);
        }
        return y;
    };
    const QVector<double> x(result->followerX.begin(), result->followerX.end());
    const bool ascending = x.size() < 2 || x.front() <= x.back();
    const FollowerSpec& spec = result->follower->spec();
    const bool roller = followerKind(spec.type).hasRadius;
    const QVector<double> profile = clipped(result->followerRhoProfile);
    const QVector<double> pitch =
        roller ? clipped(result->followerRhoPitch) : QVector<double>(x.size(), qQNaN());
    m_curvaturePlot->graph(0)->setData(x, profile, ascending);
    m_curvaturePlot->graph(1)->setData(x, pitch, ascending);
    // The range the radii span (within the clip), and the lines at the roller and the tool.
    double low = 0.0, high = 0.0;
    for (const QVector<double>* y : {&profile, &pitch}) {
        for (const double v : *y) {
            if (std::isnan(v)) continue;
            low = std::min(low, v);
            high = std::max(high, v);
        }
    }
    const double tool = result->project && result->project->machining
                            ? result->project->machining->toolRadius
                            : 0.0;
    const std::array<double, 2> levels{roller ? spec.radius : 0.0, -tool};
    for (std::size_t k = 0; k < 2; ++k) {
        m_radiusLines[k]->setVisible(levels[k] != 0.0);
        m_radiusLines[k]->point1->setCoords(0, levels[k]);
        m_radiusLines[k]->point2->setCoords(1, levels[k]);
        low = std::min(low, levels[k]);
        high = std::max(high, levels[k]);
    }
    m_curvaturePlot->xAxis->setLabel(result->axis == PlotAxis::Angle ? tr("φ [°]") : tr("t [s]"));
    const double pad = 0.08 * std::max(high - low, 1.0);
    m_curvaturePlot->yAxis->setRange(low - pad, high + pad);
    queueReplot(m_curvaturePlot);
}

void FollowerPanel::setResult(const ComputeResultPtr& result) {
    // The curves only of a valid project (stale_label.h): an invalid one is not drawn.
    const bool curve = result && result->valid() && result->follower;
    m_pressurePlot->setVisible(curve);
    m_curvaturePlot->setVisible(curve);
    if (curve) {
        showCurvature(result);
        const QVector<double> x(result->followerX.begin(), result->followerX.end());
        const QVector<double> y(result->followerPressureDeg.begin(),
                                result->followerPressureDeg.end());
        const double limit = result->follower->spec().maxPressureAngleOrDefault();
        QVector<double> beyond(y.size());
        for (qsizetype k = 0; k < y.size(); ++k) {
            beyond[k] = std::abs(y[k]) > limit ? y[k] : std::numeric_limits<double>::quiet_NaN();
        }
        // Sorted by time: over angle a cam turning clockwise runs from 0 down to −360°.
        const bool ascending = x.size() < 2 || x.front() <= x.back();
        m_pressurePlot->graph(0)->setData(x, y, ascending);
        m_pressurePlot->graph(1)->setData(x, beyond, ascending);
        m_limitLines[0]->point1->setCoords(0, limit);
        m_limitLines[0]->point2->setCoords(1, limit);
        m_limitLines[1]->point1->setCoords(0, -limit);
        m_limitLines[1]->point2->setCoords(1, -limit);
        m_pressurePlot->xAxis->setLabel(result->axis == PlotAxis::Angle ? tr("φ [°]")
                                                                        : tr("t [s]"));
        double top = limit;
        for (double v : y) top = std::max(top, std::abs(v));
        m_pressurePlot->yAxis->setRange(-1.1 * top, 1.1 * top);
        queueReplot(m_pressurePlot);
    }
    // A first picture's checks follow with its refinement (MainWindow::showResult): until
    // then the list keeps the previous ones.
    if (!(curve && result->followerChecksPending)) showChecks(result);
}

void FollowerPanel::showChecks(const ComputeResultPtr& result) {
    m_checks->clear();
    const auto add = [this](const QString& text, std::optional<double> phi, bool problem) {
        m_checks->add(text, phi, problem);
    };
    if (result && result->awaitsContour()) {
        m_checks->setSummary(
            tr("No design checks: no contour yet. Synthesize (F6) makes it from the design."));
        return;
    }
    if (!result || !result->ok()) {
        m_checks->setSummary(
            result && !result->errors.empty()
                ? tr("No design checks: %1").arg(diagnosticText(result->errors.front()))
                : tr("No design checks: the contour cannot be computed."));
        return;
    }
    if (!result->valid() && result->followerErrors.empty()) {
        // A contour with problems (an open joint): nothing of it is checked as the cam.
        const Diagnostics reasons = result->reasonsNotShown();
        m_checks->setSummary(
            tr("No design checks: %1")
                .arg(reasons.empty() ? QStringLiteral("?") : diagnosticText(reasons.front())));
        return;
    }
    if (!result->followerErrors.empty()) {
        for (const Diagnostic& d : result->followerErrors) {
            add(tr("The follower cannot ride this cam: %1").arg(diagnosticText(d)), std::nullopt,
                true);
        }
        m_checks->setSummary(tr("The follower cannot ride this cam."));
        return;
    }
    if (!result->follower) {
        m_checks->setSummary(
            tr("The seed's knife edge on the radial line: choose a follower to check it."));
        return;
    }
    const FollowerAnalysis& a = result->followerChecks;
    const double limit = a.limitRad;
    const PressurePhases& p = a.pressure;
    if (p.rise) {
        add(tr("Largest pressure angle on rise: %1 at %2 (limit %3)")
                .arg(formatRadians(p.rise->value), formatRadians(p.rise->phi),
                     formatRadians(limit)),
            p.rise->phi, p.rise->value > limit);
    }
    if (p.fall) {
        add(tr("Largest pressure angle on return: %1 at %2 (limit %3)")
                .arg(formatRadians(p.fall->value), formatRadians(p.fall->phi),
                     formatRadians(limit)),
            p.fall->phi, p.fall->value > limit);
    }
    if (p.dwell) {
        add(tr("Largest pressure angle in a dwell: %1 at %2 (limit %3)")
                .arg(formatRadians(p.dwell->value), formatRadians(p.dwell->phi),
                     formatRadians(limit)),
            p.dwell->phi, p.dwell->value > limit);
    }
    for (const AngleRange& r : a.pressureExceeded) {
        add(tr("Pressure angle beyond the limit from %1 to %2: up to %3 at %4, %5 too much")
                .arg(formatRadians(r.from), formatRadians(r.to), formatRadians(r.peak.value),
                     formatRadians(r.peak.phi), formatRadians(r.peak.value - limit)),
            r.from, true);
    }
    for (const NonContact& c : a.undercut) {
        add(tr("The follower cannot reach the profile at %1: it jumps from %2 to %3")
                .arg(formatRadians(c.phi), formatPoint(c.from.x(), c.from.y()),
                     formatPoint(c.to.x(), c.to.y())),
            c.phi, true);
    }
    const FollowerSpec& spec = result->follower->spec();
    const bool flat = followerKind(spec.type).flatFace;
    const double toolRadius = result->project && result->project->machining
                                  ? result->project->machining->toolRadius
                                  : 0.0;
    const CurvatureVerdict verdict = curvatureVerdict(a, spec, toolRadius);
    const CurvatureExtremes& profile = a.profileCurvature;
    if (profile.minConvex) {
        add(tr("Smallest convex radius of the profile: %1 at %2")
                .arg(millimetres(profile.minConvex->value), formatRadians(profile.minConvex->phi)),
            profile.minConvex->phi, false);
    }
    if (profile.minConcave) {
        // A flat face needs a convex profile; a cutter needs hollows at least as wide as it.
        const bool toolTooWide = verdict.toolFits && !*verdict.toolFits;
        const QString line =
            verdict.toolFits
                ? tr("Smallest concave radius of the profile: %1 at %2 (tool radius %3)")
                      .arg(millimetres(profile.minConcave->value),
                           formatRadians(profile.minConcave->phi), millimetres(toolRadius))
                : tr("Smallest concave radius of the profile: %1 at %2")
                      .arg(millimetres(profile.minConcave->value),
                           formatRadians(profile.minConcave->phi));
        add(line, profile.minConcave->phi, flat || toolTooWide);
    } else {
        add(tr("The profile has no concave stretch."), std::nullopt, false);
    }
    if (followerKind(spec.type).hasRadius) {
        const CurvatureExtremes& pitch = a.pitchCurvature;
        if (pitch.minConvex) {
            add(tr("Smallest convex radius of the pitch curve: %1 at %2 (roller radius %3)")
                    .arg(millimetres(pitch.minConvex->value), formatRadians(pitch.minConvex->phi),
                         millimetres(spec.radius)),
                pitch.minConvex->phi, verdict.rollerFits && !*verdict.rollerFits);
        }
        if (pitch.minConcave) {
            add(tr("Smallest concave radius of the pitch curve: %1 at %2")
                    .arg(millimetres(pitch.minConcave->value),
                         formatRadians(pitch.minConcave->phi)),
                pitch.minConcave->phi, false);
        }
    }
    if (flat) add(tr("Face width needed: %1").arg(millimetres(a.faceWidth)), std::nullopt, false);
    if (result->groove) addGrooveChecks(*result->groove, spec);
    if (spec.conjugate()) addConjugateChecks(*result, limit);
    const int problems = m_checks->problemCount();
    m_checks->setSummary(problems == 0 ? tr("Every check passes.")
                                       : tr("%n check(s) fail.", nullptr, problems));
}

void FollowerPanel::addGrooveChecks(const GrooveView& groove, const FollowerSpec& spec) {
    add(tr("Groove: %1 wide (roller radius %2, clearance %3)")
            .arg(millimetres(2.0 * spec.radius + spec.grooveClearance), millimetres(spec.radius),
                 millimetres(spec.grooveClearance)),
        std::nullopt, false);
    const PathBends& bends = groove.outerBends;
    if (bends.minConvex) {
        add(tr("Smallest convex radius of the outer flank: %1 at %2")
                .arg(millimetres(bends.minConvex->radius), formatRadians(bends.minConvex->phi)),
            bends.minConvex->phi, false);
    }
    if (bends.minConcave) {
        add(tr("Smallest concave radius of the outer flank: %1 at %2")
                .arg(millimetres(bends.minConcave->radius), formatRadians(bends.minConcave->phi)),
            bends.minConcave->phi, false);
    }
    const GrooveLands& lands = groove.lands;
    const RadialExtreme& in = lands.innerMost;
    add(lands.innerLand
            ? tr("Inner flank nearest the centre: %1 at %2 (land to %3)")
                  .arg(millimetres(in.radius), formatRadians(in.phi), millimetres(*lands.innerLand))
            : tr("Inner flank nearest the centre: %1 at %2 (no inner land radius given)")
                  .arg(millimetres(in.radius), formatRadians(in.phi)),
        in.phi, !lands.innerKept());
    const RadialExtreme& out = lands.outerMost;
    add(lands.outerLand
            ? tr("Outer flank farthest from the centre: %1 at %2 (land from %3)")
                  .arg(millimetres(out.radius), formatRadians(out.phi),
                       millimetres(*lands.outerLand))
            : tr("Outer flank farthest from the centre: %1 at %2 (no outer land radius given)")
                  .arg(millimetres(out.radius), formatRadians(out.phi)),
        out.phi, !lands.outerKept());
}

void FollowerPanel::addConjugateChecks(const ComputeResult& result, double limit) {
    if (!result.conjugate) {
        for (const Diagnostic& d : result.conjugateErrors) {
            add(tr("The second plate cannot be made: %1").arg(diagnosticText(d)), std::nullopt,
                true);
        }
        return;
    }
    const ConjugateView& c = *result.conjugate;
    const ConjugatePlate& p = c.plate;
    // The play the fitted arcs leave the second roller, the first on the first plate: within
    // the tolerance they were fitted to, or the pair rattles (a gap) or jams (interference).
    add(tr("Second plate: %n arc(s) within %1; the second roller's play from %2 at %3 to %4 "
           "at %5",
           nullptr, static_cast<int>(p.fit.arcs.size()))
            .arg(millimetres(c.toleranceMm), millimetres(p.minPlay), formatRadians(p.minPlayAt),
                 millimetres(p.maxPlay), formatRadians(p.maxPlayAt)),
        p.minPlayAt, p.maxPlay > c.toleranceMm || p.minPlay < -c.toleranceMm);
    add(tr("Largest pressure angle at the second roller: %1 at %2 (limit %3)")
            .arg(formatRadians(std::abs(p.maxPressureAngle)), formatRadians(p.maxPressureAt),
                 formatRadians(limit)),
        p.maxPressureAt, std::abs(p.maxPressureAngle) > limit);
    if (p.bends.minConvex) {
        add(tr("Smallest convex radius of the second plate: %1, touched at %2")
                .arg(millimetres(p.bends.minConvex->radius), formatRadians(p.bends.minConvex->phi)),
            p.bends.minConvex->phi, false);
    }
    if (p.bends.minConcave) {
        add(tr("Smallest concave radius of the second plate: %1, touched at %2 (second roller "
               "radius %3)")
                .arg(millimetres(p.bends.minConcave->radius),
                     formatRadians(p.bends.minConcave->phi), millimetres(c.yoke.rollerRadiusMm)),
            p.bends.minConcave->phi, !(p.bends.minConcave->radius > c.yoke.rollerRadiusMm));
    }
}

void FollowerPanel::add(const QString& text, std::optional<double> phi, bool problem) {
    m_checks->add(text, phi, problem);
}

QStringList FollowerPanel::checkLines() const { return m_checks->lines(); }

int FollowerPanel::problemCount() const { return m_checks->problemCount(); }

}  // namespace cam
