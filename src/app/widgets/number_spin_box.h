#pragma once
/// @file
/// @brief The one numeric editor of the app: shows a readable number of digits, yet never
/// changes a value the user did not change.

#include <QDoubleSpinBox>

#include "widgets/quantity_format.h"

namespace cam {

/// @brief A spin box for doubles that keeps the exact value.
///
/// QDoubleSpinBox rounds every value to its `decimals`, so merely opening an editor on
/// 50.308589201268575 and pressing Enter stored 50.308589. This one shows at most
/// `significantDigits` significant digits, but as long as the text is the text it showed for
/// the current value, that value stays bit for bit; only a changed text is parsed. Typing
/// follows the spreadsheet habit: the value is taken on Enter, Tab or leaving the field
/// (keyboard tracking off), so "12.5" can be typed without "12" being stored on the way; the
/// arrows, Page Up/Down and the wheel step live. Accepts the locale's decimal separator and the
/// dot in every locale; never group separators. The value is any finite double in the range.
class NumberSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit NumberSpinBox(QWidget* parent = nullptr);

    /// @brief How many significant digits the text shows (default: the table's Input, 10).
    void setSignificantDigits(int digits);
    [[nodiscard]] int significantDigits() const { return m_digits; }

    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;
    void fixup(QString& text) const override;

    /// @brief As wide as a typical value ("-88888.8888") rather than the range's ends, which
    /// span every finite double.
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    /// @brief Ctrl+Z and Ctrl+Shift+Z (the platform's undo and redo keys) go to the window's
    /// undo stack while the box shows its value as committed: undo from a dock works with the
    /// focus still in the box. With a typed, uncommitted text they undo the typing as usual.
    bool event(QEvent* event) override;
    /// @brief Whether the box holds typed text not yet taken as its value.
    [[nodiscard]] bool isTyping() const;

    /// @brief Why the typed text cannot be taken (out of range, beyond a double, unfinished),
    /// naming the field and the value it keeps; empty when it can or nothing was typed.
    [[nodiscard]] QString refusal() const;
    /// @brief Says the refusal, if any (status bar, tooltip, `refused`); whether there was one.
    /// Enter and leaving the box call it; a table's delegate calls it before taking the value.
    bool tellIfRefused();
    /// @brief Drops typed text, showing the value again (Escape in a table cell).
    void discardTyping();
    /// @brief The last refusal said (a refused key or text), for tests.
    [[nodiscard]] QString lastRefusal() const { return m_told; }

    /// @brief The number `text` means (locale or dot decimal, optional exponent), if it is one.
    [[nodiscard]] static std::optional<double> parseNumber(const QString& text);

signals:
    /// @brief A key or a typed text was refused: the message says where, what and why.
    void refused(const QString& message);

protected:
    /// A key that cannot be part of a number is refused with a word, not silently.
    void keyPressEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    [[nodiscard]] QString stripped(const QString& text) const;
    /// The field's name for a message: its accessible name (a table cell's editor gets one),
    /// else its form label, else "This field".
    [[nodiscard]] QString place() const;
    void tell(const QString& message);

    QString m_told;

    int m_digits = quantityFormat(DisplayQuantity::Input).significant;
};

}  // namespace cam
