#pragma once
/// @file
/// @brief The segment table as a Qt model: an adapter over the document that edits through
/// undo commands and marks invalid cells with their messages.

#include <QAbstractTableModel>
#include <QHash>

#include "document/commands.h"
#include "document/project_document.h"

namespace cam {

class ArcTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Type,
        CenterX,
        CenterY,
        Radius,
        Branch,
        FromX,
        FromY,
        ToX,
        ToY,
        PhiStart,
        PhiEnd,
        ColumnCount
    };
    /// setData with this role takes QVariantList{value, gesture}: edits of one cell that carry
    /// the same non-zero gesture (one spin-box session, one drag) merge into one undo step.
    static constexpr int MergingEditRole = Qt::UserRole + 1;
    /// data() with this role gives the list of choices of a Type or Branch cell.
    static constexpr int ChoicesRole = Qt::UserRole + 2;

    explicit ArcTableModel(ProjectDocument* document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    /// @brief The messages that concern a cell (empty when it is fine).
    [[nodiscard]] QStringList problemsAt(int row, int column) const;

    /// @brief Which field an edit of this column touches (for merging).
    static SegmentField fieldOf(int column);
    /// @brief The segment as it would be after setting `column` to `value`; false if invalid.
    static bool applyValue(SegmentSpec& segment, int column, const QVariant& value);
    /// @brief Another kind of segment through the same two end points: Bézier ↔ Hermite is the
    /// same curve exactly; a line becomes its 1/3-chord Bézier; an arc its κ-approximation.
    static bool changeType(SegmentSpec& segment, SegmentType type);

private:
    void rebuildProblems();
    bool isApplicable(int row, int column) const;

    ProjectDocument* m_document;
    int m_rows = 0;  ///< mirrors the document so begin/end notifications bracket each change
    QHash<quint64, QStringList> m_problems;  ///< (row << 8 | column) → messages
    QStringList m_rowProblems;               ///< for rows not mapped to a column
};

}  // namespace cam
