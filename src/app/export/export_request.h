#pragma once
/// @file
/// @brief What File → Export… asks for: a format, its options and a file; and the text of the
/// file formats that the core writes (every format but plot pictures).

#include <QSize>
#include <QString>
#include <cstddef>
#include <optional>
#include <string>

#include "common/diagnostic.h"
#include "export/cam_table.h"
#include "export/dxf.h"
#include "export/export_formats.h"
#include "export/gcode.h"
#include "export/plot_picture.h"
#include "export/svg.h"
#include "project/project.h"

namespace cam {

/// The formats and their dialects are the core's table (export/export_formats.h).
using ExportFormat = ExportFormatId;

struct ExportRequest {
    ExportFormat format = ExportFormat::Dxf;
    QString path;               ///< the file to write
    std::size_t csvPoints = 0;  ///< samples of the turn; 0: the project's samples_per_turn
    bool csvGerman = false;     ///< ";" and decimal commas (forGermanSpreadsheets)
    DxfOptions dxf;
    SvgOptions svg;
    GcodeOptions gcode;
    /// A conjugate pair's program mills this plate: 1 (the contour) or 2 (the second plate).
    int gcodePlate = 1;
    CamTableOptions camTable;
    /// The cam table's motion: the design's law (exact) or the follower on the contour; none:
    /// as camwright-cli's default, the law when the project has a design, else the contour.
    std::optional<CamTableSource> camTableSource;
    PlotKind plot = PlotKind::Contour;
    PictureFormat picture = PictureFormat::Png;
    QSize pictureSize;  ///< empty: defaultPictureSize()
};

/// @brief "DXF drawing (R2000)", … (translated).
[[nodiscard]] QString exportFormatTitle(ExportFormat format);
/// @brief "CODESYS Structured Text (SMC_CAMXYVA)", … (translated).
[[nodiscard]] QString exportDialectTitle(const ExportDialectKind& dialect);
/// @brief The file suffix a request's file gets by default: csv, dxf, svg, ngc, csv or st,
/// png/pdf/svg.
[[nodiscard]] QString exportSuffix(const ExportRequest& request);

/// @brief The file's text for every format but Plot, from a snapshot of the project: the same
/// core functions as `camwright-cli export`. Safe to call from any thread. Errors: the project's
/// problems, an option out of range, a shape the format cannot take (a tool too wide).
[[nodiscard]] Result<std::string> exportText(const Project& project, const ExportRequest& request);

/// @brief The motion a cam table of `source` samples (the design's law, or the follower on the
/// contour), from a snapshot of the project. Errors: no design for the law, no contour for the
/// contour, the design's or the follower's problems.
[[nodiscard]] Result<CamMotion> camTableMotion(const Project& project, CamTableSource source);

}  // namespace cam
