#pragma once
/// @file
/// @brief Cell editors for the segment table: numbers with units, and choices.

#include <QStyledItemDelegate>

namespace cam {

/// @brief Edits a number in a spin box with its unit. The model is updated on every step (the
/// plots follow live); all steps of one editing session are one undo step.
class NumberDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override;
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
};

/// @brief A fresh id for one editing gesture (a spin-box session, a drag): see EditSegment.
int nextGestureId();

}  // namespace cam
