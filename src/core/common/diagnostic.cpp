#include "common/diagnostic.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace cam {
namespace {

/// "[i]", built by appends: GCC 12 warns falsely on "[" + string (PR105651).
std::string bracketed(int i) {
    std::string out = "[";
    out += std::to_string(i);
    out += ']';
    return out;
}

}  // namespace

std::string segmentLocation(std::size_t index) {
    std::string out = "contour";
    out += bracketed(static_cast<int>(index));
    return out;
}

std::string jointLocation(std::size_t left, std::size_t right) {
    return segmentLocation(left) + "/" + segmentLocation(right);
}

std::string locationText(const SegmentPlace& place) {
    std::string text = segmentLocation(place.segment);
    switch (place.part) {
        case SegmentPart::Whole:
            return text;
        case SegmentPart::Type:
            text += ".type";
            break;
        case SegmentPart::Center:
            text += ".center";
            break;
        case SegmentPart::Radius:
            text += ".radius";
            break;
        case SegmentPart::Branch:
            text += ".branch";
            break;
        case SegmentPart::From:
            text += ".from";
            break;
        case SegmentPart::To:
            text += ".to";
            break;
        case SegmentPart::Points:
            text += ".points";
            if (place.point >= 0) text += bracketed(place.point);
            break;
        case SegmentPart::P0:
            text += ".p0";
            break;
        case SegmentPart::T0:
            text += ".t0";
            break;
        case SegmentPart::P3:
            text += ".p3";
            break;
        case SegmentPart::T1:
            text += ".t1";
            break;
        case SegmentPart::PhiStart:
            text += ".phi_start";
            break;
        case SegmentPart::PhiEnd:
            text += ".phi_end";
            break;
    }
    if (place.axis >= 0) text += bracketed(place.axis);
    return text;
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
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc{} ? std::string(buffer, end) : std::string("?");
}

}  // namespace cam
