#pragma once
/// @file
/// @brief Pictures of the real window without a display: `camwright --screenshot` and tests.

#include <QImage>
#include <QSize>
#include <QString>

namespace cam {

class MainWindow;

/// @brief The window at `size`, once the newest computation (and, with the Machining dock open,
/// its times) is shown, with the cursor at T/8. Transient status messages are cleared: they
/// name paths. Empty if no result arrived within 20 s.
[[nodiscard]] QImage renderScreenshot(MainWindow& window, const QSize& size);

/// @brief `--screenshot FILE [--size WxH]`: renders and writes the PNG through the one file
/// writer. Returns the exit code (0, 1 for a bad size, 2 for a file that cannot be written, 3
/// when the computation did not finish); messages go to stderr.
int writeScreenshot(MainWindow& window, const QString& file, const QString& sizeText);

/// @brief `--export-plot NAME [--format png|pdf|svg] --out FILE [--size WxH]`: the plot of the
/// loaded project as MainWindow::plotPicture() draws it, written through the one file writer.
/// The format defaults to FILE's suffix, the size to defaultPictureSize(). Returns the exit
/// code as camwright-cli does (1 a bad argument, 2 a file that cannot be written, 3 a plot that
/// cannot be drawn); messages go to stderr.
int writePlotPicture(MainWindow& window, const QString& plotName, const QString& formatName,
                     const QString& file, const QString& sizeText);

}  // namespace cam
