#include "export/cam_table.h"

#include <cmath>

#include "analysis/analysis.h"
#include "common/angles.h"
#include "export/number_text.h"

namespace cam {

std::vector<CamKnot> camKnots(const Contour& contour, std::size_t points) {
    // The smallest r of the turn, refined between grid points (analysis.h); ω does not matter.
    const ContourAnalysis analysis = analyzeContour(contour, 1.0);
    double minR = 0.0;
    for (const QuantityExtremes& e : analysis.extremes) {
        if (e.quantity == Quantity::R) minR = e.min.value;
    }
    constexpr double perDeg = kPi / 180.0;
    std::vector<CamKnot> knots(points);
    for (std::size_t i = 0; i < points; ++i) {
        // 360·i/N exactly for the row, and the angle from it.
        const double deg = 360.0 * static_cast<double>(i) / static_cast<double>(points);
        const PolarDerivatives d = contour.evaluate(degToRad(deg));
        knots[i] = {deg, d.r - minR, d.dr * perDeg, d.d2r * perDeg * perDeg};
    }
    return knots;
}

Result<std::string> camTableText(const Contour& contour, const CamTableOptions& options) {
    const auto n = static_cast<long long>(options.points);
    if (n < kMinCamTablePoints || n > kMaxCamTablePoints) {
        return Diagnostics{{"--points", "a cam table has from " +
                                            std::to_string(kMinCamTablePoints) + " to " +
                                            std::to_string(kMaxCamTablePoints) + " points, not " +
                                            std::to_string(n)}};
    }
    const std::vector<CamKnot> knots = camKnots(contour, options.points);
    std::string out = "# camwright cam table: master angle -> knife-edge lift r(phi) - min r\n";
    out += "# master_start_deg=0\n# master_step_deg=";
    appendExact(out, 360.0 / static_cast<double>(n));
    out += "\n# points=" + std::to_string(n) + "\n# periodic=true\n# slave=lift_mm\n";
    out += "master_deg,position,velocity_per_deg,acceleration_per_deg2\n";
    for (const CamKnot& k : knots) {
        appendExact(out, k.masterDeg);
        out += ',';
        appendExact(out, k.position);
        out += ',';
        appendExact(out, k.velocity);
        out += ',';
        appendExact(out, k.acceleration);
        out += '\n';
    }
    return out;
}

}  // namespace cam
