#pragma once
/// @file
/// @brief How a view says that what it draws is out of date: its curves turn grey and this
/// label, laid over the view, says why ("Not computed: …").

#include <QColor>
#include <QCoreApplication>
#include <QLabel>
#include <algorithm>

#include "engine/compute_result.h"

namespace cam {

/// @brief The grey of curves that no longer show the current project.
inline QColor staleColor() { return {190, 190, 190}; }

/// @brief Why a result could not be computed, as the views say it (the first problem; the
/// status bar's tooltip lists all).
inline QString staleText(const ComputeResult& result) {
    const QString first = result.errors.empty()
                              ? QStringLiteral("?")
                              : QString::fromStdString(result.errors.front().text());
    const QString more = result.errors.size() > 1 ? QCoreApplication::translate(
                                                        "cam::StaleLabel", " (and %n more)", "",
                                                        static_cast<int>(result.errors.size() - 1))
                                                  : QString();
    return QCoreApplication::translate("cam::StaleLabel",
                                       "Not computed: %1%2\nGrey: the last computed state, "
                                       "out of date.")
        .arg(first, more);
}

/// @brief A hidden label over `parent` (place it with placeStaleLabel()).
inline QLabel* makeStaleLabel(QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setObjectName("staleLabel");
    label->setWordWrap(true);
    label->setAlignment(Qt::AlignCenter);
    label->setTextFormat(Qt::PlainText);
    label->setAttribute(Qt::WA_TransparentForMouseEvents);
    label->setStyleSheet(
        "QLabel { color: #b00020; background: rgba(255, 255, 255, 225); border: 1px solid "
        "#b00020; border-radius: 3px; padding: 6px; font-weight: bold; }");
    label->hide();
    return label;
}

/// @brief Centres the label at the top of its parent, at most 90 % of its width.
inline void placeStaleLabel(QLabel* label) {
    const QWidget* parent = label->parentWidget();
    const int width = std::min(parent->width() * 9 / 10, 560);
    label->setFixedWidth(std::max(width, 80));
    label->setFixedHeight(label->heightForWidth(label->width()));
    label->move((parent->width() - label->width()) / 2, 6);
    label->raise();
}

}  // namespace cam
