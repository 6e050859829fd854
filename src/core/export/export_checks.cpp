#include "export/export_checks.h"

#include "project/project.h"

namespace cam {

void checkTolerance(double toleranceMm, Diagnostics& errors) {
    if (!(toleranceMm >= kMinExportToleranceMm && toleranceMm <= kMaxExportToleranceMm)) {
        errors.push_back(Diagnostic("--tolerance", "the tolerance must be between " +
                                                       formatNumber(kMinExportToleranceMm) +
                                                       " and " +
                                                       formatNumber(kMaxExportToleranceMm) +
                                                       " mm, not " + formatNumber(toleranceMm))
                             .coded(DiagnosticCode::ExportToleranceOutOfRange,
                                    {kMinExportToleranceMm, kMaxExportToleranceMm, toleranceMm}));
    }
}

void checkToolRadius(double radiusMm, Diagnostics& errors) {
    if (!(radiusMm > 0.0 && radiusMm <= kMaxLengthMm)) {
        errors.push_back(
            Diagnostic("--tool-radius", "the tool radius must be above 0 and at most " +
                                            formatNumber(kMaxLengthMm) + " mm, not " +
                                            formatNumber(radiusMm))
                .coded(DiagnosticCode::ExportToolRadiusOutOfRange, {kMaxLengthMm, radiusMm}));
    }
}

}  // namespace cam
