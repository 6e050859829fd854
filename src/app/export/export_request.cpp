#include "export/export_request.h"

#include <QCoreApplication>

#include "closure/conjugate.h"
#include "contour/contour.h"
#include "design/motion_design.h"
#include "export/sample_csv.h"

namespace cam {

QString exportFormatTitle(ExportFormat format) {
    return QCoreApplication::translate("ExportFormat", exportFormat(format).title);
}

QString exportDialectTitle(const ExportDialectKind& dialect) {
    return QCoreApplication::translate("ExportFormat", dialect.title);
}

QString exportSuffix(const ExportRequest& request) {
    // A dialect's suffix wins; the table lists them in CamTableDialect's and PictureFormat's
    // order.
    const ExportFormatKind& kind = exportFormat(request.format);
    std::size_t dialect = 0;
    if (request.format == ExportFormat::CamTable) {
        dialect = static_cast<std::size_t>(request.camTable.dialect);
    } else if (request.format == ExportFormat::Picture) {
        dialect = static_cast<std::size_t>(request.picture);
    }
    const std::string_view suffix =
        dialect < kind.dialects.size() ? kind.dialects[dialect].suffix : kind.suffix;
    return QString::fromUtf8(suffix.data(), static_cast<qsizetype>(suffix.size()));
}

Result<CamMotion> camTableMotion(const Project& project, CamTableSource source) {
    const FollowerSpec follower = project.follower.value_or(FollowerSpec{});
    if (source == CamTableSource::Law) {
        if (!project.design) {
            return Diagnostics{
                {"source", QCoreApplication::translate("ExportRequest",
                                                       "the project has no design: its law is the "
                                                       "source only of a design's table")
                               .toStdString()}};
        }
        auto design = MotionDesign::build(*project.design);
        if (!design.ok()) return design.errors();
        return lawMotion(design.value(), follower.motion == FollowerMotion::Oscillating);
    }
    if (project.contour.empty()) {
        return Diagnostics{{"source", QCoreApplication::translate(
                                          "ExportRequest",
                                          "the project has no contour yet: Synthesize (F6) "
                                          "makes it from the design")
                                          .toStdString()}};
    }
    auto contour = Contour::build(project);
    if (!contour.ok()) return contour.errors();
    return contourMotion(contour.value(), follower);
}

Result<std::string> exportText(const Project& project, const ExportRequest& request) {
    if (request.format == ExportFormat::CamTable) {
        // As camwright-cli's --source: a design's law needs no contour (a plain electronic
        // cam), the contour needs no design.
        CamTableOptions options = request.camTable;
        options.follower = project.follower.value_or(FollowerSpec{});
        auto motion = camTableMotion(
            project, request.camTableSource.value_or(project.design ? CamTableSource::Law
                                                                    : CamTableSource::Contour));
        if (!motion.ok()) return motion.errors();
        auto table = camTable(motion.value(), options);
        if (!table.ok()) return table.errors();
        return std::move(table).value().text;
    }
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
            // With dynamics the forces' columns follow the follower's (math.md §9).
            std::optional<ForceModel> forces;
            if (project.dynamics)
                forces = ForceModel::of(*project.dynamics, follower.value().spec());
            auto csv = sampleCsv(contour.value(), project.motion.omegaRadS(), points,
                                 &follower.value(), forces ? &*forces : nullptr);
            if (csv.ok() && request.csvGerman) return forGermanSpreadsheets(csv.value());
            return csv;
        }
        // A grooved cam's drawings show both flanks and its program mills the groove; a
        // conjugate pair's show both plates and its program mills the plate asked for.
        case ExportFormat::Dxf: {
            DxfOptions options = request.dxf;
            options.groove = grooveOf(project);
            auto plate = secondPlateOf(project, contour.value());
            if (!plate.ok()) return plate.errors();
            if (plate.value()) options.secondPlate = plate.value()->path;
            return dxfDocument(contour.value(), options);
        }
        case ExportFormat::Svg: {
            SvgOptions options = request.svg;
            options.groove = grooveOf(project);
            auto plate = secondPlateOf(project, contour.value());
            if (!plate.ok()) return plate.errors();
            if (plate.value()) options.secondPlate = plate.value()->path;
            return svgDocument(contour.value(), options);
        }
        case ExportFormat::Gcode: {
            GcodeOptions options = request.gcode;
            options.groove = grooveOf(project);
            if (request.gcodePlate == 2) {
                auto plate = secondPlateOf(project, contour.value());
                if (!plate.ok()) return plate.errors();
                if (!plate.value()) {
                    return Diagnostics{{"plate", "only a conjugate pair has a second plate"}};
                }
                auto second = plateContour(*plate.value());
                if (!second.ok()) return second.errors();
                options.projectName += ", second plate";
                return gcodeProgram(second.value(), options);
            }
            return gcodeProgram(contour.value(), options);
        }
        case ExportFormat::CamTable:  // above
        case ExportFormat::Picture:
            break;
    }
    return Diagnostics{{"format", "a plot is drawn by the app, not written as text"}};
}

}  // namespace cam
