#pragma once
/// @file
/// @brief How a view says that what it draws is out of date: its curves turn grey and this
/// label, laid over the view, says why ("Not computed: …").

#include <QColor>
#include <QCoreApplication>
#include <QLabel>
#include <algorithm>

#include "engine/compute_result.h"
#include "messages/diagnostic_text.h"

namespace cam {

/// @brief The grey of curves that no longer show the current project.
inline QColor staleColor() { return {190, 190, 190}; }

/// @brief Why a result could not be computed, as the views say it (the first problem; the
/// status bar's tooltip lists all).
inline QString staleText(const ComputeResult& result) {
    if (result.awaitsContour()) {
        return QCoreApplication::translate("cam::StaleLabel",
                                           "No contour yet: Synthesize (F6, in the Motion Design "
                                           "dock) makes it from the design.");
    }
    // The errors of a result that could not be computed, else the problems of a project that
    // was computed but is not valid (an open joint): the plots show neither.
    const Diagnostics reasons = result.reasonsNotShown();
    const QString first = reasons.empty() ? QStringLiteral("?") : diagnosticText(reasons.front());
    QString more;
    if (reasons.size() > 1) {
        const int others = static_cast<int>(reasons.size() - 1);
        more = QCoreApplication::translate("cam::StaleLabel", " (and %n more)", nullptr, others);
    }
    return QCoreApplication::translate("cam::StaleLabel",
                                       "Not computed: %1%2\nGrey: the last computed state, "
                                       "out of date.")
        .arg(first, more);
}

/// @brief The label laid over a view that draws an out-of-date picture: hidden while the view is
/// current, red and centred at the top of the view (at most 90 % of its width) while not.
class StaleLabel : public QLabel {
public:
    explicit StaleLabel(QWidget* parent) : QLabel(parent) {
        setObjectName("staleLabel");
        setWordWrap(true);
        setAlignment(Qt::AlignCenter);
        setTextFormat(Qt::PlainText);
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setStyleSheet(
            "QLabel { color: #b00020; background: rgba(255, 255, 255, 225); border: 1px solid "
            "#b00020; border-radius: 3px; padding: 6px; font-weight: bold; }");
        hide();
    }

    /// @brief Shows `reason` (empty: current again, hidden). False when nothing changed.
    bool setReason(const QString& reason) {
        if (reason.isEmpty() == !m_stale && reason == text()) return false;
        m_stale = !reason.isEmpty();
        setText(reason);
        setVisible(m_stale);
        place();
        return true;
    }
    [[nodiscard]] bool isStale() const { return m_stale; }
    /// @brief Why the view is out of date; empty when it is current.
    [[nodiscard]] QString reason() const { return m_stale ? text() : QString(); }

    /// @brief Follows the parent's size (call from its resizeEvent).
    void place() {
        if (!m_stale) return;
        const QWidget* p = parentWidget();
        const int width = std::min(p->width() * 9 / 10, 560);
        setFixedWidth(std::max(width, 80));
        setFixedHeight(heightForWidth(this->width()));
        move((p->width() - this->width()) / 2, 6);
        raise();
    }

private:
    bool m_stale = false;
};

}  // namespace cam
