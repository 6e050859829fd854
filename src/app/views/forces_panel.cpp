#include "views/forces_panel.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "document/commands.h"
#include "messages/diagnostic_text.h"
#include "messages/field_titles.h"
#include "models/delegates.h"
#include "project/dynamics.h"
#include "views/check_list.h"
#include "views/plot_redraw.h"
#include "views/plot_setup.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

/// Where a cam angle φ (rad, signed as the turn runs) is on the plots' x axis.
double plotXOf(const ComputeResult& r, double phi) {
    return r.axis == PlotAxis::Angle ? radToDeg(phi) : phi / r.omega;
}

/// The two material groups: the picker's keys (E, ν).
constexpr std::array<std::array<DynamicsKey, 2>, 2> kMaterialKeys{{
    {DynamicsKey::CamModulusMpa, DynamicsKey::CamPoisson},
    {DynamicsKey::FollowerModulusMpa, DynamicsKey::FollowerPoisson},
}};

/// A key with a value that must be > 0 (or a Poisson ratio) is not set at 0: its box shows
/// "—" there, and 0 clears it.
bool zeroClears(DynamicsKey key) {
    const DynamicsRule rule = dynamicsKey(key).rule;
    return rule == DynamicsRule::Positive || rule == DynamicsRule::Poisson;
}

QCustomPlot* turnPlot(QWidget* parent, const char* name, const QString& label, const QString& tip) {
    QCustomPlot* plot = newAlongXPlot(parent, name, label);
    plot->setMinimumHeight(130);
    plot->setToolTip(tip);
    return plot;
}

/// The y range of the finite values of some curves, with a margin and 0 in it.
QCPRange rangeOf(std::initializer_list<const std::vector<double>*> curves) {
    double low = 0.0, high = 0.0;
    for (const std::vector<double>* curve : curves) {
        for (const double v : *curve) {
            if (!std::isfinite(v)) continue;
            low = std::min(low, v);
            high = std::max(high, v);
        }
    }
    const double pad = 0.08 * std::max(high - low, 1e-9);
    return {low - pad, high + pad};
}

}  // namespace

ForcesPanel::ForcesPanel(ProjectDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    m_form = new QFormLayout;
    for (const DynamicsKeyInfo& info : dynamicsKeys()) {
        const DynamicsKey key = info.key;
        for (std::size_t g = 0; g < kMaterialKeys.size(); ++g) {
            if (kMaterialKeys[g][0] != key) continue;
            auto* box = new QComboBox(this);
            box->setObjectName(g == 0 ? "camMaterialComboBox" : "followerMaterialComboBox");
            box->addItem(tr("Other (typed below)"));
            for (const Material& m : materials()) {
                box->addItem(
                    QCoreApplication::translate("Material", m.title),
                    QString::fromUtf8(m.name.data(), static_cast<qsizetype>(m.name.size())));
            }
            box->setToolTip(
                tr("A common material: sets E and Poisson's ratio below (typical "
                   "room-temperature values; a data sheet's own values can be "
                   "typed instead)"));
            m_materials[g] = box;
            m_form->addRow(g == 0 ? tr("Cam material") : tr("Follower material"), box);
            connect(box, &QComboBox::activated, this, [this, g, box](int index) {
                if (m_refreshing || index <= 0) return;
                const Material& m = materials()[static_cast<std::size_t>(index - 1)];
                m_gesture = 0;
                edit([&](DynamicsSpec& d) {
                    d[kMaterialKeys[g][0]] = m.modulusMpa;
                    d[kMaterialKeys[g][1]] = m.poisson;
                });
                box->setCurrentIndex(index);  // keeps a table twin (steel, bearing steel)
            });
        }
        auto* spin = new NumberSpinBox(this);
        spin->setObjectName(QStringLiteral("dynamics_%1")
                                .arg(QString::fromUtf8(dynamicsKeyPath(key).c_str()))
                                .replace('.', '_'));
        const bool poisson = info.rule == DynamicsRule::Poisson;
        spin->setMinimum(info.rule == DynamicsRule::Finite ? -kMaxDynamicsValue : 0.0);
        spin->setMaximum(poisson ? 0.4999 : kMaxDynamicsValue);
        spin->setSingleStep(poisson ? 0.01 : 1.0);
        if (zeroClears(key)) spin->setSpecialValueText(tr("—"));
        QString tip = dynamicsKeyTitle(key);
        if (zeroClears(key)) tip += tr(" (0 or — : not set)");
        if (key == DynamicsKey::SpringSafetyFactor) tip += tr("; not set: 1");
        spin->setToolTip(tip);
        m_values[static_cast<std::size_t>(key)] = spin;
        m_form->addRow(dynamicsKeyTitle(key), spin);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, key](double v) {
            if (m_refreshing) return;
            if (m_gesture == 0) m_gesture = nextGestureId();
            edit([&](DynamicsSpec& d) {
                if (zeroClears(key) && v == 0.0) {
                    d[key].reset();
                } else {
                    d[key] = v;
                }
            });
        });
        connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { m_gesture = 0; });
    }
    layout->addLayout(m_form);
    m_remove = new QPushButton(tr("Remove Dynamics"), this);
    m_remove->setObjectName("removeDynamicsButton");
    m_remove->setToolTip(tr("Takes the dynamics out of the project (undo brings them back)"));
    connect(m_remove, &QPushButton::clicked, this,
            [this] { m_document->undoStack()->push(new SetDynamics(m_document, std::nullopt)); });
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_remove);
    layout->addLayout(buttons);

    m_results =
        new CheckList(tr("Forces (click one to go there):"), "forceResultsList", "forcesSummary",
                      tr("The forces over the turn: click a line to put the cursor there"), this);
    // Room for every line of a turn without lift-off (about nine, some wrapped).
    m_results->list()->setMinimumHeight(12 * fontMetrics().height());
    layout->addWidget(m_results, 1);
    connect(m_results, &CheckList::anglePicked, this, &ForcesPanel::anglePicked);

    m_plots[0] = turnPlot(this, "normalForcePlot", tr("Force [N]"),
                          tr("Contact normal force over the turn (blue), the law's own (dashed, "
                             "with a motion design) and the load along the follower's line or "
                             "the arm's moment (grey); shaded: the follower leaves the cam"));
    m_plots[1] = turnPlot(this, "torquePlot", tr("Torque [N·m]"),
                          tr("Torque on the camshaft over the turn"));
    m_plots[2] = turnPlot(this, "contactStressPlot", tr("Contact stress [MPa]"),
                          tr("Hertz contact stress over the turn; dashed: the allowable"));
    const QColor blue(20, 90, 160);
    m_plots[0]->addGraph()->setPen(QPen(blue, 1.0));
    m_plots[0]->addGraph()->setPen(QPen(blue, 1.0, Qt::DashLine));
    m_plots[0]->addGraph()->setPen(QPen(QColor(120, 120, 120), 1.0));
    m_plots[1]->addGraph()->setPen(QPen(blue, 1.0));
    m_plots[2]->addGraph()->setPen(QPen(blue, 1.0));
    m_allowable = new QCPItemStraightLine(m_plots[2]);
    m_allowable->setPen(QPen(QColor(200, 30, 30), 1, Qt::DashLine));
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        m_cursors[i] = addCursorLine(m_plots[i]);
        layout->addWidget(m_plots[i], 1);
    }
    connect(document, &ProjectDocument::dynamicsChanged, this, &ForcesPanel::refresh);
    connect(document, &ProjectDocument::followerChanged, this, &ForcesPanel::refresh);
    refresh();
}

void ForcesPanel::edit(const std::function<void(DynamicsSpec&)>& change) {
    const std::optional<DynamicsSpec>& before = m_document->project().dynamics;
    DynamicsSpec spec = before.value_or(DynamicsSpec{});
    change(spec);
    if (before && spec == *before) return;
    m_document->undoStack()->push(new SetDynamics(m_document, spec, m_gesture));
}

void ForcesPanel::refresh() {
    m_refreshing = true;
    const Project& project = m_document->project();
    const DynamicsSpec d = project.dynamics.value_or(DynamicsSpec{});
    const FollowerSpec follower = project.follower.value_or(FollowerSpec{});
    for (const DynamicsKeyInfo& info : dynamicsKeys()) {
        NumberSpinBox* spin = m_values[static_cast<std::size_t>(info.key)];
        spin->setValue(d[info.key].value_or(zeroClears(info.key) ? 0.0 : info.defaultValue));
        m_form->setRowVisible(spin, dynamicsKeyApplies(info.key, follower));
    }
    for (std::size_t g = 0; g < kMaterialKeys.size(); ++g) {
        QComboBox* box = m_materials[g];
        const auto& e = d[kMaterialKeys[g][0]];
        const auto& nu = d[kMaterialKeys[g][1]];
        const Material* m = e && nu ? materialWith(*e, *nu) : nullptr;
        // The picked one stays while it still has these values (steel and bearing steel share
        // theirs).
        const int current = box->currentIndex();
        const bool keep = m && current > 0 &&
                          materials()[static_cast<std::size_t>(current - 1)].modulusMpa == *e &&
                          materials()[static_cast<std::size_t>(current - 1)].poisson == *nu;
        if (!keep) box->setCurrentIndex(m ? static_cast<int>(m - materials().data()) + 1 : 0);
    }
    m_remove->setEnabled(project.dynamics.has_value());
    m_refreshing = false;
}

void ForcesPanel::setCursorX(double x) {
    for (QCPItemStraightLine* cursor : m_cursors) moveCursorLine(cursor, x);
}

void ForcesPanel::setResult(const ComputeResultPtr& result) {
    const bool curves = result && result->valid() && result->forces;
    for (QCustomPlot* plot : m_plots) plot->setVisible(curves);
    if (curves) {
        m_plots[2]->setVisible(result->forces->model.hasStress);
        showCurves(*result);
    }
    m_results->clear();
    if (!result || !result->project || !result->project->dynamics) {
        m_results->setSummary(
            tr("No dynamics: enter the follower's mass and its spring to see the "
               "forces, the jump speed and the contact stress."));
        return;
    }
    if (result->awaitsContour()) {
        m_results->setSummary(
            tr("No forces: no contour yet. Synthesize (F6) makes it from the "
               "design."));
        return;
    }
    if (!result->valid()) {
        const Diagnostics reasons = result->reasonsNotShown();
        m_results->setSummary(
            tr("No forces: %1")
                .arg(reasons.empty() ? QStringLiteral("?") : diagnosticText(reasons.front())));
        return;
    }
    if (!result->forces) {
        m_results->setSummary(tr("No forces: choose a follower in the Follower dock."));
        return;
    }
    showSummary(*result);
}

void ForcesPanel::showCurves(const ComputeResult& r) {
    const ForceCurves& f = *r.forces;
    const QVector<double> x(r.followerX.begin(), r.followerX.end());
    const bool ascending = x.size() < 2 || x.front() <= x.back();
    const auto data = [&](QCPGraph* graph, const std::vector<double>& y) {
        if (y.size() == static_cast<std::size_t>(x.size())) {
            graph->setData(x, QVector<double>(y.begin(), y.end()), ascending);
        } else {
            graph->data()->clear();
        }
    };
    static const std::vector<double> kNone;
    const std::vector<double>& law =
        r.design && !r.design->lawForces.normal.empty() ? r.design->lawForces.normal : kNone;
    data(m_plots[0]->graph(0), f.curves.normal);
    data(m_plots[0]->graph(1), law);
    data(m_plots[0]->graph(2), f.curves.load);
    m_plots[0]->graph(2)->setVisible(!f.model.swinging);  // an arm's moment is in N·m
    data(m_plots[1]->graph(0), f.curves.torque);
    data(m_plots[2]->graph(0), f.curves.stress);
    m_plots[0]->yAxis->setRange(
        rangeOf({&f.curves.normal, &law, f.model.swinging ? &kNone : &f.curves.load}));
    m_plots[1]->yAxis->setRange(rangeOf({&f.curves.torque}));
    QCPRange stress = rangeOf({&f.curves.stress});
    m_allowable->setVisible(f.model.allowableMpa.has_value());
    if (f.model.allowableMpa) {
        const double allowable = *f.model.allowableMpa;
        m_allowable->point1->setCoords(0, allowable);
        m_allowable->point2->setCoords(1, allowable);
        stress.upper = std::max(stress.upper, 1.08 * allowable);
    }
    m_plots[2]->yAxis->setRange(stress);
    // The lift-off ranges, shaded over the whole height of the force plot.
    for (QCPItemRect* shade : m_liftOff) m_plots[0]->removeItem(shade);
    m_liftOff.clear();
    for (const auto& [from, to] : f.summary.liftOff) {
        auto* shade = new QCPItemRect(m_plots[0]);
        shade->setPen(Qt::NoPen);
        shade->setBrush(QColor(220, 40, 40, 60));
        shade->topLeft->setTypeY(QCPItemPosition::ptAxisRectRatio);
        shade->bottomRight->setTypeY(QCPItemPosition::ptAxisRectRatio);
        shade->topLeft->setCoords(plotXOf(r, from), 0.0);
        shade->bottomRight->setCoords(plotXOf(r, to), 1.0);
        m_liftOff.push_back(shade);
    }
    const QString xLabel = r.axis == PlotAxis::Angle ? tr("φ [°]") : tr("t [s]");
    m_plots[0]->yAxis->setLabel(tr("Force [N]"));
    for (QCustomPlot* plot : m_plots) {
        plot->xAxis->setLabel(xLabel);
        queueReplot(plot);
    }
}

void ForcesPanel::showSummary(const ComputeResult& r) {
    const ForceCurves& f = *r.forces;
    const ForceSummary& s = f.summary;
    const ForceModel& m = f.model;
    const auto add = [this](const QString& text, std::optional<double> phi, bool problem) {
        m_results->add(text, phi, problem);
    };
    const DisplayQuantity load = m.swinging ? DisplayQuantity::Moment : DisplayQuantity::Force;
    const auto rpm = [](double radPerS) {
        return formatQuantity(DisplayQuantity::RotationSpeed, radPerS * 60.0 / kTwoPi);
    };
    if (m.formClosed()) {
        // A groove holds the roller: where the load turns negative it crosses its clearance
        // and strikes the outer flank (a knock a designer moves into a slow stretch). On a
        // conjugate pair the second roller takes the load over from the first there.
        const bool groove = m.grooved();
        if (s.liftOff.empty()) {
            add(groove ? tr("The inner flank carries the load over the whole turn.")
                       : tr("The first plate carries the load over the whole turn."),
                std::nullopt, false);
        }
        for (const auto& [from, to] : s.liftOff) {
            add((groove ? tr("The roller crosses to the outer flank at %1 and back at %2")
                        : tr("The second roller takes the load over at %1 and gives it back at "
                             "%2"))
                    .arg(formatRadians(from), formatRadians(to)),
                from, false);
        }
        if (s.maxNormalSecond && s.maxNormalSecondAt) {
            add((groove ? tr("Largest normal force on the outer flank: %1 at %2")
                        : tr("Largest normal force on the second roller: %1 at %2"))
                    .arg(formatQuantity(DisplayQuantity::Force, *s.maxNormalSecond),
                         formatRadians(*s.maxNormalSecondAt)),
                *s.maxNormalSecondAt, false);
        }
        if (s.maxStressSecond && s.maxStressSecondAt) {
            const bool over = m.allowableMpa && *s.maxStressSecond > *m.allowableMpa;
            add(m.allowableMpa
                    ? (groove ? tr("Largest contact stress on the outer flank: %1 at %2, %3 % of "
                                   "the allowable %4")
                              : tr("Largest contact stress on the second plate: %1 at %2, %3 % "
                                   "of the allowable %4"))
                          .arg(formatQuantity(DisplayQuantity::Stress, *s.maxStressSecond),
                               formatRadians(*s.maxStressSecondAt),
                               formatQuantity(DisplayQuantity::Ratio,
                                              100.0 * *s.maxStressSecond / *m.allowableMpa),
                               formatQuantity(DisplayQuantity::Stress, *m.allowableMpa))
                    : (groove ? tr("Largest contact stress on the outer flank: %1 at %2")
                              : tr("Largest contact stress on the second plate: %1 at %2"))
                          .arg(formatQuantity(DisplayQuantity::Stress, *s.maxStressSecond),
                               formatRadians(*s.maxStressSecondAt)),
                *s.maxStressSecondAt, over);
        }
    } else {
        if (s.liftOff.empty()) {
            add(tr("The follower stays on the cam over the whole turn."), std::nullopt, false);
        }
        for (const auto& [from, to] : s.liftOff) {
            add(tr("The follower leaves the cam from %1 to %2")
                    .arg(formatRadians(from), formatRadians(to)),
                from, true);
        }
        const double speed = std::abs(r.omega);
        if (std::isfinite(s.jumpSpeed)) {
            add(tr("Jump speed: %1 at %2 (the cam runs at %3)")
                    .arg(rpm(s.jumpSpeed), formatRadians(s.jumpSpeedAt), rpm(speed)),
                s.jumpSpeedAt, s.jumpSpeed <= speed);
        } else {
            add(tr("No speed lifts the follower off the cam."), std::nullopt, false);
        }
        const DynamicsSpec& d = *r.project->dynamics;
        const double preload = dynamicsValue(
            d, m.swinging ? DynamicsKey::SpringPreloadNm : DynamicsKey::SpringPreloadN);
        add(tr("Least preload for a safety factor of %1: %2 at %3 (the spring has %4)")
                .arg(formatQuantity(DisplayQuantity::Ratio, m.safetyFactor),
                     formatQuantity(load, s.minPreload), formatRadians(s.minPreloadAt),
                     formatQuantity(load, preload)),
            s.minPreloadAt, preload < s.minPreload);
    }
    add((m.grooved()     ? tr("Largest normal force on the inner flank: %1 at %2")
         : m.conjugate() ? tr("Largest normal force on the first roller: %1 at %2")
                         : tr("Largest normal force: %1 at %2"))
            .arg(formatQuantity(DisplayQuantity::Force, s.maxNormal), formatRadians(s.maxNormalAt)),
        s.maxNormalAt, false);
    add(tr("Peak torque on the camshaft: %1 at %2; RMS %3")
            .arg(formatQuantity(DisplayQuantity::Moment, s.peakTorque),
                 formatRadians(s.peakTorqueAt),
                 formatQuantity(DisplayQuantity::Moment, s.rmsTorque)),
        s.peakTorqueAt, false);
    add(tr("Peak power: %1").arg(formatQuantity(DisplayQuantity::Power, s.peakPower)), std::nullopt,
        false);
    if (s.maxStress && s.maxStressAt) {
        if (m.allowableMpa) {
            add((m.grooved() ? tr("Largest contact stress on the inner flank: %1 at %2, %3 % of "
                                  "the allowable %4")
                 : m.conjugate()
                     ? tr("Largest contact stress on the first plate: %1 at %2, %3 % of the "
                          "allowable %4")
                     : tr("Largest contact stress: %1 at %2, %3 % of the allowable %4"))
                    .arg(formatQuantity(DisplayQuantity::Stress, *s.maxStress),
                         formatRadians(*s.maxStressAt),
                         formatQuantity(DisplayQuantity::Ratio,
                                        100.0 * *s.maxStress / *m.allowableMpa),
                         formatQuantity(DisplayQuantity::Stress, *m.allowableMpa)),
                *s.maxStressAt, *s.maxStress > *m.allowableMpa);
        } else {
            add((m.grooved() ? tr("Largest contact stress on the inner flank: %1 at %2 (no "
                                  "allowable stress given)")
                 : m.conjugate()
                     ? tr("Largest contact stress on the first plate: %1 at %2 (no allowable "
                          "stress given)")
                     : tr("Largest contact stress: %1 at %2 (no allowable stress given)"))
                    .arg(formatQuantity(DisplayQuantity::Stress, *s.maxStress),
                         formatRadians(*s.maxStressAt)),
                *s.maxStressAt, false);
        }
    } else {
        add(m.followerCurvature == 0.0 && !m.hasStress && r.follower &&
                    r.follower->spec().type == FollowerType::Knife
                ? tr("No contact stress: a knife edge touches the cam at a point.")
                : tr("No contact stress: give the contact width and both materials."),
            std::nullopt, false);
    }
    if (!s.jumps.empty()) {
        const auto largest = std::max_element(
            s.jumps.begin(), s.jumps.end(), [](const ForceJump& a, const ForceJump& b) {
                return std::abs(a.after.normal - a.before.normal) <
                       std::abs(b.after.normal - b.before.normal);
            });
        add(tr("The normal force jumps at %n joint(s) of the contour, by up to %1 at %2", nullptr,
               static_cast<int>(s.jumps.size()))
                .arg(formatQuantity(DisplayQuantity::Force,
                                    std::abs(largest->after.normal - largest->before.normal)),
                     formatRadians(largest->phi)),
            largest->phi, false);
    }
    // The price of the arcs: the force on the synthesised contour against the law's own.
    if (r.design && r.design->lawForces.normal.size() == f.curves.normal.size()) {
        double most = 0.0;
        std::size_t at = 0;
        for (std::size_t k = 0; k < f.curves.normal.size(); ++k) {
            const double diff = std::abs(f.curves.normal[k] - r.design->lawForces.normal[k]);
            if (diff > most) {
                most = diff;
                at = k;
            }
        }
        const std::size_t n = f.curves.normal.size() - 1;
        const double phi =
            r.omega * r.period * static_cast<double>(at % n) / static_cast<double>(n);
        add(tr("The contour's normal force differs from the law's by up to %1 at %2")
                .arg(formatQuantity(DisplayQuantity::Force, most), formatRadians(phi)),
            phi, false);
    }
    const int problems = m_results->problemCount();
    m_results->setSummary(problems == 0 ? tr("The follower stays on; every force check passes.")
                                        : tr("%n force check(s) fail.", nullptr, problems));
}

QStringList ForcesPanel::resultLines() const { return m_results->lines(); }

int ForcesPanel::problemCount() const { return m_results->problemCount(); }

}  // namespace cam
