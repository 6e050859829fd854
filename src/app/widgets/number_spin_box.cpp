#include "widgets/number_spin_box.h"

#include <QCoreApplication>
#include <QFormLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QStatusTipEvent>
#include <QToolTip>
#include <cmath>
#include <limits>

#include "widgets/number_format.h"

namespace cam {

NumberSpinBox::NumberSpinBox(QWidget* parent) : QDoubleSpinBox(parent) {
    // QDoubleSpinBox rounds to `decimals` in setValue and when stepping; with the most it
    // allows, that rounding is exact for every double.
    setDecimals(std::numeric_limits<double>::max_exponent10 +
                std::numeric_limits<double>::digits10);
    setRange(-std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
    setKeyboardTracking(false);
    setAccelerated(true);
    setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
}

void NumberSpinBox::setSignificantDigits(int digits) {
    m_digits = std::clamp(digits, 1, 17);
    // Show the current value in the new precision (a display change only).
    const double v = value();
    const QSignalBlocker block(this);
    setValue(v);
}

namespace {

/// The hint's width with the text of the range's ends replaced by a typical value's.
QSize typicalWidth(const NumberSpinBox& box, QSize hint) {
    const QFontMetrics fm(box.font());
    auto width = [&](const QString& text) {
        return fm.horizontalAdvance(box.prefix() + text + box.suffix());
    };
    const int ends =
        std::max(width(box.textFromValue(box.minimum())), width(box.textFromValue(box.maximum())));
    const int typical =
        std::max(width(QStringLiteral("-88888.8888")),
                 width(box.specialValueText()) - fm.horizontalAdvance(box.prefix() + box.suffix()));
    hint.setWidth(hint.width() - ends + typical);
    return hint;
}

}  // namespace

QSize NumberSpinBox::sizeHint() const { return typicalWidth(*this, QDoubleSpinBox::sizeHint()); }

QSize NumberSpinBox::minimumSizeHint() const {
    return typicalWidth(*this, QDoubleSpinBox::minimumSizeHint());
}

QString NumberSpinBox::textFromValue(double v) const {
    if (v == 0.0) return QStringLiteral("0");  // never "-0"
    QLocale locale = this->locale();
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return withCapitalExponent(locale.toString(v, 'g', m_digits), v);
}

bool NumberSpinBox::event(QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const bool undoKey = key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo);
        if (undoKey && !isTyping()) {
            // Not ours: the shortcut (the window's Undo or Redo) takes the key.
            event->ignore();
            return true;
        }
    }
    return QDoubleSpinBox::event(event);
}

bool NumberSpinBox::isTyping() const { return cleanText() != textFromValue(value()); }

QString NumberSpinBox::stripped(const QString& text) const {
    QString s = text;
    if (!prefix().isEmpty() && s.startsWith(prefix())) s.remove(0, prefix().size());
    if (!suffix().isEmpty() && s.endsWith(suffix())) s.chop(suffix().size());
    return s.trimmed();
}

std::optional<double> NumberSpinBox::parseNumber(const QString& text) {
    QString t = text.trimmed();
    if (t.isEmpty()) return std::nullopt;
    // "12." and "12," are 12, as a user who stopped typing means.
    if (t.endsWith('.') || t.endsWith(',')) t += '0';
    QLocale mine;
    mine.setNumberOptions(QLocale::RejectGroupSeparator);
    QLocale c = QLocale::c();
    c.setNumberOptions(QLocale::RejectGroupSeparator);
    for (const QLocale& locale : {mine, c}) {
        bool ok = false;
        const double v = locale.toDouble(t, &ok);
        if (ok && std::isfinite(v)) return v;
    }
    return std::nullopt;
}

double NumberSpinBox::valueFromText(const QString& text) const {
    if (!specialValueText().isEmpty() && text == specialValueText()) return minimum();
    const QString s = stripped(text);
    // The text shown for the current value means that value exactly, not its rounding.
    if (s == textFromValue(value())) return value();
    return parseNumber(s).value_or(value());
}

QValidator::State NumberSpinBox::validate(QString& text, int&) const {
    if (!specialValueText().isEmpty() && text == specialValueText()) return QValidator::Acceptable;
    const QString s = stripped(text);
    if (const auto v = parseNumber(s)) {
        return *v >= minimum() && *v <= maximum() ? QValidator::Acceptable
                                                  : QValidator::Intermediate;
    }
    // Anything that can still become a number while typing: "", "-", "1e", "2.5e-".
    static const QRegularExpression partial(R"(^[+-]?\d*([.,]\d*)?([eE][+-]?\d*)?$)");
    return partial.match(s).hasMatch() ? QValidator::Intermediate : QValidator::Invalid;
}

void NumberSpinBox::fixup(QString&) const {
    // Nothing is repaired silently: an unfinished number keeps the previous value.
}

namespace {

bool holds(QLayoutItem* item, const QWidget* widget) {
    if (!item) return false;
    if (item->widget() == widget) return true;
    if (QLayout* layout = item->layout()) {
        for (int k = 0; k < layout->count(); ++k) {
            if (holds(layout->itemAt(k), widget)) return true;
        }
    }
    return false;
}

}  // namespace

QString NumberSpinBox::place() const {
    if (!accessibleName().isEmpty()) return accessibleName();
    // A field of a form (alone or in a row with buttons): the label that names it.
    if (parentWidget()) {
        for (const QFormLayout* form : parentWidget()->findChildren<QFormLayout*>()) {
            for (int row = 0; row < form->rowCount(); ++row) {
                const auto* label =
                    qobject_cast<QLabel*>(form->itemAt(row, QFormLayout::LabelRole)
                                              ? form->itemAt(row, QFormLayout::LabelRole)->widget()
                                              : nullptr);
                if (label && !label->text().isEmpty() &&
                    holds(form->itemAt(row, QFormLayout::FieldRole), this)) {
                    return QString(label->text()).remove('&').remove(QRegularExpression(":$"));
                }
            }
        }
    }
    return tr("This field");
}

QString NumberSpinBox::refusal() const {
    const QString typed = cleanText();
    if (!isTyping() || (!specialValueText().isEmpty() && text() == specialValueText())) return {};
    const QString stays = textFromValue(value()) + suffix();
    if (const auto v = parseNumber(typed)) {
        if (*v >= minimum() && *v <= maximum()) return {};
        return tr("%1: %2 is outside %3 … %4; it stays %5.")
            .arg(place(), typed, textFromValue(minimum()), textFromValue(maximum()) + suffix(),
                 stays);
    }
    static const QRegularExpression whole(R"(^[+-]?(\d+([.,]\d*)?|[.,]\d+)([eE][+-]?\d+)?$)");
    if (whole.match(typed).hasMatch()) {
        return tr("%1: %2 is beyond the largest number there is (about 1.8E308); it stays %3.")
            .arg(place(), typed, stays);
    }
    return tr("%1: “%2” is not a number yet; it stays %3.").arg(place(), typed, stays);
}

bool NumberSpinBox::tellIfRefused() {
    const QString why = refusal();
    if (why.isEmpty()) return false;
    tell(why);
    return true;
}

void NumberSpinBox::tell(const QString& message) {
    m_told = message;
    emit refused(message);
    // The main window's status bar shows it (the event climbs the parents to the window).
    QStatusTipEvent tip(message);
    QCoreApplication::sendEvent(this, &tip);
    QToolTip::showText(mapToGlobal(QPoint(0, height())), message, nullptr, {}, 8000);
}

void NumberSpinBox::discardTyping() {
    if (isTyping()) lineEdit()->setText(prefix() + textFromValue(value()) + suffix());
}

void NumberSpinBox::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) {
        tellIfRefused();  // before the spin box puts the last value back
        QDoubleSpinBox::keyPressEvent(event);
        return;
    }
    const QString before = lineEdit()->text();
    QDoubleSpinBox::keyPressEvent(event);
    const QString typed = event->text();
    const bool printable = !typed.isEmpty() && typed.at(0).isPrint() &&
                           !(event->modifiers() & (Qt::ControlModifier | Qt::AltModifier));
    if (printable && lineEdit()->text() == before) {
        tell(tr("%1: “%2” cannot be part of a number: type digits, %3 for decimals and e for a "
                "power of ten (1.5e-3).")
                 .arg(place(), typed, locale().decimalPoint()));
    }
}

void NumberSpinBox::focusOutEvent(QFocusEvent* event) {
    tellIfRefused();
    QDoubleSpinBox::focusOutEvent(event);
}

}  // namespace cam
