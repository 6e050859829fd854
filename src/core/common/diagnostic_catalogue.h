#pragma once
/// @file
/// @brief The one catalogue of the core's messages: per DiagnosticCode the kinds of its
/// arguments and its English template, which the core renders for the CLI and a window
/// translates (QCoreApplication::translate(kDiagnosticContext, template)) and fills its own way.
///
/// A signature has one letter per placeholder, %1 for the first letter, %2 for the second …:
///   n  a number (double): formatNumber(); in a window, the user's number format
///   i  a whole number, a count or an index (held as a double): every digit
///   d  a number shown with one decimal (a file's size in MiB)
///   k  a segment of the contour, by its index (a double): "contour[3]"; "segment 3" in a window
///   a  an axis of the machine, by its index (a double): "x", "y", "z"
///   f  a segment field (a SegmentPart): its file key "phi_start"; its column in a window
///   s  a term of the core (a string): English the core marks with CAM_TRANSLATE_NOOP in the
///      context kDiagnosticContext where it writes it ("a number", "the roller"), translated
///      by a window
///   t  text as it is (a string): from a file, the operating system, a path; never translated
///   l  a motion law, by its file name (a string): "cycloidal"; its title in a window
///   r  the diagnostic's reasons (takes no argument): each reason's text, joined by "; "
///
/// Why a reason is a diagnostic of its own and not an argument: a message that lists a
/// variable number of reasons ("no tangent line fits: a; b; c") cannot hold them in a fixed
/// signature, a reason may have arguments of its own (the segment a fillet's tangent point
/// would leave), and one may be a whole located diagnostic (the contour problem a fillet radius
/// would make).

#include <string>
#include <string_view>
#include <vector>

#include "common/diagnostic.h"

namespace cam {

/// @brief The translation context of the templates and of the `s` terms.
inline constexpr const char* kDiagnosticContext = "Diagnostic";

/// @brief One row of the catalogue.
struct DiagnosticEntry {
    DiagnosticCode code;
    const char* signature;  ///< one letter per placeholder, as above
    const char* text;       ///< the English template, the source text of its translations
};

/// @brief The code's row.
[[nodiscard]] const DiagnosticEntry& diagnosticEntry(DiagnosticCode code);
/// @brief "nnnn": one letter per placeholder.
[[nodiscard]] std::string_view diagnosticCodeSignature(DiagnosticCode code);
/// @brief The English template, "must be > 0 (got %1)".
[[nodiscard]] const char* diagnosticTemplate(DiagnosticCode code);

/// @brief Whether `args` are what the code's signature lists (every letter but `r` takes one,
/// in order, of its type).
[[nodiscard]] bool argumentsFit(DiagnosticCode code, const std::vector<DiagnosticArg>& args);

/// @brief `text` with %1 … %99 replaced by values[0] …; a placeholder without a value stays.
[[nodiscard]] std::string fillPlaceholders(std::string_view text,
                                           const std::vector<std::string>& values);

/// @brief An argument of the kind `kind` (a signature letter other than `r`) as the English
/// message shows it.
[[nodiscard]] std::string englishArgument(char kind, const DiagnosticArg& arg);

/// @brief The English message of the code with these arguments and reasons.
[[nodiscard]] std::string englishMessage(DiagnosticCode code,
                                         const std::vector<DiagnosticArg>& args,
                                         const Diagnostics& reasons);

}  // namespace cam
