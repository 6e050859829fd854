#pragma once
/// @file
/// @brief The motion design's segments as a Qt model (Motion Design dock): law, end angle,
/// lift and the parameters its law takes (boundary values, λ, b, d; a table's points are
/// imported, design/motion_table.h), editable through undo commands; where each segment starts,
/// its boundary classes as its neighbours demand them (design/boundary_classes.h) and its law's
/// Cv, Ca, Cj, read-only. Cells a diagnostic names are marked with its message.

#include <QAbstractTableModel>
#include <QHash>
#include <vector>

#include "design/boundary_classes.h"
#include "design/motion_law.h"
#include "document/project_document.h"

namespace cam {

class DesignTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Law,
        FromDeg,
        ToDeg,
        Lift,
        V0,
        A0,
        J0,
        V1,
        A1,
        J1,
        Lambda,
        SccaB,
        SccaD,
        Points,
        StartClass,
        EndClass,
        Cv,
        Ca,
        Cj,
        ColumnCount
    };

    explicit DesignTableModel(ProjectDocument* document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    /// Qt::EditRole, or SegmentTableModel::MergingEditRole with {value, gesture}: edits of one
    /// cell with the same non-zero gesture are one undo step.
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    /// @brief The coefficients the engine computed for the design as it was (poly5's depend on
    /// its boundary values); the other laws' are known without it.
    void setCoefficients(const std::vector<LawCoefficients>& coefficients);
    /// @brief The messages that concern a cell (empty when it is fine).
    [[nodiscard]] QStringList problemsAt(int row, int column) const;
    /// @brief The law names as the Law column offers them, in MotionLawType's order.
    [[nodiscard]] static QStringList lawNames();
    /// @brief The field of a segment a column edits (DesignPart::Whole for none).
    [[nodiscard]] static DesignPart partOf(int column);

private:
    void rebuild();
    [[nodiscard]] bool swinging() const;

    ProjectDocument* m_document;
    std::vector<LawCoefficients> m_coefficients;
    QHash<quint64, QStringList> m_problems;  ///< (row << 8 | column) → messages
    std::vector<DesignSegmentSpec> m_shown;  ///< the segments the views know of
    std::vector<SegmentClasses> m_classes;   ///< each segment's, when the design has them
};

}  // namespace cam
