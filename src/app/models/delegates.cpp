#include "models/delegates.h"

#include <QIcon>

#include <QComboBox>
#include <QFontMetrics>
#include <QPersistentModelIndex>
#include <algorithm>

#include "models/segment_table_model.h"
#include "widgets/law_picture.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

// Properties a number editor carries through its session.
constexpr const char* kGesture = "gesture";      ///< merges the session's edits into one step
constexpr const char* kOriginal = "original";    ///< the cell's value when the session began
constexpr const char* kIndex = "index";          ///< the cell (a QPersistentModelIndex)
constexpr const char* kCommitted = "committed";  ///< a step already reached the model

}  // namespace

int nextGestureId() {
    static int counter = 0;
    return ++counter;
}

NumberDelegate::NumberDelegate(QObject* parent) : QStyledItemDelegate(parent) {
    connect(this, &QAbstractItemDelegate::closeEditor, this,
            [this](QWidget* editor, QAbstractItemDelegate::EndEditHint hint) {
                if (hint != QAbstractItemDelegate::RevertModelCache) return;
                // Escape: what was typed goes unsaid (the box would refuse it as it closes).
                static_cast<NumberSpinBox*>(editor)->discardTyping();
                revert(editor);
            });
}

QWidget* NumberDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                      const QModelIndex& index) const {
    auto* spin = new NumberSpinBox(parent);
    spin->setFrame(false);
    const int c = index.column();
    const bool angle = c == SegmentTableModel::PhiStart || c == SegmentTableModel::PhiEnd;
    const QVariant suffix = index.data(kEditorSuffixRole);
    const QVariant step = index.data(kEditorStepRole);
    spin->setSuffix(suffix.isValid() ? suffix.toString()
                    : angle          ? QStringLiteral(" °")
                                     : QStringLiteral(" mm"));
    spin->setSingleStep(step.isValid() ? step.toDouble() : angle ? 0.5 : 0.1);
    spin->setProperty(kGesture, nextGestureId());
    // Its messages name the cell: "Radius, row 3".
    spin->setAccessibleName(
        tr("%1, row %2")
            .arg(index.model()->headerData(c, Qt::Horizontal).toString().section('\n', 0, 0),
                 index.model()->headerData(index.row(), Qt::Vertical).toString()));
    spin->setProperty(kIndex, QVariant::fromValue(QPersistentModelIndex(index)));
    // Steps (arrows, wheel) are live: they reach the model, and the gesture id merges them.
    // Typed text arrives only on Enter/Tab (keyboard tracking is off).
    connect(spin, &QDoubleSpinBox::valueChanged, this,
            [this, spin] { emit const_cast<NumberDelegate*>(this)->commitData(spin); });
    return spin;
}

void NumberDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    auto* spin = static_cast<NumberSpinBox*>(editor);
    const double v = index.data(Qt::EditRole).toDouble();
    // Never overwrite what is being typed: once the editor shows the cell, only a value that
    // differs (an undo, a drag elsewhere) replaces the text.
    if (spin->property(kOriginal).isValid() && spin->value() == v) return;
    if (!spin->property(kOriginal).isValid()) spin->setProperty(kOriginal, v);
    const QSignalBlocker block(spin);
    spin->setValue(v);
}

void NumberDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                  const QModelIndex& index) const {
    auto* spin = static_cast<NumberSpinBox*>(editor);
    spin->tellIfRefused();  // Tab takes the text here, before the box could say it
    spin->interpretText();
    const double v = spin->value();
    if (v == index.data(Qt::EditRole).toDouble()) return;  // unchanged: no undo step
    model->setData(index, QVariantList{v, spin->property(kGesture)},
                   SegmentTableModel::MergingEditRole);
    spin->setProperty(kCommitted, true);
}

void NumberDelegate::revert(QWidget* editor) const {
    if (!editor->property(kCommitted).isValid()) return;  // nothing reached the model
    const auto index = editor->property(kIndex).value<QPersistentModelIndex>();
    if (!index.isValid()) return;
    // The same gesture: the edit merges with the session's and, back at its start, vanishes
    // from the undo stack.
    auto* model = const_cast<QAbstractItemModel*>(index.model());
    model->setData(index, QVariantList{editor->property(kOriginal), editor->property(kGesture)},
                   SegmentTableModel::MergingEditRole);
}

QWidget* ChoiceDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                      const QModelIndex& index) const {
    auto* combo = new QComboBox(parent);
    combo->addItems(index.data(SegmentTableModel::ChoicesRole).toStringList());
    const QVariantList icons = index.data(kChoiceIconsRole).toList();
    const QStringList tips = index.data(kChoiceTipsRole).toStringList();
    for (int i = 0; i < combo->count(); ++i) {
        if (i < icons.size()) combo->setItemIcon(i, icons[i].value<QIcon>());
        if (i < tips.size()) combo->setItemData(i, tips[i], Qt::ToolTipRole);
    }
    if (!icons.isEmpty()) combo->setIconSize(kLawPictureSize);
    connect(combo, &QComboBox::activated, this,
            [this, combo] { emit const_cast<ChoiceDelegate*>(this)->commitData(combo); });
    return combo;
}

void ChoiceDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    auto* combo = static_cast<QComboBox*>(editor);
    const QSignalBlocker block(combo);
    combo->setCurrentIndex(index.data(Qt::EditRole).toInt());
}

void ChoiceDelegate::updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option,
                                          const QModelIndex&) const {
    QRect rect = option.rect;
    rect.setWidth(std::max(rect.width(), editor->sizeHint().width()));
    editor->setGeometry(rect);
}

QSize ChoiceDelegate::sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const {
    QSize hint = QStyledItemDelegate::sizeHint(option, index);
    const QFontMetrics metrics(option.font);
    const int shown = metrics.horizontalAdvance(index.data(Qt::DisplayRole).toString());
    int widest = shown;
    for (const QString& choice : index.data(SegmentTableModel::ChoicesRole).toStringList()) {
        widest = std::max(widest, metrics.horizontalAdvance(choice));
    }
    hint.rwidth() += widest - shown;
    return hint;
}

void ChoiceDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                  const QModelIndex& index) const {
    const int choice = static_cast<QComboBox*>(editor)->currentIndex();
    if (choice == index.data(Qt::EditRole).toInt()) return;  // unchanged: no undo step
    model->setData(index, choice, Qt::EditRole);
}

}  // namespace cam
