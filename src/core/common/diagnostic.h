#pragma once
/// @file
/// @brief Located messages: how the core reports problems without throwing or printing.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cam {

enum class Severity { Error, Info };

/// @brief Which field of a segment a problem concerns.
enum class SegmentPart {
    Whole,  ///< the segment as a whole (its shape, its window)
    Type,
    Center,
    Radius,
    Branch,
    From,
    To,
    Points,  ///< a Bézier's control points; SegmentPlace::point says which
    P0,      ///< a Hermite's start point
    T0,      ///< its start tangent
    P3,      ///< its end point
    T1,      ///< its end tangent
    PhiStart,
    PhiEnd,
};

/// @brief A place in the contour, as data: the app marks table cells from it, the text form is
/// derived from it and never parsed back.
struct SegmentPlace {
    std::size_t segment = 0;
    SegmentPart part = SegmentPart::Whole;
    int point = -1;  ///< SegmentPart::Points: which control point, 0..3
    int axis = -1;   ///< of a point: 0 x, 1 y; -1 the whole point

    friend bool operator==(const SegmentPlace&, const SegmentPlace&) = default;
};

/// @brief "contour[3]".
[[nodiscard]] std::string segmentLocation(std::size_t index);
/// @brief "contour[3]", "contour[3].radius", "contour[3].points[2][0]", "contour[3].p0[1]".
[[nodiscard]] std::string locationText(const SegmentPlace& place);
/// @brief "contour[4]/contour[5]": the joint where `left` ends and `right` begins.
[[nodiscard]] std::string jointLocation(std::size_t left, std::size_t right);

/// @brief One problem (or note) and where it is, e.g. {"contour[3].radius", "must be > 0 (got
/// -2)"}. Problems in the contour also carry their place as data.
struct Diagnostic {
    Diagnostic() = default;
    Diagnostic(std::string location_, std::string message_, Severity severity_ = Severity::Error,
               std::vector<SegmentPlace> places_ = {})
        : location(std::move(location_)),
          message(std::move(message_)),
          severity(severity_),
          places(std::move(places_)) {}

    std::string location;
    std::string message;
    Severity severity = Severity::Error;
    /// The segment fields it concerns (empty when it is not about a segment): one for a field,
    /// two (phi_end of the left, phi_start of the right) for a joint.
    std::vector<SegmentPlace> places;

    /// @brief A problem of one segment field; the location text follows from the place.
    [[nodiscard]] static Diagnostic at(const SegmentPlace& place, std::string message,
                                       Severity severity = Severity::Error) {
        return {locationText(place), std::move(message), severity, {place}};
    }
    /// @brief A problem of the joint where `left` ends and `right` begins.
    [[nodiscard]] static Diagnostic atJoint(std::size_t left, std::size_t right,
                                            std::string message,
                                            Severity severity = Severity::Error) {
        return {jointLocation(left, right),
                std::move(message),
                severity,
                {{left, SegmentPart::PhiEnd}, {right, SegmentPart::PhiStart}}};
    }

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

/// @brief Reports a broken precondition (a programming error, never bad input) and aborts.
[[noreturn]] void internalError(const std::string& what);

/// @brief Reports a Result read without a value and aborts.
[[noreturn]] void resultHasNoValue(const Diagnostics& errors);

/// @brief A value or the diagnostics that explain why there is none.
template <class T>
class Result {
public:
    Result(T value) : m_value(std::move(value)) {}  // NOLINT(google-explicit-constructor)
    Result(Diagnostics errors)
        : m_errors(std::move(errors)) {}  // NOLINT(google-explicit-constructor)

    [[nodiscard]] bool ok() const { return m_value.has_value(); }
    /// @brief The value; only when ok(). Without one it aborts with a message (in every build
    /// type), never reads an empty optional.
    [[nodiscard]] const T& value() const& {
        if (!m_value) [[unlikely]]
            resultHasNoValue(m_errors);
        return *m_value;
    }
    [[nodiscard]] T&& value() && {
        if (!m_value) [[unlikely]]
            resultHasNoValue(m_errors);
        return std::move(*m_value);
    }
    [[nodiscard]] const Diagnostics& errors() const { return m_errors; }

private:
    std::optional<T> m_value;
    Diagnostics m_errors;
};

/// @brief How many significant digits a number in a message has at most.
inline constexpr int kMessageDigits = 10;

/// @brief A number for a message (never for a file, which writes the exact value): at most
/// kMessageDigits significant digits and no trailing zeros, so a typed 12.5 reads 12.5 and the
/// round-off of a computed 215.6 (215.60000000000002) reads 215.6; never "-0".
std::string formatNumber(double value);

}  // namespace cam
