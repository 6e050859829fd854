#include "dialogs/contour_dialogs.h"

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPlainTextEdit>

#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

/// A dialog with a form and OK/Cancel.
QDialogButtonBox* addButtons(QDialog& dialog, QFormLayout* form) {
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    form->addRow(buttons);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    return buttons;
}

/// One number in a dialog of its own, taken exactly as typed.
std::optional<double> askNumber(QWidget* parent, const QString& title, const QString& label,
                                const QString& suffix, double initial) {
    QDialog dialog(parent);
    dialog.setWindowTitle(title);
    auto* form = new QFormLayout(&dialog);
    auto* value = new NumberSpinBox(&dialog);
    value->setObjectName("valueSpinBox");
    value->setSuffix(suffix);
    value->setValue(initial);
    form->addRow(label, value);
    addButtons(dialog, form);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    value->interpretText();
    return value->value();
}

}  // namespace

std::optional<TeachInInput> ContourDialogs::askTeachIn(QWidget* parent) {
    QDialog dialog(parent);
    dialog.setWindowTitle(tr("New Contour Through Points"));
    auto* form = new QFormLayout(&dialog);
    auto* points = new QPlainTextEdit(&dialog);
    points->setPlaceholderText(
        tr("x, y per line, in mm, counter-clockwise around the rotation centre"));
    points->setPlainText("20, 0\n14, 15\n-3, 22\n-18, 9\n-16, -12\n5, -19");
    auto* rule = new QComboBox(&dialog);
    rule->addItems({tr("Chord"), tr("Circumcircle"), tr("Oval")});
    rule->setCurrentIndex(static_cast<int>(HandleRule::Oval));
    auto* bulge = new NumberSpinBox(&dialog);
    bulge->setSingleStep(0.05);
    bulge->setValue(1.0);
    form->addRow(tr("Points"), points);
    form->addRow(tr("Handle rule"), rule);
    form->addRow(tr("Bulge factor"), bulge);
    addButtons(dialog, form);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    bulge->interpretText();
    return TeachInInput{points->toPlainText(), static_cast<HandleRule>(rule->currentIndex()),
                        bulge->value()};
}

std::optional<double> ContourDialogs::askRadialError(QWidget* parent) {
    return askNumber(parent, tr("Approximate Arc by Béziers"), tr("Admissible radial error:"),
                     QStringLiteral(" mm"), 0.001);
}

}  // namespace cam
