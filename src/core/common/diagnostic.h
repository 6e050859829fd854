#pragma once
/// @file
/// @brief Located messages: how the core reports problems without throwing or printing.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cam {

enum class Severity { Error, Info };

/// @brief One problem (or note) and where it is, e.g. {"contour[3].radius", "must be > 0 (got
/// -2)"}.
struct Diagnostic {
    std::string location;
    std::string message;
    Severity severity = Severity::Error;

    /// @brief "location: message", the form the CLI and the app show.
    [[nodiscard]] std::string text() const {
        return location.empty() ? message : location + ": " + message;
    }
};

using Diagnostics = std::vector<Diagnostic>;

[[nodiscard]] inline bool hasErrors(const Diagnostics& diagnostics) {
    for (const auto& d : diagnostics) {
        if (d.severity == Severity::Error) return true;
    }
    return false;
}

/// @brief A value or the diagnostics that explain why there is none.
template <class T>
class Result {
public:
    Result(T value) : m_value(std::move(value)) {}  // NOLINT(google-explicit-constructor)
    Result(Diagnostics errors)
        : m_errors(std::move(errors)) {}  // NOLINT(google-explicit-constructor)

    [[nodiscard]] bool ok() const { return m_value.has_value(); }
    [[nodiscard]] const T& value() const& { return *m_value; }
    [[nodiscard]] T&& value() && { return std::move(*m_value); }
    [[nodiscard]] const Diagnostics& errors() const { return m_errors; }

private:
    std::optional<T> m_value;
    Diagnostics m_errors;
};

/// @brief Shortest text that reads back as the same double (for messages, not for files).
std::string formatNumber(double value);

}  // namespace cam
