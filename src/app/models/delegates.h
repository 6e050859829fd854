#pragma once
/// @file
/// @brief Cell editors for the segment table: numbers with units, and choices.

#include <QStyledItemDelegate>

namespace cam {

/// A model other than SegmentTableModel tells NumberDelegate a cell's unit (" mm", " °") and
/// step with these roles; without them the segment table's columns decide.
inline constexpr int kEditorSuffixRole = Qt::UserRole + 3;
inline constexpr int kEditorStepRole = Qt::UserRole + 4;
/// Beside SegmentTableModel::ChoicesRole, a model may give each choice a picture (a
/// QVariantList of QIcon) and a tip (a QStringList) for ChoiceDelegate's list.
inline constexpr int kChoiceIconsRole = Qt::UserRole + 5;
inline constexpr int kChoiceTipsRole = Qt::UserRole + 6;

/// @brief Edits a number in a NumberSpinBox with its unit, as in any spreadsheet: typed text is
/// taken on Enter or Tab (so "12.5" is 12.5, never 12 on the way), arrow and wheel steps update
/// the plots live, and all of one session is one undo step. Opening an editor and leaving it
/// unchanged changes nothing (the value stays exact and no undo step is pushed); Escape undoes
/// whatever the session had stepped.
class NumberDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit NumberDelegate(QObject* parent = nullptr);
    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override;

private:
    /// Puts the cell back to its value from before the session (Escape).
    void revert(QWidget* editor) const;
};

/// @brief Edits a cell whose model offers its choices under SegmentTableModel::ChoicesRole.
class ChoiceDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override;
    /// The editor is as wide as its longest choice, also when the column is narrower (it then
    /// lies over the next cell while open): a choice is never cut off.
    void updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option,
                              const QModelIndex& index) const override;
    /// As wide as the longest choice whichever is chosen: a column fitted to it keeps its
    /// width when another choice is picked, and the columns right of it stay where they are.
    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override;
};

/// @brief A fresh id for one editing gesture (a spin-box session, a drag): see EditSegment.
int nextGestureId();

}  // namespace cam
