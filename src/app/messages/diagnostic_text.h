#pragma once
/// @file
/// @brief The window's wording of the core's diagnostics: each code's template from the core's
/// catalogue (common/diagnostic_catalogue.h), translated, with its arguments in the window's
/// terms (numbers in the user's locale, segments and columns as the table names them, terms
/// and laws translated), and the typed place named as the window shows it ("Segment 4, Radius
/// [mm]", "Joint between segments 4 and 5") instead of the file's keys ("contour[4].radius").
/// A diagnostic without a code (or with arguments that do not fit its code) is shown in the
/// core's English, so nothing is ever lost. The CLI keeps printing the core's English.

#include <QCoreApplication>
#include <QString>

#include "common/diagnostic.h"

namespace cam {

/// @brief Holds the translation context "DiagnosticText" of the messages.
class DiagnosticText {
    Q_DECLARE_TR_FUNCTIONS(DiagnosticText)
public:
    /// @brief "Segment 4, Radius [mm]: must be > 0 (got -2)": the place and the message, as the
    /// status bar and the table's tooltips show them.
    [[nodiscard]] static QString line(const Diagnostic& diagnostic);
    /// @brief The message alone, for a cell that already is the place.
    [[nodiscard]] static QString message(const Diagnostic& diagnostic);
    /// @brief The place alone ("Segment 4, Radius [mm]"; empty when it has none).
    [[nodiscard]] static QString location(const Diagnostic& diagnostic);
    /// @brief Whether the window can word this diagnostic itself (it has a code and the
    /// arguments its code takes); otherwise line() and message() give the core's English.
    [[nodiscard]] static bool translatable(const Diagnostic& diagnostic);
};

/// @brief DiagnosticText::line(): the one function every window display of a diagnostic uses.
[[nodiscard]] inline QString diagnosticText(const Diagnostic& diagnostic) {
    return DiagnosticText::line(diagnostic);
}

}  // namespace cam
