#include "models/delegates.h"

#include <QComboBox>
#include <QDoubleSpinBox>

#include "models/segment_table_model.h"

namespace cam {

int nextGestureId() {
    static int counter = 0;
    return ++counter;
}

QWidget* NumberDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                      const QModelIndex& index) const {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setFrame(false);
    spin->setDecimals(6);
    spin->setRange(-1e6, 1e6);
    spin->setAccelerated(true);
    const int c = index.column();
    const bool angle = c == SegmentTableModel::PhiStart || c == SegmentTableModel::PhiEnd;
    spin->setSuffix(angle ? QStringLiteral(" °") : QStringLiteral(" mm"));
    spin->setSingleStep(angle ? 0.5 : 0.1);
    if (c == SegmentTableModel::Radius) spin->setMinimum(0.0);
    spin->setProperty("gesture", nextGestureId());
    // Live: every step reaches the model (and the plots); the gesture id merges them.
    connect(spin, &QDoubleSpinBox::valueChanged, this,
            [this, spin] { emit const_cast<NumberDelegate*>(this)->commitData(spin); });
    return spin;
}

void NumberDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    auto* spin = static_cast<QDoubleSpinBox*>(editor);
    const QSignalBlocker block(spin);
    spin->setValue(index.data(Qt::EditRole).toDouble());
}

void NumberDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                  const QModelIndex& index) const {
    auto* spin = static_cast<QDoubleSpinBox*>(editor);
    spin->interpretText();
    model->setData(index, QVariantList{spin->value(), spin->property("gesture")},
                   SegmentTableModel::MergingEditRole);
}

QWidget* ChoiceDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                      const QModelIndex& index) const {
    auto* combo = new QComboBox(parent);
    combo->addItems(index.data(SegmentTableModel::ChoicesRole).toStringList());
    connect(combo, &QComboBox::activated, this,
            [this, combo] { emit const_cast<ChoiceDelegate*>(this)->commitData(combo); });
    return combo;
}

void ChoiceDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    auto* combo = static_cast<QComboBox*>(editor);
    const QSignalBlocker block(combo);
    combo->setCurrentIndex(index.data(Qt::EditRole).toInt());
}

void ChoiceDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                  const QModelIndex& index) const {
    model->setData(index, static_cast<QComboBox*>(editor)->currentIndex(), Qt::EditRole);
}

}  // namespace cam
