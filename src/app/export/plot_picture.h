#pragma once
/// @file
/// @brief Pictures of the app's plots as PNG, PDF (vector) or SVG: what right-click → Export
/// plot…, File → Export… and `camwright --export-plot` write.

#include <QByteArray>
#include <QSize>
#include <QString>
#include <functional>
#include <optional>
#include <vector>

class QCustomPlot;

namespace cam {

enum class PictureFormat { Png, Pdf, Svg };

/// @brief The plots of the app that can be exported, by the name `--plot` and
/// `camwright --export-plot` take.
enum class PlotKind {
    Contour,           ///< "contour": the contour view
    Velocity,          ///< "velocity"
    Acceleration,      ///< "acceleration"
    Jerk,              ///< "jerk"
    Feed,              ///< "feed": the machining panel's feed along the path
    AxisAcceleration,  ///< "axis-acceleration": the machining panel's axis accelerations
    PressureAngle,     ///< "pressure-angle": the follower panel's, with the limit
    Lift,              ///< "lift": the follower's lift (the polar view: the radius r)
    Motion,            ///< "motion": one sheet of lift, velocity, acceleration and jerk
};
inline constexpr PlotKind kPlotKinds[] = {
    PlotKind::Contour,       PlotKind::Velocity, PlotKind::Acceleration,
    PlotKind::Jerk,          PlotKind::Feed,     PlotKind::AxisAcceleration,
    PlotKind::PressureAngle, PlotKind::Lift,     PlotKind::Motion};
/// @brief "contour", "velocity", …: the name on the command line and in file names.
[[nodiscard]] QString plotKindName(PlotKind kind);
/// @brief The kind of that name; none for any other.
[[nodiscard]] std::optional<PlotKind> plotKindNamed(const QString& name);
/// @brief "contour, velocity, acceleration, jerk, feed, axis-acceleration, pressure-angle,
/// lift, motion".
[[nodiscard]] QString plotKindNames();
/// @brief The plot's title as the user reads it (translated): "Velocity".
[[nodiscard]] QString plotKindTitle(PlotKind kind);
/// @brief Whether the plot shows the machining times (it needs the project's machining section
/// and the Machining panel open).
[[nodiscard]] inline bool isMachiningPlot(PlotKind kind) {
    return kind == PlotKind::Feed || kind == PlotKind::AxisAcceleration;
}

/// @brief "png", "pdf", "svg" (any case); none for anything else.
[[nodiscard]] std::optional<PictureFormat> pictureFormatNamed(const QString& name);
/// @brief The format a file name's suffix names; none for any other suffix.
[[nodiscard]] std::optional<PictureFormat> pictureFormatOfFile(const QString& fileName);
[[nodiscard]] QString pictureSuffix(PictureFormat format);

/// @brief The size a picture gets when none is asked for: 1200 × 800 pixels for PNG, A4
/// landscape (842 × 595 pt) for PDF and SVG.
[[nodiscard]] QSize defaultPictureSize(PictureFormat format);
inline constexpr int kMinPictureSide = 100;
inline constexpr int kMaxPictureSide = 8000;

/// @brief The property (true) of a plot's items a picture leaves out: the cursor line and the
/// joint markers, which are for working on screen.
inline constexpr const char* kNotInPictures = "camwrightNotInPictures";

/// @brief What a picture shows besides the plot itself.
struct PictureText {
    QString title;   ///< a line above the plot; also the PDF's and SVG's title
    QString xLabel;  ///< the x axis label while the picture is drawn, if the plot shows none
};

/// @brief The plot drawn at `size` (PNG: pixels; PDF: points, one page of exactly that size;
/// SVG: user units) in `format`, its x axis numbered. `fit` runs once the plot is laid out at that
/// size and before it is drawn (the contour view keeps its equal scales there). The plot on screen
/// is left as it was: viewport, ranges, labels and layout are restored. PDF and SVG are vector
/// (text as text); the PDF's creator is "Camwright VERSION". Empty when the painter could not
/// start.
[[nodiscard]] QByteArray renderPlotPicture(QCustomPlot& plot, PictureFormat format, QSize size,
                                           const PictureText& text,
                                           const std::function<void()>& fit = {});

/// @brief Plots stacked on one sheet, top to bottom, sharing its height by `stretch` (one
/// factor per plot): the title above the first, the x label (`text.xLabel` where a plot shows
/// none) under each. Otherwise as renderPlotPicture.
[[nodiscard]] QByteArray renderPlotSheet(const std::vector<QCustomPlot*>& plots,
                                         const std::vector<int>& stretch, PictureFormat format,
                                         QSize size, const PictureText& text);

}  // namespace cam
