#pragma once
/// @file
/// @brief The window's exports: File → Export… (its dialog, then the file written in a worker
/// thread), right-click → Export Plot… on every plot, and the pictures of the plots.

#include <QByteArray>
#include <QObject>
#include <QSize>
#include <vector>

#include "export/export_request.h"
#include "export/plot_picture.h"

class QCustomPlot;
class QMainWindow;

namespace Ui {
class MainWindow;
}

namespace cam {

class ComputeEngine;
class DockLayout;
class ProjectDocument;
class ResultHub;

class ExportController : public QObject {
    Q_OBJECT
public:
    ExportController(QMainWindow* window, Ui::MainWindow& ui, ProjectDocument* document,
                     const ComputeEngine* engine, DockLayout& views, const ResultHub* results);

    /// @brief The widget that draws this plot.
    [[nodiscard]] QCustomPlot* plotWidget(PlotKind kind) const;
    /// @brief The plots that can be drawn now: every plot once a result is shown, the
    /// machining plots only while the Machining panel shows times of a machining section.
    [[nodiscard]] std::vector<PlotKind> drawablePlots() const;
    /// @brief The plot as a picture titled "PROJECT — PLOT" (renderPlotPicture), at `size`
    /// (empty: the plot's size on screen). Empty with `problem` set when it cannot be drawn.
    [[nodiscard]] QByteArray plotPicture(PlotKind kind, PictureFormat format, QSize size,
                                         QString* problem);
    /// @brief Writes the export: text formats are made and written in a worker thread, plot
    /// pictures drawn here and written at once. Reports in the status bar, or in a message box
    /// naming the problem; emits finished() either way.
    void exportFile(const ExportRequest& request);

signals:
    /// An export ended: `problem` is empty when `path` was written.
    void finished(const QString& path, const QString& problem);

private:
    void askExportPlot(PlotKind kind);
    void finishExport(const QString& path, const QString& what, qint64 bytes,
                      const QString& problem);
    /// The project's file name without .cam.json ("untitled" before it has one).
    [[nodiscard]] QString exportBaseName() const;
    /// The project's name, or without one its file's base name: the title of a picture.
    [[nodiscard]] QString exportTitle() const;

    QMainWindow* m_window;
    Ui::MainWindow& m_ui;
    ProjectDocument* m_document;
    const ComputeEngine* m_engine;
    DockLayout& m_views;
    const ResultHub* m_results;
};

}  // namespace cam
