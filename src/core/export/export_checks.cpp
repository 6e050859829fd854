#include "export/export_checks.h"

#include "project/project.h"

namespace cam {

void checkTolerance(double toleranceMm, Diagnostics& errors) {
    if (!(toleranceMm >= kMinExportToleranceMm && toleranceMm <= kMaxExportToleranceMm)) {
        errors.push_back(Diagnostic::make(
            FieldPlace{Field::ToleranceOption}, DiagnosticCode::ExportToleranceOutOfRange,
            {kMinExportToleranceMm, kMaxExportToleranceMm, toleranceMm}));
    }
}

void checkToolRadius(double radiusMm, Diagnostics& errors) {
    if (!(radiusMm > 0.0 && radiusMm <= kMaxLengthMm)) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::ToolRadiusOption},
                                          DiagnosticCode::ExportToolRadiusOutOfRange,
                                          {kMaxLengthMm, radiusMm}));
    }
}

}  // namespace cam
