#include "export/export_formats.h"

#include <array>

#include "common/kind_table.h"
#include "common/translate_marker.h"
#include "export/cam_table.h"

namespace cam {
namespace {

using Names = std::string_view;

constexpr Names kCsvOptions[] = {"--points"};
constexpr Names kDxfOptions[] = {"--tolerance", "--tool-radius"};
constexpr Names kDxfFlags[] = {"--polyline", "--spline-entities", "--centres"};
constexpr Names kSvgOptions[] = {"--tolerance"};
constexpr Names kGcodeOptions[] = {"--tolerance", "--tool-radius", "--depth", "--step-down",
                                   "--plate"};
constexpr Names kGcodeFlags[] = {"--compensation"};
constexpr Names kCamTableOptions[] = {"--points", "--dialect", "--source", "--tolerance"};
constexpr Names kPictureOptions[] = {"--plot", "--size"};

/// The first dialect is the default; a cam table's are in CamTableDialect's order, a
/// picture's in the app's PictureFormat order (Png, Pdf, Svg).
constexpr ExportDialectKind kCamTableDialects[] = {
    {"csv", CAM_TRANSLATE_NOOP("ExportFormat", "CSV"), "csv"},
    {"codesys", CAM_TRANSLATE_NOOP("ExportFormat", "CODESYS Structured Text (SMC_CAMXYVA)"), "st"},
    {"beckhoff",
     CAM_TRANSLATE_NOOP("ExportFormat",
                        "Beckhoff TwinCAT Structured Text (MC_MotionFunctionPoint)"),
     "st"},
    {"rockwell", CAM_TRANSLATE_NOOP("ExportFormat", "Rockwell Logix Structured Text (CAM array)"),
     "st"},
    {"kollmorgen", CAM_TRANSLATE_NOOP("ExportFormat", "Kollmorgen KAS cam profile CSV"), "csv"},
};
static_assert(kCamTableDialects[static_cast<int>(CamTableDialect::Csv)].name == "csv" &&
              kCamTableDialects[static_cast<int>(CamTableDialect::Codesys)].name == "codesys" &&
              kCamTableDialects[static_cast<int>(CamTableDialect::Beckhoff)].name == "beckhoff" &&
              kCamTableDialects[static_cast<int>(CamTableDialect::Rockwell)].name == "rockwell" &&
              kCamTableDialects[static_cast<int>(CamTableDialect::Kollmorgen)].name ==
                  "kollmorgen" &&
              std::size(kCamTableDialects) == 5);
constexpr ExportDialectKind kPictureDialects[] = {
    {"png", CAM_TRANSLATE_NOOP("ExportFormat", "PNG image"), "png"},
    {"pdf", CAM_TRANSLATE_NOOP("ExportFormat", "PDF document (vector)"), "pdf"},
    {"svg", CAM_TRANSLATE_NOOP("ExportFormat", "SVG drawing (vector)"), "svg"},
};

/// Every format, one row each, in ExportFormatId order.
constexpr std::array<ExportFormatKind, 6> kFormats{{
    {ExportFormatId::Csv,
     "csv",
     CAM_TRANSLATE_NOOP("ExportFormat", "CSV: the sampled turn"),
     "csv",
     kCsvOptions,
     {},
     {}},
    {ExportFormatId::Dxf,
     "dxf",
     CAM_TRANSLATE_NOOP("ExportFormat", "DXF drawing (R2000, mm)"),
     "dxf",
     kDxfOptions,
     kDxfFlags,
     {}},
    {ExportFormatId::Svg,
     "svg",
     CAM_TRANSLATE_NOOP("ExportFormat", "SVG drawing, 1:1 in mm"),
     "svg",
     kSvgOptions,
     {},
     {}},
    {ExportFormatId::Gcode,
     "gcode",
     CAM_TRANSLATE_NOOP("ExportFormat", "G-code for milling the cam"),
     "ngc",
     kGcodeOptions,
     kGcodeFlags,
     {}},
    {ExportFormatId::CamTable,
     "camtable",
     CAM_TRANSLATE_NOOP("ExportFormat", "Servo cam table"),
     "csv",
     kCamTableOptions,
     {},
     kCamTableDialects},
    // The CLI names a picture by its dialect (`--format png`); an SVG picture is `--format svg`
    // with `--plot`, the drawing without.
    {ExportFormatId::Picture,
     "",
     CAM_TRANSLATE_NOOP("ExportFormat", "Picture of a plot (PNG, PDF, SVG)"),
     "png",
     kPictureOptions,
     {},
     kPictureDialects},
}};

static_assert(rowsFollowTheirEnum(kFormats, &ExportFormatKind::id),
              "one row per export format, in ExportFormatId order");

}  // namespace

std::span<const ExportFormatKind> exportFormats() { return kFormats; }

const ExportFormatKind& exportFormat(ExportFormatId id) {
    return kFormats.at(static_cast<std::size_t>(id));
}

const ExportDialectKind* findDialect(const ExportFormatKind& format, std::string_view name) {
    for (const ExportDialectKind& dialect : format.dialects) {
        if (dialect.name == name) return &dialect;
    }
    return nullptr;
}

std::string exportName(const std::string& projectName, const std::string& filePath) {
    if (!projectName.empty()) return projectName;
    std::string name = filePath.substr(filePath.find_last_of("/\\") + 1);
    for (const std::string_view suffix :
         {std::string_view(".cam.json"), std::string_view(".json")}) {
        if (name.size() > suffix.size() && name.ends_with(suffix)) {
            name.resize(name.size() - suffix.size());
            break;
        }
    }
    return name.empty() ? "untitled" : name;
}

}  // namespace cam
