#include "closure/groove.h"

#include <cmath>

namespace cam {

Result<GrooveFlanks> grooveFlanks(const Contour& contour, double rollerRadius, double clearance) {
    Diagnostics errors;
    if (!(std::isfinite(rollerRadius) && rollerRadius > 0.0)) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::FollowerRadius},
                                          DiagnosticCode::NotPositive, {rollerRadius}));
    }
    if (!(std::isfinite(clearance) && clearance >= 0.0)) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::FollowerGrooveClearance},
                                          DiagnosticCode::OutOfRange,
                                          {0.0, kMaxLengthMm, std::string(" mm"), clearance}));
    }
    if (!errors.empty()) return errors;
    auto pitch = toolPathFromContour(contour, rollerRadius);
    if (!pitch.ok()) return pitch.errors();
    // The outer flank is the inner one offset by 2ρ + c: where that offset degenerates, the
    // pitch curve's concave stretch is tighter than ρ + c and the outer flank folds over.
    auto outer = toolPathFromContour(contour, 2.0 * rollerRadius + clearance);
    if (!outer.ok()) {
        for (const Diagnostic& d : outer.errors()) {
            const bool undercut = d.code == DiagnosticCode::ToolNotBelowArcRadius ||
                                  d.code == DiagnosticCode::ToolAboveCurveRadius;
            if (!undercut) {
                errors.push_back(d);
                continue;
            }
            // The arguments of both: the tool radius, then the inner flank's concave radius.
            const double radius = std::get<double>(d.args.at(1));
            errors.push_back(Diagnostic::make(d.place, DiagnosticCode::GrooveOuterFlankUndercut,
                                              {rollerRadius, clearance, radius}));
        }
        return errors;
    }
    return GrooveFlanks{std::move(pitch).value(), std::move(outer).value()};
}

}  // namespace cam
