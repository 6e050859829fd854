#include "views/motion_design_panel.h"

#include <qcustomplot.h>

#include <QAction>
#include <QCheckBox>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableView>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "common/angles.h"
#include "common/diagnostic_catalogue.h"
#include "design/boundary_classes.h"
#include "design/motion_table.h"
#include "design/sizing.h"
#include "document/commands.h"
#include "engine/background_priority.h"
#include "messages/diagnostic_text.h"
#include "messages/field_titles.h"
#include "models/delegates.h"
#include "models/design_table_model.h"
#include "project/follower_kind.h"
#include "views/feasible_region_plot.h"
#include "views/plot_data.h"
#include "views/plot_redraw.h"
#include "views/plot_setup.h"
#include "widgets/column_fit.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"
#include "widgets/read_only_cells.h"

namespace cam {
namespace {

NumberSpinBox* lengthBox(QWidget* parent, const char* name, const QString& tip) {
    auto* s = new NumberSpinBox(parent);
    s->setObjectName(name);
    s->setSuffix(QStringLiteral(" mm"));
    s->setToolTip(tip);
    s->setMinimum(1e-6);
    s->setMaximum(1e6);
    s->setMinimumWidth(80);
    return s;
}

/// The quantities of the errors in lift, velocity and acceleration: a swinging arm's lift is
/// its angle.
std::array<DisplayQuantity, 3> liftErrorQuantities(bool swinging) {
    if (swinging) {
        return {DisplayQuantity::AngleError, DisplayQuantity::AngularVelocityError,
                DisplayQuantity::AngularAccelerationError};
    }
    return {DisplayQuantity::LengthError, DisplayQuantity::VelocityError,
            DisplayQuantity::AccelerationError};
}

/// Whether a feasible region made for `was` still describes `now`: the same design and follower
/// but for the base radius and the placement, its axes (an arm's pivot keeps its direction).
bool sameRegion(const DesignSpec& wasDesign, const FollowerSpec& wasFollower,
                const DesignSpec& nowDesign, const FollowerSpec& nowFollower, Placement placement) {
    DesignSpec design = nowDesign;
    design.baseRadius = wasDesign.baseRadius;
    if (design != wasDesign) return false;
    FollowerSpec follower = nowFollower;
    if (placement == Placement::Offset) {
        follower.offset = wasFollower.offset;
    } else {
        const double was = std::atan2(wasFollower.pivot.y(), wasFollower.pivot.x());
        const double now = std::atan2(nowFollower.pivot.y(), nowFollower.pivot.x());
        if (std::abs(std::remainder(was - now, 2.0 * std::numbers::pi)) > 1e-9) return false;
        follower.pivot = wasFollower.pivot;
    }
    return follower == wasFollower;
}

/// The law: dashed; the follower riding the contour: solid (as on the kinematics plots).
const QPen kLawPen(QColor(0, 130, 60), 1.6, Qt::DashLine);
const QPen kFollowerPen(QColor(230, 120, 0), 1.2);

}  // namespace

MotionDesignPanel::MotionDesignPanel(ProjectDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_model(new DesignTableModel(document, this)) {
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_newDesign = new QPushButton(tr("New Design"), this);
    m_newDesign->setObjectName("newDesignButton");
    m_newDesign->setToolTip(
        tr("Start from a cycloidal dwell–rise–dwell–return motion (math.md §8) and edit it"));
    m_removeDesign = new QPushButton(tr("Remove Design"), this);
    m_removeDesign->setObjectName("removeDesignButton");
    m_removeDesign->setToolTip(tr("Remove the motion design from the project (the contour stays)"));
    top->addWidget(m_newDesign);
    top->addWidget(m_removeDesign);
    top->addStretch(1);
    layout->addLayout(top);

    auto* form = new QFormLayout;
    m_baseRadius = lengthBox(this, "baseRadiusSpinBox",
                             tr("Radius of the base circle the follower touches at lift 0"));
    m_baseRadius->setSingleStep(1.0);
    m_size = new QPushButton(tr("Smallest"), this);
    m_size->setObjectName("sizeBaseRadiusButton");
    m_size->setToolTip(
        tr("Set the smallest base radius for which the follower passes every check: the "
           "pressure angle within its limit on rise and return, no undercut (one undo step)"));
    m_bestPlacement = new QPushButton(this);  // text and tip: updateSizingButtons
    m_bestPlacement->setObjectName("bestPlacementButton");
    m_sizing = new QLabel(this);
    m_sizing->setObjectName("sizingLabel");
    m_sizing->setWordWrap(true);
    m_sizing->setVisible(false);
    m_region = new FeasibleRegionPlot(this);
    m_region->setVisible(false);
    auto* radiusRow = new QHBoxLayout;
    radiusRow->addWidget(m_baseRadius, 1);
    radiusRow->addWidget(m_size);
    radiusRow->addWidget(m_bestPlacement);
    m_tolerance = lengthBox(this, "toleranceSpinBox",
                            tr("Largest distance of the arc table from the exact profile"));
    m_tolerance->setSingleStep(0.001);
    m_strict = new QCheckBox(tr("Refuse pressure angles beyond the limit"), this);
    m_strict->setObjectName("strictPressureAngleCheckBox");
    m_strict->setToolTip(
        tr("Synthesize refuses a design whose pressure angle exceeds the "
           "follower's limit (otherwise it is only reported)"));
    form->addRow(tr("Base radius"), radiusRow);
    form->addRow(QString(), m_sizing);
    form->addRow(m_region);
    form->addRow(tr("Tolerance"), m_tolerance);
    form->addRow(QString(), m_strict);
    layout->addLayout(form);

    m_table = new QTableView(this);
    m_table->setObjectName("designTable");
    m_table->setModel(m_model);
    auto* numbers = new NumberDelegate(m_table);
    auto* choices = new ChoiceDelegate(m_table);
    for (int c = 0; c < DesignTableModel::ColumnCount; ++c) {
        m_table->setItemDelegateForColumn(
            c, c == DesignTableModel::Law ? static_cast<QAbstractItemDelegate*>(choices) : numbers);
    }
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    // Columns wide enough from the start for any class and any Cv, Ca, Cj a law can have, so
    // that picking a law moves no column under the mouse.
    m_table->horizontalHeader()->setMinimumSectionSize(
        std::max({m_table->fontMetrics().horizontalAdvance(QStringLiteral("0000.000")),
                  m_table->fontMetrics().horizontalAdvance(DesignTableModel::tr("Movement")),
                  m_table->fontMetrics().horizontalAdvance(DesignTableModel::tr("Reversal")),
                  m_table->fontMetrics().horizontalAdvance(DesignTableModel::tr("Velocity"))}) +
        14);
    keepColumnsFitting(m_table);
    sayWhyCellsAreReadOnly(m_table);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
    m_table->setSelectionBehavior(QAbstractItemView::SelectItems);
    m_table->setMinimumSize(120, 100);
    layout->addWidget(m_table, 1);

    auto* rows = new QHBoxLayout;
    m_split = new QPushButton(tr("Split"), this);
    m_split->setObjectName("splitDesignSegmentButton");
    m_split->setToolTip(tr("Split the selected segment at its middle: the second half dwells"));
    m_delete = new QPushButton(tr("Delete"), this);
    m_delete->setObjectName("deleteDesignSegmentButton");
    m_delete->setToolTip(
        tr("Delete the selected segment: the one before it takes over its stretch and lift"));
    m_synthesize = new QToolButton(this);
    m_synthesize->setObjectName("synthesizeButton");
    m_synthesize->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_suggest = new QPushButton(tr("Suggest"), this);
    m_suggest->setObjectName("suggestLawButton");
    m_suggest->setToolTip(
        tr("Choose the recommended law for the selected segment from the boundary classes its "
           "neighbours demand (VDI 2143, CODESYS SoftMotion's table)"));
    m_suggestAll = new QPushButton(tr("Suggest All"), this);
    m_suggestAll->setObjectName("suggestAllLawsButton");
    m_suggestAll->setToolTip(
        tr("Choose the recommended law for every segment that is not a "
           "dwell or a line"));
    m_importTable = new QPushButton(tr("Import Table…"), this);
    m_importTable->setObjectName("importMotionTableButton");
    m_importTable->setToolTip(
        tr("Make the selected segment a motion table from a text file of points: x and y "
           "from 0 to 1 in two columns (as Inventor writes them), optionally dy/dx in a third"));
    rows->addWidget(m_split);
    rows->addWidget(m_delete);
    rows->addWidget(m_suggest);
    rows->addWidget(m_suggestAll);
    rows->addWidget(m_importTable);
    rows->addStretch(1);
    layout->addLayout(rows);
    m_suggestion = new QLabel(this);
    m_suggestion->setObjectName("suggestionLabel");
    m_suggestion->setWordWrap(true);
    m_suggestion->hide();
    layout->addWidget(m_suggestion);
    m_synthesize->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    layout->addWidget(m_synthesize);

    m_report = new QLabel(this);
    m_report->setObjectName("synthesisReportLabel");
    m_report->setWordWrap(true);
    m_report->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_report);
    m_notes = new QLabel(this);
    m_notes->setObjectName("designNotesLabel");
    m_notes->setWordWrap(true);
    m_notes->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_notes);

    m_plotArea = new QWidget(this);
    auto* plots = new QVBoxLayout(m_plotArea);
    plots->setContentsMargins(0, 0, 0, 0);
    plots->setSpacing(0);
    // The key above the plots, where it hides no curve.
    auto* key = new QLabel(m_plotArea);
    key->setObjectName("designPlotKey");
    key->setText(QStringLiteral("<span style='color:%1'>╌╌ %2</span>&nbsp;&nbsp;&nbsp;"
                                "<span style='color:%3'>── %4</span>")
                     .arg(kLawPen.color().name(), tr("law").toHtmlEscaped(),
                          kFollowerPen.color().name(),
                          tr("follower on the contour").toHtmlEscaped()));
    plots->addWidget(key);
    const char* names[] = {"designLiftPlot", "designVelocityPlot", "designAccelerationPlot",
                           "designJerkPlot"};
    auto* group = new QCPMarginGroup(nullptr);
    for (std::size_t p = 0; p < 4; ++p) {
        QCustomPlot* plot = newAlongXPlot(m_plotArea, names[p], QString());
        plot->setMinimumHeight(70);
        plot->xAxis->setTickLabels(p == 3);
        QCPGraph* law = plot->addGraph();
        law->setName(tr("law"));
        law->setPen(kLawPen);
        QCPGraph* follower = plot->addGraph();
        follower->setName(tr("follower on the contour"));
        follower->setPen(kFollowerPen);
        m_cursors[p] = addCursorLine(plot);
        plot->axisRect()->setMarginGroup(QCP::msLeft | QCP::msRight, group);
        m_plots[p] = plot;
        plots->addWidget(plot, 1);
    }
    group->setParent(m_plots[0]);
    for (QCustomPlot* a : m_plots) {
        for (QCustomPlot* b : m_plots) {
            if (a == b) continue;
            connect(a->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), b,
                    [b](const QCPRange& r) {
                        if (b->xAxis->range() != r) {
                            b->xAxis->setRange(r);
                            queueReplot(b);
                        }
                    });
        }
    }
    layout->addWidget(m_plotArea, 2);

    connect(m_newDesign, &QPushButton::clicked, this, &MotionDesignPanel::newDesign);
    connect(m_removeDesign, &QPushButton::clicked, this, [this] {
        m_document->undoStack()->push(new SetDesign(m_document, std::nullopt, tr("Remove design")));
    });
    connect(m_size, &QPushButton::clicked, this, &MotionDesignPanel::sizeBaseRadius);
    connect(m_bestPlacement, &QPushButton::clicked, this, &MotionDesignPanel::sizePlacement);
    connect(m_split, &QPushButton::clicked, this, [this] { splitSegment(currentRow()); });
    connect(m_delete, &QPushButton::clicked, this, [this] { deleteSegment(currentRow()); });
    connect(m_suggest, &QPushButton::clicked, this, [this] {
        if (currentRow() >= 0) suggestLaw(currentRow());
    });
    connect(m_suggestAll, &QPushButton::clicked, this, [this] { suggestLaw(-1); });
    connect(m_importTable, &QPushButton::clicked, this, [this] {
        const int row = currentRow();
        if (row < 0) return;
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Import Motion Table"), QString(),
                                         tr("Motion tables (*.txt *.csv *.dat);;All files (*)"));
        if (path.isEmpty()) return;
        QFile file(path);
        QString problem;
        if (!file.open(QIODevice::ReadOnly) || file.size() > 16 * 1024 * 1024) {
            problem = tr("%1: cannot be read").arg(QDir::toNativeSeparators(path));
        } else {
            problem = importTable(row, QString::fromUtf8(file.readAll()));
            if (!problem.isEmpty()) problem = QDir::toNativeSeparators(path) + ": " + problem;
        }
        if (!problem.isEmpty()) QMessageBox::warning(this, tr("Import Motion Table"), problem);
    });
    const auto number = [this](NumberSpinBox* box, std::function<void(DesignSpec&, double)> set,
                               QString text) {
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, set, text](double v) {
            if (m_refreshing || !m_document->project().design) return;
            if (m_gesture == 0) m_gesture = nextGestureId();
            editDesign([&](DesignSpec& d) { set(d, v); }, text, m_gesture);
        });
        connect(box, &QDoubleSpinBox::editingFinished, this, [this] { m_gesture = 0; });
    };
    number(
        m_baseRadius, [](DesignSpec& d, double v) { d.baseRadius = v; }, tr("Change base radius"));
    number(
        m_tolerance, [](DesignSpec& d, double v) { d.tolerance = v; }, tr("Change tolerance"));
    connect(m_strict, &QCheckBox::toggled, this, [this](bool on) {
        if (m_refreshing || !m_document->project().design) return;
        editDesign([on](DesignSpec& d) { d.strictPressureAngle = on; },
                   tr("Change pressure-angle strictness"), 0);
    });
    connect(m_document, &ProjectDocument::designChanged, this, &MotionDesignPanel::refresh);
    connect(m_document, &ProjectDocument::followerChanged, this, &MotionDesignPanel::refresh);
    connect(m_document, &ProjectDocument::changed, this, &MotionDesignPanel::dropStaleTexts);
    refresh();
}

void MotionDesignPanel::setSynthesizeAction(QAction* action) {
    m_synthesize->setDefaultAction(action);
}

int MotionDesignPanel::currentRow() const {
    const QModelIndex current = m_table->currentIndex();
    return current.isValid() ? current.row() : -1;
}

void MotionDesignPanel::editDesign(const std::function<void(DesignSpec&)>& change,
                                   const QString& text, int gesture) {
    DesignSpec design = *m_document->project().design;
    change(design);
    if (design == *m_document->project().design) return;
    m_document->undoStack()->push(new SetDesign(m_document, design, text, gesture));
}

template <class Answer>
void MotionDesignPanel::runSizing(
    const QString& busy, Result<Answer> (*job)(const DesignSpec&, const FollowerSpec&),
    const std::function<void(const Answer&, const DesignSpec&, const FollowerSpec&)>& apply) {
    // The GUI thread never computes: the design and follower are snapshotted, sized in the
    // background, and the answer applied only if they are still what was sized.
    const DesignSpec design = *m_document->project().design;
    const FollowerSpec follower = m_document->project().follower.value_or(FollowerSpec{});
    m_sizingRuns = true;
    m_sizingFor.reset();  // the line says it runs, whatever changes meanwhile
    updateSizingButtons();
    m_sizing->setVisible(true);
    m_sizing->setStyleSheet(QString());
    m_sizing->setText(busy);
    auto* watcher = new QFutureWatcher<Result<Answer>>(this);
    connect(watcher, &QFutureWatcher<Result<Answer>>::finished, this,
            [this, watcher, design, follower, apply] {
                watcher->deleteLater();
                m_sizingRuns = false;
                updateSizingButtons();
                const Result<Answer> r = watcher->result();
                const auto& now = m_document->project();
                if (!now.design || *now.design != design ||
                    now.follower.value_or(FollowerSpec{}) != follower) {
                    m_sizing->setText(staleSizingText());
                } else if (!r.ok()) {
                    m_sizing->setStyleSheet(QStringLiteral("color: #b41e1e"));
                    m_sizing->setText(DiagnosticText::line(r.errors().front()));
                } else {
                    apply(r.value(), design, follower);
                }
                // Each answer describes the project as it is now, until it changes.
                m_sizingFor = Basis{{}, now.design, now.follower, {}, {}};
                emit sizingFinished();
            });
    watcher->setFuture(QtConcurrent::run([job, design, follower] {
        runInTheBackground();
        return job(design, follower);
    }));
}

QString MotionDesignPanel::staleSizingText() {
    return tr("The design changed while it was sized: try again.");
}

void MotionDesignPanel::updateSizingButtons() {
    const Project& project = m_document->project();
    m_size->setEnabled(project.design.has_value() && !m_sizingRuns);
    const auto placement = placementOf(project.follower.value_or(FollowerSpec{}));
    m_bestPlacement->setEnabled(project.design.has_value() && !m_sizingRuns && placement);
    if (placement == Placement::PivotDistance) {
        m_bestPlacement->setText(tr("Best Pivot"));
        m_bestPlacement->setToolTip(
            tr("Move the arm's pivot along its line to the cam centre to where it allows the "
               "smallest base radius, set that radius, and show the feasible region over base "
               "radius × pivot distance (one undo step; the arm keeps its length)"));
    } else {
        m_bestPlacement->setText(tr("Best Offset"));
        m_bestPlacement->setToolTip(
            tr("Set the follower's offset that allows the smallest base radius, and that "
               "radius, and show the feasible region over base radius × offset (one undo step; "
               "a translating knife or roller)"));
    }
}

void MotionDesignPanel::sizeBaseRadius() {
    if (m_sizingRuns || !m_document->project().design) return;
    runSizing<SizingResult>(
        tr("Finding the smallest base radius…"),
        [](const DesignSpec& design, const FollowerSpec& follower) {
            return cam::sizeBaseRadius(design, follower);
        },
        [this](const SizingResult& s, const DesignSpec&, const FollowerSpec&) {
            m_sizing->setText(
                tr("Smallest base radius %1: %2 binds at %3.")
                    .arg(formatQuantity(DisplayQuantity::Length, s.baseRadius),
                         QCoreApplication::translate(kDiagnosticContext,
                                                     sizingCheckTitle(s.binding)),
                         formatQuantity(DisplayQuantity::Angle, radToDeg(s.bindingPhi))));
            editDesign([&](DesignSpec& d) { d.baseRadius = s.baseRadius; },
                       tr("Smallest base radius"), 0);
        });
}

void MotionDesignPanel::sizePlacement() {
    const Project& project = m_document->project();
    if (m_sizingRuns || !project.design ||
        !placementOf(project.follower.value_or(FollowerSpec{}))) {
        return;
    }
    runSizing<PlacementSizing>(
        tr("Finding the placement that allows the smallest base radius…"),
        [](const DesignSpec& design, const FollowerSpec& follower) {
            return cam::sizePlacement(design, follower);
        },
        [this](const PlacementSizing& o, const DesignSpec& design, const FollowerSpec& follower) {
            const SizingResult& s = o.sizing;
            const bool offset = o.placement == Placement::Offset;
            const QString binds =
                QCoreApplication::translate(kDiagnosticContext, sizingCheckTitle(s.binding));
            const QString at = formatQuantity(DisplayQuantity::Angle, radToDeg(s.bindingPhi));
            const QString radius = formatQuantity(DisplayQuantity::Length, s.baseRadius);
            const QString value = formatQuantity(DisplayQuantity::Length, o.value);
            m_sizing->setText(
                offset ? tr("Smallest base radius %1 at offset %2: %3 binds at %4.")
                             .arg(radius, value, binds, at)
                       : tr("Smallest base radius %1 with the pivot %2 from the cam centre: %3 "
                            "binds at %4.")
                             .arg(radius, value, binds, at));
            m_region->setVisible(true);
            m_region->setRegion(o.placement, o.region, {o.value, s.baseRadius},
                                {placementValue(follower, o.placement), design.baseRadius});
            m_regionFor = Basis{{}, design, follower, {}, {}};
            m_regionPlacement = o.placement;
            DesignSpec sized = design;
            sized.baseRadius = s.baseRadius;
            QUndoStack* stack = m_document->undoStack();
            stack->beginMacro(offset ? tr("Best offset") : tr("Best pivot"));
            stack->push(new SetDesign(m_document, sized, tr("Smallest base radius")));
            stack->push(new SetFollower(m_document, placedAt(follower, o.placement, o.value)));
            stack->endMacro();
        });
}

QString MotionDesignPanel::sizingText() const { return m_sizing->text(); }

void MotionDesignPanel::newDesign() {
    if (m_document->project().design) return;
    DesignSpec d;
    d.baseRadius = 40.0;
    using L = MotionLawType;
    d.segments = {{L::Cycloidal, 120.0, 10.0},
                  {L::Dwell, 180.0, 10.0},
                  {L::Cycloidal, 300.0, 0.0},
                  {L::Dwell, 360.0, 0.0}};
    if (const auto& f = m_document->project().follower;
        f && f->motion == FollowerMotion::Oscillating) {
        // An arm swings by degrees: 10° suits the default arm of 50 mm.
        for (auto& s : d.segments) s.lift = s.lift > 0.0 ? 10.0 : 0.0;
    }
    m_document->undoStack()->push(new SetDesign(m_document, d, tr("New design")));
    m_table->setCurrentIndex(m_model->index(0, DesignTableModel::Law));
}

void MotionDesignPanel::splitSegment(int row) {
    const auto& design = m_document->project().design;
    if (!design || row < 0 || row >= static_cast<int>(design->segments.size())) return;
    editDesign(
        [row](DesignSpec& d) {
            const auto k = static_cast<std::size_t>(row);
            const double from = k == 0 ? 0.0 : d.segments[k - 1].toDeg;
            DesignSegmentSpec dwell{MotionLawType::Dwell, d.segments[k].toDeg, d.segments[k].lift};
            d.segments[k].toDeg = (from + d.segments[k].toDeg) / 2.0;
            d.segments.insert(d.segments.begin() + row + 1, dwell);
        },
        tr("Split design segment %1").arg(row), 0);
    m_table->setCurrentIndex(m_model->index(row + 1, DesignTableModel::Law));
}

void MotionDesignPanel::deleteSegment(int row) {
    const auto& design = m_document->project().design;
    if (!design || row < 0 || row >= static_cast<int>(design->segments.size()) ||
        design->segments.size() < 2) {
        return;
    }
    editDesign(
        [row](DesignSpec& d) {
            const auto k = static_cast<std::size_t>(row);
            const DesignSegmentSpec gone = d.segments[k];
            if (k > 0) {
                d.segments[k - 1].toDeg = gone.toDeg;
                d.segments[k - 1].lift = gone.lift;
            }
            // The first segment's stretch goes to the next, which then starts at 0°.
            d.segments.erase(d.segments.begin() + row);
        },
        tr("Delete design segment %1").arg(row), 0);
}

void MotionDesignPanel::suggestLaw(int row) {
    const auto& design = m_document->project().design;
    if (!design || row >= static_cast<int>(design->segments.size())) return;
    const auto only = row < 0 ? std::nullopt : std::optional<std::size_t>(row);
    const auto suggested = suggestLaws(*design, only);
    m_suggestion->show();
    if (!suggested.ok()) {
        m_suggestion->setText(tr("Suggest needs a design that can be evaluated: %1")
                                  .arg(DiagnosticText::message(suggested.errors().front())));
        return;
    }
    QStringList changes;
    const QStringList titles = motionLawTitles();
    for (std::size_t k = 0; k < design->segments.size(); ++k) {
        if (suggested.value().segments[k] == design->segments[k]) continue;
        changes << tr("segment %1: %2")
                       .arg(k)
                       .arg(titles.value(static_cast<int>(suggested.value().segments[k].law)));
    }
    if (changes.isEmpty()) {
        m_suggestion->setText(row < 0
                                  ? tr("Every law is already the one suggested.")
                                  : tr("Segment %1's law is already the one suggested.").arg(row));
        return;
    }
    m_suggestion->setText(tr("Suggested %1.").arg(changes.join(QStringLiteral("; "))));
    editDesign([&](DesignSpec& d) { d = suggested.value(); },
               row < 0 ? tr("Suggest laws") : tr("Suggest the law of design segment %1").arg(row),
               0);
}

QString MotionDesignPanel::importTable(int row, const QString& text) {
    const auto& design = m_document->project().design;
    if (!design || row < 0 || row >= static_cast<int>(design->segments.size())) return {};
    const auto points = parseMotionTable(text.toStdString());
    if (!points.ok()) return DiagnosticText::line(points.errors().front());
    const Diagnostics problems = motionTableProblems(
        points.value(), DesignSegmentPlace{static_cast<std::size_t>(row), DesignPart::Points});
    if (!problems.empty()) return DiagnosticText::message(problems.front());
    editDesign(
        [&](DesignSpec& d) {
            DesignSegmentSpec& s = d.segments[static_cast<std::size_t>(row)];
            s.law = MotionLawType::Table;
            s.table = points.value();
        },
        tr("Import a motion table into design segment %1").arg(row), 0);
    return {};
}

void MotionDesignPanel::refresh() {
    m_refreshing = true;
    const auto& design = m_document->project().design;
    m_newDesign->setVisible(!design);
    m_removeDesign->setVisible(design.has_value());
    for (QWidget* w : std::initializer_list<QWidget*>{m_baseRadius, m_tolerance, m_strict, m_table,
                                                      m_split, m_delete, m_suggest, m_suggestAll,
                                                      m_importTable, m_synthesize}) {
        w->setEnabled(design.has_value());
    }
    updateSizingButtons();
    if (design) {
        m_baseRadius->setValue(design->baseRadius);
        m_tolerance->setValue(design->tolerance);
        m_strict->setChecked(design->strictPressureAngle);
    }
    m_refreshing = false;
    if (!design) {
        m_plotArea->hide();
        m_notes->clear();
        m_report->setText(noDesignText());
    } else if (m_reportText.isEmpty()) {
        // A design that cannot be computed yet (a law its neighbours cannot meet) brings no
        // result to say so: it is a design all the same.
        m_report->setText(synthesizeHint());
    }
}

void MotionDesignPanel::dropStaleTexts() {
    const Project& now = m_document->project();
    if (m_reportFor) {
        // Shown while the project is the one synthesized (again after Undo and Redo).
        const bool holds =
            *m_reportFor == Basis{now.contour, now.design, now.follower, now.motion, {}};
        m_reportText = holds ? m_reportFor->text : QString();
        m_report->setText(holds ? m_reportText : now.design ? synthesizeHint() : noDesignText());
    }
    if (m_sizingFor) {
        m_sizing->setVisible(*m_sizingFor == Basis{{}, now.design, now.follower, {}, {}});
    }
    if (m_regionFor) {
        const FollowerSpec follower = now.follower.value_or(FollowerSpec{});
        const bool holds = now.design && sameRegion(*m_regionFor->design, *m_regionFor->follower,
                                                    *now.design, follower, m_regionPlacement);
        if (holds) {
            m_region->setCurrent(
                {placementValue(follower, m_regionPlacement), now.design->baseRadius});
        }
        m_region->setVisible(holds);
    }
}

QString MotionDesignPanel::synthesizeHint() {
    return tr(
        "Synthesize fits the exact profile with tangent arcs within the "
        "tolerance and replaces the contour (one undo step).");
}

QString MotionDesignPanel::noDesignText() {
    return tr(
        "This project has no motion design. New Design starts one: lay out "
        "the follower's motion, then Synthesize makes the contour from it.");
}

void MotionDesignPanel::setReport(const SynthesisReport& report, const Project& after) {
    const bool swinging = after.follower && after.follower->motion == FollowerMotion::Oscillating;
    const auto [lift, speed, accel] = liftErrorQuantities(swinging);
    m_reportText = tr("Last synthesis: %n segment(s), at most %1 from the exact profile. The "
                      "follower on them against the law (%2 angles): lift %3, velocity %4, "
                      "acceleration %5 (the arcs are only tangent-continuous: the "
                      "acceleration jumps at their joints).",
                      nullptr, static_cast<int>(report.segments))
                       .arg(formatQuantity(DisplayQuantity::LengthError, report.maxDeviationMm))
                       .arg(static_cast<qulonglong>(report.checkedAngles))
                       .arg(formatQuantity(lift, report.maxLiftError),
                            formatQuantity(speed, report.maxVelocityError),
                            formatQuantity(accel, report.maxAccelerationError));
    m_reportFor = Basis{after.contour, after.design, after.follower, after.motion, m_reportText};
    m_report->setText(m_reportText);
}

QString MotionDesignPanel::reportText() const { return m_report->text(); }
QString MotionDesignPanel::notesText() const { return m_notes->text(); }

void MotionDesignPanel::setCursorX(double x) {
    if (!m_plotArea->isVisible()) return;
    for (QCPItemStraightLine* cursor : m_cursors) moveCursorLine(cursor, x);
}

void MotionDesignPanel::setResult(const ComputeResultPtr& result) {
    if (!result || !m_document->project().design) return;
    const auto& design = result->design;
    if (!design || !design->errors.empty()) {
        // The design cannot be drawn as it is: its problems are marked in the table.
        m_plotArea->setVisible(false);
        m_notes->setText(
            design ? tr("The design cannot be made: %1").arg(diagnosticText(design->errors.front()))
                   : tr("The design cannot be drawn at this speed."));
        m_notes->setStyleSheet("color: #b00020;");
        return;
    }
    m_model->setCoefficients(design->coefficients);
    m_plotArea->setVisible(true);
    const auto data = std::dynamic_pointer_cast<const KinematicsPlotData>(result->prepared);
    const bool swinging = design->swinging;
    const QString unit = swinging ? QStringLiteral("°") : QStringLiteral("mm");
    const QString titles[] = {tr("Lift [%1]").arg(unit), tr("v [%1/s]").arg(unit),
                              tr("a [%1/s²]").arg(unit), tr("j [%1/s³]").arg(unit)};
    for (QCPItemStraightLine* j : m_joints) j->parentPlot()->removeItem(j);
    m_joints.clear();
    for (std::size_t p = 0; p < 4; ++p) {
        QCustomPlot* plot = m_plots[p];
        plot->yAxis->setLabel(titles[p]);
        if (data && data->designLaw[p]) {
            plot->graph(0)->setData(data->designLaw[p]);
        } else {
            clearGraph(plot->graph(0));
        }
        if (data && data->designOnContour[p]) {
            plot->graph(1)->setData(data->designOnContour[p]);
        } else {
            clearGraph(plot->graph(1));
        }
        for (double x : design->jointsX) {
            auto* line = new QCPItemStraightLine(plot);
            line->setPen(QPen(QColor(120, 120, 120, 120), 1, Qt::DotLine));
            line->point1->setCoords(x, 0);
            line->point2->setCoords(x, 1);
            m_joints.push_back(line);
        }
        QCPRange y(design->yRanges[p].lower, design->yRanges[p].upper);
        if (!(y.size() > 0.0)) y = QCPRange(y.lower - 1.0, y.upper + 1.0);
        plot->yAxis->setRange(y);
        plot->yAxis->scaleRange(1.1);
        if (!m_fitted || plot->xAxis->range().size() == 0.0) {
            plot->xAxis->setRange(design->x.front(), design->x.back());
        }
        plot->xAxis->setLabel(p == 3 ? (result->axis == PlotAxis::Angle ? tr("φ [°]") : tr("t [s]"))
                                     : QString());
        queueReplot(plot);
    }
    m_fitted = true;
    if (const QCPRange x(design->x.front(), design->x.back());
        m_plots[0]->xAxis->range().lower < std::min(x.lower, x.upper) - 1e-9 ||
        m_plots[0]->xAxis->range().upper > std::max(x.lower, x.upper) + 1e-9) {
        // Another axis (time ↔ angle) or another sense of rotation: shown whole.
        for (QCustomPlot* plot : m_plots) plot->xAxis->setRange(x);
    }
    QStringList lines;
    if (!design->onContour[0].empty()) {
        const std::array<DisplayQuantity, 3> errors = liftErrorQuantities(swinging);
        lines << tr("The follower on the contour as it is, against the law (%1 samples): lift "
                    "%2, velocity %3, acceleration %4.")
                     .arg(design->x.size() - 1)
                     .arg(formatQuantity(errors[0], design->maxError[0]),
                          formatQuantity(errors[1], design->maxError[1]),
                          formatQuantity(errors[2], design->maxError[2]));
    } else if (!design->onContourErrors.empty()) {
        lines << tr("The follower cannot ride the contour: %1")
                     .arg(diagnosticText(design->onContourErrors.front()));
    } else if (!result->ok()) {
        lines << tr("No contour yet: Synthesize makes it from this design.");
    }
    bool problem = false;
    for (const Diagnostic& d : design->notes) {
        lines << diagnosticText(d);
        problem = problem || d.severity == Severity::Error;
    }
    m_notes->setText(lines.join('\n'));
    m_notes->setStyleSheet(problem ? "color: #b00020;" : "");
    if (m_reportText.isEmpty()) m_report->setText(synthesizeHint());
}

}  // namespace cam
