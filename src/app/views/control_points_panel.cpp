#include "views/control_points_panel.h"

#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <cmath>

#include "common/angles.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "models/delegates.h"
#include "spline/control_points.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

NumberSpinBox* editor(QWidget* parent, const QString& name, const QString& suffix,
                      const QString& tip) {
    auto* box = new NumberSpinBox(parent);
    box->setObjectName(name);
    box->setSuffix(suffix);
    box->setToolTip(tip);
    box->setRange(-kMaxLengthMm, kMaxLengthMm);
    box->setSignificantDigits(quantityFormat(DisplayQuantity::Input).significant);
    return box;
}

}  // namespace

ControlPointsPanel::ControlPointsPanel(ProjectDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setObjectName("controlPointsTitle");
    m_title->setWordWrap(true);
    layout->addWidget(m_title);
    m_editors = new QWidget(this);
    auto* grid = new QGridLayout(m_editors);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("x [mm]"), m_editors), 0, 1);
    grid->addWidget(new QLabel(tr("y [mm]"), m_editors), 0, 2);
    grid->addWidget(new QLabel(tr("Handle length [mm]"), m_editors), 0, 4);
    grid->addWidget(new QLabel(tr("Handle angle [°]"), m_editors), 0, 5);
    for (int k = 0; k < 4; ++k) {
        m_pointNames[k] = new QLabel(m_editors);
        grid->addWidget(m_pointNames[k], k + 1, 0);
        for (int axis = 0; axis < 2; ++axis) {
            NumberSpinBox* box = editor(
                m_editors, QStringLiteral("controlPoint%1%2").arg(k).arg(axis ? 'y' : 'x'), {}, {});
            m_points[k][axis] = box;
            grid->addWidget(box, k + 1, axis + 1);
            connect(box, &QDoubleSpinBox::valueChanged, this, [this, k, axis](double v) {
                if (m_refreshing || m_row < 0) return;
                const SegmentSpec& s = m_document->project().contour.at(std::size_t(m_row));
                push(withControlPoint(s, k, axis, v),
                     QStringLiteral("%1 %2").arg(m_pointNames[k]->text(), axis ? "y" : "x"));
            });
            connect(box, &QDoubleSpinBox::editingFinished, this, [this] { m_gesture = 0; });
        }
    }
    grid->setColumnMinimumWidth(3, 12);
    for (int k = 0; k < 2; ++k) {
        // The start handle sits on the row of P1 (t0), the end handle on that of P2 (p3).
        m_handleLength[k] = editor(m_editors, QStringLiteral("handleLength%1").arg(k), {},
                                   tr("Length of the handle, mm (the angle stays)"));
        m_handleLength[k]->setMinimum(0.0);
        m_handleAngle[k] = editor(m_editors, QStringLiteral("handleAngle%1").arg(k), {},
                                  tr("Direction of the handle, degrees counter-clockwise from +x "
                                     "(the length stays)"));
        m_handleAngle[k]->setRange(-360.0, 360.0);
        m_handleNames[k] =
            new QLabel(k == 0 ? tr("Start handle P0→P1") : tr("End handle P3→P2"), m_editors);
        grid->addWidget(m_handleLength[k], k + 2, 4);
        grid->addWidget(m_handleAngle[k], k + 2, 5);
        grid->addWidget(m_handleNames[k], k + 2, 6);
        connect(m_handleLength[k], &QDoubleSpinBox::valueChanged, this, [this, k](double v) {
            if (m_refreshing || m_row < 0) return;
            const SegmentSpec& s = m_document->project().contour.at(std::size_t(m_row));
            push(withHandleLength(s, k, v), m_handleNames[k]->text());
        });
        connect(m_handleAngle[k], &QDoubleSpinBox::valueChanged, this, [this, k](double v) {
            if (m_refreshing || m_row < 0) return;
            const SegmentSpec& s = m_document->project().contour.at(std::size_t(m_row));
            push(withHandleAngle(s, k, v), m_handleNames[k]->text());
        });
        for (NumberSpinBox* box : {m_handleLength[k], m_handleAngle[k]}) {
            connect(box, &QDoubleSpinBox::editingFinished, this, [this] { m_gesture = 0; });
        }
    }
    grid->setColumnStretch(7, 1);
    layout->addWidget(m_editors);
    layout->addStretch(1);
    connect(document, &ProjectDocument::changed, this, &ControlPointsPanel::refresh);
    refresh();
}

void ControlPointsPanel::setRow(int row) {
    if (row == m_row) return;
    m_row = row;
    m_gesture = 0;
    refresh();
}

void ControlPointsPanel::push(const SegmentSpec& after, const QString& what) {
    const SegmentSpec& before = m_document->project().contour.at(std::size_t(m_row));
    if (after == before) return;
    if (m_gesture == 0) m_gesture = nextGestureId();
    m_document->undoStack()->push(
        new EditSegment(m_document, m_row, after, EditedField::ControlPoint,
                        tr("Edit %1 of segment %2").arg(what).arg(m_row), m_gesture));
}

void ControlPointsPanel::refresh() {
    const auto& contour = m_document->project().contour;
    const bool valid = m_row >= 0 && std::size_t(m_row) < contour.size();
    const SegmentSpec* s = valid ? &contour[std::size_t(m_row)] : nullptr;
    if (!s || !isSpline(s->type())) {
        m_title->setText(
            valid ? tr("Segment %1 is not a spline: its values are in the Segments table. "
                       "Select a Bézier or Hermite row to edit its control points.")
                        .arg(m_row)
                  : tr("Select a Bézier or Hermite row to edit its control points."));
        m_editors->hide();
        return;
    }
    const bool bezier = s->type() == SegmentType::Bezier;
    m_title->setText(bezier ? tr("Segment %1, Bézier: control points P0…P3. Moving an end point "
                                 "moves its handle with it.")
                                  .arg(m_row)
                            : tr("Segment %1, Hermite: end points p0, p3 and end tangents t0, "
                                 "t1 (t0 = 3·(P1 − P0)). Moving an end point keeps its tangent.")
                                  .arg(m_row));
    const QStringList names =
        bezier ? QStringList{"P0", "P1", "P2", "P3"} : QStringList{"p0", "t0", "p3", "t1"};
    const HermiteCurve* h = s->as<HermiteCurve>();
    const CubicBezier b = bezierOf(*s);
    // Row k edits point k of the kind's own list: a Bézier's P0…P3, a Hermite's p0, t0, p3, t1.
    const Eigen::Vector2d values[4] = {b.p[0], h ? h->t0 : b.p[1], h ? h->p3 : b.p[2],
                                       h ? h->t1 : b.p[3]};
    m_refreshing = true;
    for (int k = 0; k < 4; ++k) {
        m_pointNames[k]->setText(names[k]);
        const bool tangent = h && (k == 1 || k == 3);
        for (int axis = 0; axis < 2; ++axis) {
            NumberSpinBox* box = m_points[k][axis];
            box->setValue(values[k][axis]);
            box->setToolTip(tangent ? tr("%1 %2: a component of the tangent vector, mm")
                                          .arg(names[k], axis ? "y" : "x")
                                    : tr("%1 %2, mm").arg(names[k], axis ? "y" : "x"));
        }
    }
    for (int k = 0; k < 2; ++k) {
        const Eigen::Vector2d handle = splineHandle(*s, k);
        m_handleLength[k]->setValue(handle.norm());
        m_handleAngle[k]->setValue(
            handle.norm() > 0.0 ? radToDeg(std::atan2(handle.y(), handle.x())) : 0.0);
    }
    m_refreshing = false;
    m_editors->show();
}

}  // namespace cam
