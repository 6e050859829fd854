#include "widgets/number_spin_box.h"

#include <QKeyEvent>
#include <QLocale>
#include <QRegularExpression>
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

}  // namespace cam
