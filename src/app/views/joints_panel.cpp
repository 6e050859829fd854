#include "views/joints_panel.h"

#include <QHeaderView>
#include <QShowEvent>

#include "common/angles.h"
#include "widgets/quantity_format.h"

namespace cam {

JointsPanel::JointsPanel(QWidget* parent) : QTableWidget(parent) {
    setObjectName("jointsTable");
    setColumnCount(7);
    setHorizontalHeaderLabels({tr("Joint"), tr("φ [°]"), tr("Kinematic"), tr("Geometric"),
                               tr("Tangent break [°]"), tr("Δa_r [mm/s²]"), tr("Δ(d²P/dφ²) rel.")});
    horizontalHeaderItem(2)->setToolTip(
        tr("Continuity in φ, as the follower feels it: C0 position, C1 velocity, C2 acceleration"));
    horizontalHeaderItem(3)->setToolTip(
        tr("Continuity in each curve's own parameter: G1 is a continuous direction whose "
           "derivative jumps in length"));
    horizontalHeaderItem(5)->setToolTip(tr("Jump of the radial acceleration at the joint"));
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    verticalHeader()->setVisible(false);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    setToolTip(tr("Click a joint to put the cursor there"));
    connect(this, &QTableWidget::cellClicked, this, [this](int row, int) {
        if (!m_result || row < 0 || row >= static_cast<int>(m_result->joints.size())) {
            return;
        }
        const JointAnalysis& j = m_result->joints[static_cast<std::size_t>(row)];
        emit jointPicked(static_cast<int>(j.left), static_cast<int>(j.right), j.phi);
    });
}

void JointsPanel::setResult(const ComputeResultPtr& result) {
    if (!result) return;
    setEnabled(result->ok());  // greyed: the joints of the last project that could be computed
    if (!result->ok()) return;
    m_result = result;
    // A hidden tab does no work while edits stream in; it catches up when it is shown.
    m_stale = !isVisible();
    if (!m_stale) fill();
}

void JointsPanel::showEvent(QShowEvent* event) {
    QTableWidget::showEvent(event);
    if (m_stale) fill();
}

void JointsPanel::fill() {
    m_stale = false;
    if (!m_result) return;
    const auto& joints = m_result->joints;
    const bool first = rowCount() == 0;
    setRowCount(static_cast<int>(joints.size()));
    for (int row = 0; row < rowCount(); ++row) {
        const JointAnalysis& j = joints[static_cast<std::size_t>(row)];
        const QString cells[] = {QStringLiteral("%1 | %2").arg(j.left).arg(j.right),
                                 formatQuantityValue(DisplayQuantity::Angle, radToDeg(j.phi)),
                                 continuityName(j.continuity),
                                 continuityName(j.geometric),
                                 formatQuantityValue(DisplayQuantity::Angle, j.tangentBreakDeg),
                                 formatQuantityValue(DisplayQuantity::Acceleration, j.jumpAR),
                                 formatQuantityValue(DisplayQuantity::Ratio, j.relativeD2)};
        for (int c = 0; c < 7; ++c) {
            // The rows there are keep their items: an edit changes a few cells, if any.
            QTableWidgetItem* item = this->item(row, c);
            if (!item) {
                item = new QTableWidgetItem;
                item->setTextAlignment(c < 4 ? Qt::Alignment(Qt::AlignCenter)
                                             : Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
                setItem(row, c, item);
            }
            if (item->text() != cells[c]) item->setText(cells[c]);
            if (c == 2) {
                const QBrush colour = j.continuity == Continuity::C2   ? QBrush()
                                      : j.continuity == Continuity::C1 ? QColor(170, 100, 0)
                                                                       : QColor(180, 0, 30);
                if (item->foreground() != colour) item->setForeground(colour);
            }
        }
    }
    if (first) resizeColumnsToContents();
}

}  // namespace cam
