#pragma once
/// @file
/// @brief The segment table as a Qt model: an adapter over the document that edits through
/// undo commands and marks invalid cells with their messages. One row per segment of any kind
/// (arc, line, Bézier, Hermite); the columns that do not apply to a row's kind are empty.

#include <QAbstractTableModel>
#include <QHash>

#include "document/commands.h"
#include "document/project_document.h"
#include "messages/field_titles.h"

namespace cam {

/// The columns are SegmentColumns' (messages/field_titles.h): SegmentTableModel::Radius.
class SegmentTableModel : public QAbstractTableModel, public SegmentColumns {
    Q_OBJECT
public:
    /// setData with this role takes QVariantList{value, gesture}: edits of one cell that carry
    /// the same non-zero gesture (one spin-box session, one drag) merge into one undo step.
    static constexpr int MergingEditRole = Qt::UserRole + 1;
    /// data() with this role gives the list of choices of a Type or Branch cell.
    static constexpr int ChoicesRole = Qt::UserRole + 2;

    explicit SegmentTableModel(ProjectDocument* document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    /// @brief The column's header text, "Radius [mm]": also how messages name the column.
    [[nodiscard]] static QString columnTitle(int column);

    /// @brief The messages that concern a cell (empty when it is fine).
    [[nodiscard]] QStringList problemsAt(int row, int column) const;

    /// @brief Which field an edit of this column touches (for merging).
    static EditedField fieldOf(int column);
    /// @brief The segment as it would be after setting `column` to `value`; false if invalid.
    /// The Type column converts the segment (see withType).
    static bool applyValue(SegmentSpec& segment, int column, const QVariant& value);

    /// @brief The cells a diagnostic's place marks: the field's column(s); a spline's control
    /// points mark the Type cell (whose tooltip lists them); the whole segment marks every cell.
    static QList<int> columnsOf(const SegmentPlace& place);

private:
    void rebuildProblems();
    bool isApplicable(int row, int column) const;

    ProjectDocument* m_document;
    QHash<quint64, QStringList> m_problems;  ///< (row << 8 | column) → messages
};

}  // namespace cam
