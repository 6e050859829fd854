#include "common/diagnostic.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/diagnostic_catalogue.h"

namespace cam {

Diagnostic Diagnostic::make(Place place, DiagnosticCode code, std::vector<DiagnosticArg> args,
                            Severity severity) {
    Diagnostic d;
    d.location = locationText(place);
    d.message = englishMessage(code, args, {});
    d.severity = severity;
    d.place = std::move(place);
    d.code = code;
    d.args = std::move(args);
    return d;
}

Diagnostic Diagnostic::because(Diagnostics reasons_) && {
    reasons = std::move(reasons_);
    message = englishMessage(code, args, reasons);
    return std::move(*this);
}

std::string_view diagnosticCodeName(DiagnosticCode code) {
    switch (code) {
#define CAM_DIAGNOSTIC_NAME(name) \
    case DiagnosticCode::name:    \
        return #name;
        CAM_DIAGNOSTIC_CODES(CAM_DIAGNOSTIC_NAME)
#undef CAM_DIAGNOSTIC_NAME
    }
    return "?";
}

void internalError(const std::string& what) {
    std::fprintf(stderr, "camwright: internal error: %s\n", what.c_str());
    std::abort();
}

void resultHasNoValue(const Diagnostics& errors) {
    internalError("Result::value() read without a value (" +
                  (errors.empty() ? std::string("no diagnostics") : errors.front().text()) + ")");
}

std::string formatNumber(double value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (value == 0.0) return "0";  // never "-0"
    // The shortest digits that read back as the value, or kMessageDigits of them when the
    // shortest are more (round-off): "d.ddde±x".
    char buffer[48];
    auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
    if (ec != std::errc{}) return "?";
    std::string text(buffer, end);
    std::size_t e = text.find('e');
    const std::size_t digitCount = e - (text[0] == '-') - (text.find('.') < e ? 1 : 0);
    if (digitCount > static_cast<std::size_t>(kMessageDigits)) {
        const auto rounded = std::to_chars(buffer, buffer + sizeof buffer, value,
                                           std::chars_format::scientific, kMessageDigits - 1);
        text.assign(buffer, rounded.ptr);
        e = text.find('e');
    }
    const bool negative = text[0] == '-';
    std::string digits;
    for (std::size_t i = negative ? 1 : 0; i < e; ++i) {
        if (text[i] != '.') digits += text[i];
    }
    while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
    const int exponent = std::stoi(text.substr(e + 1));
    // Laid out as printf's %g would with kMessageDigits: positional from 1e-4 up to below
    // 1e10, otherwise with an exponent of at least two digits.
    // (Appended piece by piece: GCC 12 warns falsely, -Wrestrict, on "0." + std::string.)
    std::string out = negative ? "-" : "";
    const std::size_t n = digits.size();
    if (exponent >= -4 && exponent < kMessageDigits) {
        if (exponent < 0) {
            out.append("0.").append(static_cast<std::size_t>(-exponent - 1), '0').append(digits);
        } else if (n <= static_cast<std::size_t>(exponent) + 1) {
            out.append(digits).append(static_cast<std::size_t>(exponent) + 1 - n, '0');
        } else {
            const std::size_t point = static_cast<std::size_t>(exponent) + 1;
            out.append(digits, 0, point).append(1, '.').append(digits, point);
        }
        return out;
    }
    out.append(digits, 0, 1);
    if (n > 1) out.append(1, '.').append(digits, 1);
    const int magnitude = exponent < 0 ? -exponent : exponent;
    out.append(exponent < 0 ? "e-" : "e+");
    if (magnitude < 10) out.append(1, '0');
    return out.append(std::to_string(magnitude));
}

}  // namespace cam
