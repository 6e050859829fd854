#include "views/machining_panel.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <functional>

#include "document/commands.h"
#include "messages/diagnostic_text.h"
#include "models/delegates.h"
#include "views/palette.h"
#include "views/plot_data.h"
#include "views/plot_redraw.h"
#include "views/plot_setup.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

NumberSpinBox* spinBox(QWidget* parent, const QString& suffix, const QString& tip) {
    auto* s = new NumberSpinBox(parent);
    s->setSuffix(suffix);
    s->setToolTip(tip);
    return s;
}

QCustomPlot* smallPlot(QWidget* parent, const QString& xLabel, const QString& yLabel) {
    QCustomPlot* p = newAlongXPlot(parent, nullptr, yLabel);
    p->setMinimumHeight(150);
    p->xAxis->setLabel(xLabel);
    return p;
}

}  // namespace

MachiningPanel::MachiningPanel(ProjectDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    m_addButton = new QPushButton(tr("Add Machining Limits"), this);
    m_addButton->setObjectName("addMachiningButton");
    m_addButton->setToolTip(tr("This project has no machining limits yet: add sensible defaults"));
    layout->addWidget(m_addButton);

    m_form = new QWidget(this);
    auto* grid = new QGridLayout(m_form);
    grid->setContentsMargins(0, 0, 0, 0);
    const char* axes[] = {"X", "Y", "Z"};
    grid->addWidget(new QLabel(tr("Acceleration"), m_form), 0, 0);
    for (int i = 0; i < 3; ++i) {
        m_accel[i] =
            spinBox(m_form, " mm/s²", tr("Acceleration limit of the %1 axis").arg(axes[i]));
        m_accel[i]->setObjectName(QStringLiteral("accel%1SpinBox").arg(axes[i]));
        m_accel[i]->setSingleStep(10.0);
        if (i == 2) {
            // Two axes are enough for a contour in the plane: Z's limit may be left out.
            m_accel[i]->setMinimum(0.0);
            m_accel[i]->setSpecialValueText(tr("none"));
            m_accel[i]->setToolTip(tr("Acceleration limit of the Z axis (none: only X and Y)"));
        }
        grid->addWidget(m_accel[i], 0, i + 1);
    }
    m_vmaxEnabled = new QCheckBox(tr("Velocity"), m_form);
    m_vmaxEnabled->setObjectName("vmaxCheckBox");
    m_vmaxEnabled->setToolTip(tr("Limit the velocity of each axis"));
    grid->addWidget(m_vmaxEnabled, 1, 0);
    for (int i = 0; i < 3; ++i) {
        m_vmax[i] = spinBox(m_form, " mm/s", tr("Velocity limit of the %1 axis").arg(axes[i]));
        m_vmax[i]->setObjectName(QStringLiteral("vmax%1SpinBox").arg(axes[i]));
        grid->addWidget(m_vmax[i], 1, i + 1);
    }
    m_feed = spinBox(m_form, " mm/s", tr("Feed ceiling along the path"));
    m_toolRadius =
        spinBox(m_form, " mm", tr("Radius of the tool: the path is the contour offset by it"));
    m_toolRadius->setSingleStep(0.1);
    m_feed->setObjectName("feedSpinBox");
    m_toolRadius->setObjectName("toolRadiusSpinBox");
    m_step = spinBox(m_form, " mm", tr("Step of the seed method"));
    m_step->setSingleStep(0.1);
    m_step->setObjectName("seedStepSpinBox");
    grid->addWidget(new QLabel(tr("Feed"), m_form), 2, 0);
    grid->addWidget(m_feed, 2, 1);
    grid->addWidget(new QLabel(tr("Tool radius"), m_form), 2, 2);
    grid->addWidget(m_toolRadius, 2, 3);
    grid->addWidget(new QLabel(tr("Seed step"), m_form), 3, 0);
    grid->addWidget(m_step, 3, 1);
    m_method = new QComboBox(m_form);
    m_method->setObjectName("plotMethodComboBox");
    m_method->addItems({tr("Seed"), tr("Exact stop"), tr("Optimal")});
    m_method->setCurrentIndex(2);
    m_method->setToolTip(tr("The method whose feed and accelerations are plotted"));
    grid->addWidget(new QLabel(tr("Plot"), m_form), 3, 2);
    grid->addWidget(m_method, 3, 3);
    layout->addWidget(m_form);

    auto* times = new QHBoxLayout;
    const QString names[] = {tr("Seed"), tr("Exact stop"), tr("Optimal")};
    const QString tips[] = {
        tr("The seed document's 1 mm steps from rest to mid-segment, doubled: a legacy estimate "
           "that ignores the speed rising within a step"),
        tr("Rest to rest on every segment"),
        tr("Minimum time along the whole path, stopping only at corners")};
    for (int m = 0; m < 3; ++m) {
        m_times[m] = new QLabel(this);
        m_times[m]->setObjectName(QString("time%1").arg(m));
        m_times[m]->setToolTip(tips[m]);
        m_times[m]->setAlignment(Qt::AlignCenter);
        m_times[m]->setProperty("name", names[m]);
        times->addWidget(m_times[m]);
    }
    layout->addLayout(times);
    m_status = new QLabel(this);
    m_status->setObjectName("machiningStatus");
    m_status->setWordWrap(true);
    layout->addWidget(m_status);

    m_feedPlot = smallPlot(this, tr("path [mm]"), tr("feed [mm/s]"));
    m_feedPlot->addGraph()->setPen(QPen(QColor(40, 40, 40), 1.2));
    m_accelPlot = smallPlot(this, tr("path [mm]"), tr("axis accel. [mm/s²]"));
    for (int i = 0; i < 3; ++i) {
        QCPGraph* g = m_accelPlot->addGraph();
        g->setPen(QPen(segmentColor(i), 1.0));
        g->setName(QString("a_%1").arg(QChar('x' + i)));
    }
    m_accelPlot->legend->setVisible(true);
    m_accelPlot->legend->setFont(QFont(font().family(), 8));
    m_accelPlot->legend->setBrush(QColor(255, 255, 255, 200));
    layout->addWidget(m_feedPlot, 1);
    layout->addWidget(m_accelPlot, 1);

    connect(m_addButton, &QPushButton::clicked, this, [this] {
        m_document->undoStack()->push(new SetMachining(m_document, MachiningSpec{}));
    });
    // Each field edits only its own value of the document: the others are never rewritten
    // from what the spin boxes show.
    auto field = [this](NumberSpinBox* s, std::function<void(MachiningSpec&, double)> set) {
        connect(s, &QDoubleSpinBox::valueChanged, this, [this, set](double v) {
            if (m_refreshing || !m_document->project().machining) return;
            if (m_gesture == 0) m_gesture = nextGestureId();
            MachiningSpec m = *m_document->project().machining;
            set(m, v);
            if (m != *m_document->project().machining) push(m);
        });
        connect(s, &QDoubleSpinBox::editingFinished, this, [this] { m_gesture = 0; });
    };
    for (std::size_t i = 0; i < 3; ++i) {
        field(m_accel[i], [i](MachiningSpec& m, double v) {
            if (i < 2) {
                m.axisAccel[i] = v;
            } else if (v > 0.0) {
                m.axisAccel.resize(3);
                m.axisAccel[2] = v;
            } else {
                m.axisAccel.resize(2);  // "none": Z unlimited
            }
        });
        field(m_vmax[i], [this, i](MachiningSpec& m, double v) {
            if (m.axisVmax.empty()) return;  // the limits are switched off
            for (std::size_t j = m.axisVmax.size(); j <= i; ++j) {
                m.axisVmax.push_back(m_vmax[j]->value());
            }
            m.axisVmax[i] = v;
        });
    }
    field(m_feed, [](MachiningSpec& m, double v) { m.feedMax = v; });
    field(m_toolRadius, [](MachiningSpec& m, double v) { m.toolRadius = v; });
    field(m_step, [](MachiningSpec& m, double v) { m.step = v; });
    connect(m_vmaxEnabled, &QCheckBox::toggled, this, [this](bool on) {
        if (m_refreshing || !m_document->project().machining) return;
        MachiningSpec m = *m_document->project().machining;
        m.axisVmax.clear();
        if (on) {
            for (std::size_t i = 0; i < m.axisAccel.size(); ++i)
                m.axisVmax.push_back(m_vmax[i]->value());
        }
        m_gesture = 0;
        push(m);
    });
    connect(m_method, &QComboBox::currentIndexChanged, this, &MachiningPanel::plotMethodChanged);
    connect(document, &ProjectDocument::machiningChanged, this, &MachiningPanel::refresh);
    refresh();
}

TimingMethod MachiningPanel::plotMethod() const {
    return static_cast<TimingMethod>(m_method->currentIndex());
}

void MachiningPanel::push(const MachiningSpec& spec) {
    m_document->undoStack()->push(new SetMachining(m_document, spec, m_gesture));
}

void MachiningPanel::refresh() {
    m_refreshing = true;
    const auto& spec = m_document->project().machining;
    m_addButton->setVisible(!spec);
    m_form->setVisible(spec.has_value());
    m_feedPlot->setVisible(spec.has_value());
    m_accelPlot->setVisible(spec.has_value());
    for (QLabel* l : m_times) l->setVisible(spec.has_value());
    if (spec) {
        for (std::size_t i = 0; i < 3; ++i) {
            m_accel[i]->setValue(i < spec->axisAccel.size() ? spec->axisAccel[i] : 0.0);
            m_vmax[i]->setValue(i < spec->axisVmax.size() ? spec->axisVmax[i] : 100.0);
            m_vmax[i]->setEnabled(!spec->axisVmax.empty());
        }
        m_vmaxEnabled->setChecked(!spec->axisVmax.empty());
        m_feed->setValue(spec->feedMax);
        m_toolRadius->setValue(spec->toolRadius);
        m_step->setValue(spec->step);
        m_status->setText(tr("Computing…"));
    } else {
        m_status->setText(tr("Machining times need the machine's axis limits."));
    }
    m_refreshing = false;
}

void MachiningPanel::setPending() {
    if (m_document->project().machining) m_status->setText(tr("Computing…"));
}

void MachiningPanel::setOutcome(const TimingOutcomePtr& outcome) {
    if (!outcome->errors.empty()) {
        QStringList lines;
        for (const Diagnostic& d : outcome->errors) lines << diagnosticText(d);
        m_status->setText(tr("No machining time: %1").arg(lines.join("; ")));
        for (QLabel* l : m_times) l->setText("—");
        // Nor the profiles of an earlier path, which would pass for this one's.
        m_feedPlot->graph(0)->data()->clear();
        for (int i = 0; i < m_accelPlot->graphCount(); ++i) m_accelPlot->graph(i)->data()->clear();
        queueReplot(m_feedPlot);
        queueReplot(m_accelPlot);
        return;
    }
    const int plotted = static_cast<int>(outcome->plotted);
    QStringList estimates;
    for (int m = 0; m < 3; ++m) {
        const auto k = static_cast<std::size_t>(m);
        // A time whose refinement stopped short is an estimate, and shown as one.
        const QString text = QStringLiteral("%1\n%2%3")
                                 .arg(m_times[m]->property("name").toString(),
                                      outcome->converged[k] ? QString() : QStringLiteral("≈ "),
                                      formatQuantity(DisplayQuantity::Time, outcome->timesS[k]));
        if (!outcome->converged[k]) {
            estimates << tr("%1 (relative error about %2)")
                             .arg(m_times[m]->property("name").toString(),
                                  formatQuantity(DisplayQuantity::RelativeError,
                                                 outcome->convergence[k]));
        }
        m_times[m]->setText(text);
        QFont f = m_times[m]->font();
        f.setBold(m == plotted);
        m_times[m]->setFont(f);
    }
    m_status->setText(
        tr("Path %1 (contour offset by the tool radius); optimal plan on %2 "
           "grid points; computed in %3")
            .arg(formatQuantity(DisplayQuantity::Length, outcome->lengthMm),
                 formatQuantity(DisplayQuantity::Count, static_cast<double>(outcome->gridPoints)),
                 formatQuantity(DisplayQuantity::Duration, outcome->computeMs)));
    if (!estimates.isEmpty()) {
        m_status->setText(m_status->text() + "\n" +
                          tr("Not converged: the grid limit stopped the refinement first, so "
                             "these times are estimates: %1.")
                              .arg(estimates.join(", ")));
    }
    // Made in the worker by the views' preparer; made here only without one (tests).
    auto data = std::dynamic_pointer_cast<const MachiningPlotData>(outcome->prepared);
    if (!data) data = makeMachiningPlotData(*outcome);
    m_feedPlot->graph(0)->setData(data->feed);
    m_feedPlot->rescaleAxes();
    m_feedPlot->yAxis->setRangeLower(0.0);
    m_feedPlot->yAxis->scaleRange(1.08, m_feedPlot->yAxis->range().lower);
    queueReplot(m_feedPlot);
    double limit = 0.0;
    for (int i = 0; i < 3; ++i) {
        m_accelPlot->graph(i)->setData(data->accel[static_cast<std::size_t>(i)]);
        if (std::isfinite(outcome->limits.accel[i])) {
            limit = std::max(limit, outcome->limits.accel[i]);
        }
    }
    m_accelPlot->rescaleAxes();
    m_accelPlot->yAxis->setRange(-1.1 * limit, 1.1 * limit);
    queueReplot(m_accelPlot);
}

QString MachiningPanel::timesText() const {
    QStringList parts;
    for (QLabel* l : m_times) parts << l->text().replace('\n', ' ');
    return parts.join(" · ");
}

}  // namespace cam
