#include "export/export_request.h"

#include <QCoreApplication>

#include "contour/contour.h"
#include "export/sample_csv.h"

namespace cam {

QString exportFormatTitle(ExportFormat format) {
    switch (format) {
        case ExportFormat::Csv:
            return QCoreApplication::translate("ExportFormat", "CSV: the sampled turn");
        case ExportFormat::Dxf:
            return QCoreApplication::translate("ExportFormat", "DXF drawing (R2000, mm)");
        case ExportFormat::Svg:
            return QCoreApplication::translate("ExportFormat", "SVG drawing, 1:1 in mm");
        case ExportFormat::Gcode:
            return QCoreApplication::translate("ExportFormat", "G-code for milling the cam");
        case ExportFormat::CamTable:
            return QCoreApplication::translate("ExportFormat", "Servo cam table");
        case ExportFormat::Plot:
            return QCoreApplication::translate("ExportFormat", "Picture of a plot (PNG, PDF, SVG)");
    }
    return {};
}

QString exportSuffix(const ExportRequest& request) {
    switch (request.format) {
        case ExportFormat::Csv:
            return "csv";
        case ExportFormat::Dxf:
            return "dxf";
        case ExportFormat::Svg:
            return "svg";
        case ExportFormat::Gcode:
            return "ngc";
        case ExportFormat::CamTable:
            return request.camTable.dialect == CamTableDialect::Codesys ? "st" : "csv";
        case ExportFormat::Plot:
            return pictureSuffix(request.picture);
    }
    return {};
}

Result<std::string> exportText(const Project& project, const ExportRequest& request) {
    auto contour = Contour::build(project);
    if (!contour.ok()) return contour.errors();
    switch (request.format) {
        case ExportFormat::Csv: {
            const std::size_t points =
                request.csvPoints > 0 ? request.csvPoints
                                      : static_cast<std::size_t>(project.samplesPerTurnOrDefault());
            auto follower =
                FollowerModel::build(contour.value(), project.follower.value_or(FollowerSpec{}));
            if (!follower.ok()) return follower.errors();
            return sampleCsv(contour.value(), project.motion.omegaRadS(), points,
                             &follower.value());
        }
        case ExportFormat::Dxf:
            return dxfDocument(contour.value(), request.dxf);
        case ExportFormat::Svg:
            return svgDocument(contour.value(), request.svg);
        case ExportFormat::Gcode:
            return gcodeProgram(contour.value(), request.gcode);
        case ExportFormat::CamTable: {
            CamTableOptions options = request.camTable;
            options.follower = project.follower.value_or(FollowerSpec{});
            return camTableText(contour.value(), options);
        }
        case ExportFormat::Plot:
            break;
    }
    return Diagnostics{{"format", "a plot is drawn by the app, not written as text"}};
}

}  // namespace cam
