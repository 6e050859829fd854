#pragma once
// Big valid projects generated as text, for the tests and benchmarks of loading: nothing this
// size is kept in the repository.

#include <cmath>
#include <cstdio>
#include <string>

namespace cam::test {

/// N arcs: one circle of radius 10 mm about the rotation centre cut into N equal windows.
inline std::string projectOfArcs(std::size_t n) {
    std::string text = R"({"format":"camwright","version":1,"motion":{"period_s":0.4},"contour":[)";
    char buffer[160];
    for (std::size_t k = 0; k < n; ++k) {
        const double start = 360.0 * static_cast<double>(k) / static_cast<double>(n);
        const double end = k + 1 == n ? 360.0 : 360.0 * static_cast<double>(k + 1) / n;
        std::snprintf(buffer, sizeof buffer,
                      R"(%s{"type":"arc","center":[0,0],"radius":10,"branch":"outer",)"
                      R"("phi_start":%.17g,"phi_end":%.17g})",
                      k ? ",\n" : "", start, end);
        text += buffer;
    }
    return text + "]}";
}

/// N lines: the regular N-gon of radius 100 mm about the rotation centre, one line per side,
/// their windows left to follow from the end points.
inline std::string projectOfLines(std::size_t n) {
    std::string text = R"({"format":"camwright","version":1,"motion":{"period_s":1},"contour":[)";
    char buffer[200];
    auto corner = [n](std::size_t k, double& x, double& y) {
        const double phi = 2.0 * M_PI * static_cast<double>(k % n) / static_cast<double>(n);
        x = 100.0 * std::cos(phi);
        y = 100.0 * std::sin(phi);
    };
    for (std::size_t k = 0; k < n; ++k) {
        double x0, y0, x1, y1;
        corner(k, x0, y0);
        corner(k + 1, x1, y1);
        std::snprintf(buffer, sizeof buffer,
                      R"(%s{"type":"line","from":[%.17g,%.17g],"to":[%.17g,%.17g]})",
                      k ? ",\n" : "", x0, y0, x1, y1);
        text += buffer;
    }
    return text + "]}";
}

/// `[{},{},…]`: N empty objects.
inline std::string emptyObjects(std::size_t n) {
    std::string text = "[";
    text.reserve(3 * n + 2);
    for (std::size_t k = 0; k < n; ++k) text += k ? ",{}" : "{}";
    return text + "]";
}

/// A project whose contour is N empty objects: N segments, each missing its type.
inline std::string projectOfEmptySegments(std::size_t n) {
    return R"({"format": "camwright", "version": 1, "motion": {"period_s": 1}, "contour": )" +
           emptyObjects(n) + "}";
}

}  // namespace cam::test
