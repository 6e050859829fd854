#pragma once
/// @file
/// @brief Free text on its way into an export: the project's name, or the file name that stands
/// in for it, may hold anything a user (or a hostile file) can type — line breaks, control
/// characters, markup, formula prefixes, bidirectional overrides, invalid UTF-8, 100,000
/// characters. Each format takes it only through one of these functions, which reduce it to
/// one harmless line and escape it for that format. Numbers and fixed words never need them.

#include <cstddef>
#include <string>
#include <string_view>

namespace cam {

/// Characters a title or comment keeps at most; a longer text ends in "…".
inline constexpr std::size_t kFreeTextMaxChars = 120;

/// @brief The text as one line of valid UTF-8: invalid bytes become U+FFFD; line breaks, tabs
/// and other control characters (C0, DEL, C1, U+2028/2029) a space; bidirectional controls
/// (U+061C, U+200E/F, U+202A–E, U+2066–9), the byte-order mark and noncharacters (U+FDD0–FDEF,
/// U+xFFFE/xFFFF, which XML forbids) are dropped; spaces at either end are trimmed; at most
/// `maxChars` characters, the last of them "…" when the text was longer.
[[nodiscard]] std::string oneLine(std::string_view text, std::size_t maxChars = kFreeTextMaxChars);

/// @brief Whether `text` is valid UTF-8 (no overlong forms, surrogates or values above
/// U+10FFFF): what a program that reads its arguments as UTF-8, like Qt, gets back unchanged.
[[nodiscard]] bool isValidUtf8(std::string_view text);

/// @brief oneLine() with &, <, >, " and ' escaped: text of an XML (SVG) element or attribute.
[[nodiscard]] std::string xmlText(std::string_view text, std::size_t maxChars = kFreeTextMaxChars);

/// @brief oneLine() for a CSV comment line, read by spreadsheets as cells: double quotes
/// become single ones (a cell opening with one would swallow the rows after it), and every
/// cell the line splits into at ',' or ';' that would begin (after spaces) with =, +, - or @,
/// a formula, begins with an apostrophe instead ("'=1+1").
[[nodiscard]] std::string csvCommentText(std::string_view text,
                                         std::size_t maxChars = kFreeTextMaxChars);

}  // namespace cam
