#pragma once
/// @file
/// @brief The main window: the wiring of the document, the engine and the views. What each
/// part does lives in its own class: the docks and views (window/dock_layout), the actions
/// (window/window_actions), the results handed to the views (window/result_hub), the cursor
/// (window/cursor_model), the status labels, Play, Synthesize, recovery and the exports. The
/// accessors below are for the tests, which drive the very same window.

#include <QMainWindow>
#include <memory>

#include "engine/compute_result.h"
#include "export/export_request.h"
#include "files/autosave.h"

class QCustomPlot;

namespace Ui {
class MainWindow;
}

namespace cam {

class SegmentTableModel;
class ComputeEngine;
class ContourView;
class KinematicsPlots;
class JointsPanel;
class PathStudyPanel;
class ControlPointsPanel;
class UserGuide;
class FollowerPanel;
class ForcesPanel;
class MachiningPanel;
class MotionPanel;
class MotionDesignPanel;
class ProjectDocument;
class ProjectFiles;
class StateReadout;
class DockLayout;
class WindowActions;
class ResultHub;
class CursorModel;
class StatusLabels;
class PlayController;
class SynthesisController;
class RecoveryPrompt;
class ExportController;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// @brief Help → About: version, license, the libraries and their versions.
    [[nodiscard]] QString aboutText() const;

    /// @brief Opens a project without asking anything (ProjectFiles::load): a project with
    /// geometric problems opens with them listed; a file that is no project is refused with
    /// the located problems and the open document stays untouched.
    QString loadFile(const QString& path);
    /// @brief Saves to `path` atomically (ProjectFiles::save); returns the problem, or empty.
    QString saveFile(const QString& path);
    /// @brief File → Project Name…: renames the project (trimmed) as one undo step; nothing
    /// when the name is unchanged.
    void renameProject(const QString& name);

    [[nodiscard]] ProjectDocument* document() const { return m_document; }
    [[nodiscard]] ComputeEngine* engine() const { return m_engine; }
    [[nodiscard]] SegmentTableModel* tableModel() const { return m_model; }
    [[nodiscard]] KinematicsPlots* plots() const;
    [[nodiscard]] ContourView* contourView() const;
    [[nodiscard]] StateReadout* readout() const;
    [[nodiscard]] FollowerPanel* followerPanel() const;
    [[nodiscard]] ForcesPanel* forcesPanel() const;
    [[nodiscard]] ControlPointsPanel* controlPointsPanel() const;
    [[nodiscard]] MachiningPanel* machiningPanel() const;
    [[nodiscard]] JointsPanel* jointsPanel() const;
    [[nodiscard]] PathStudyPanel* pathStudyPanel() const;
    [[nodiscard]] MotionDesignPanel* motionDesignPanel() const;
    /// @brief The user guide, once F1 has opened it (else null).
    [[nodiscard]] UserGuide* userGuide() const;
    /// @brief The cursor's instant (s, within the turn).
    [[nodiscard]] double cursorTime() const;
    [[nodiscard]] QAction* playAction() const;
    /// @brief The fraction of the real speed Play turns the cam at.
    [[nodiscard]] double playSpeedFactor() const;
    [[nodiscard]] QAction* synthesizeAction() const;

    [[nodiscard]] Autosave* autosave() const { return m_autosave; }
    [[nodiscard]] ProjectFiles* files() const { return m_files; }
    /// @brief After a crash: offers to restore the newest recovery copy a dead session left
    /// (Restore, Discard, or keep it for later). True when a project was restored.
    bool offerRecovery();
    /// @brief Opens a recovery copy as the project it was (its file, unsaved); the copy goes
    /// once this session's own holds it. Problems are shown; true when restored.
    bool restoreRecovery(const Autosave::Orphan& orphan);

    /// @brief Starts synthesising the contour from the design in a worker (Synthesize, F6);
    /// false when there is no design or a synthesis is running. Its end is reported by
    /// synthesisFinished(); progress with Cancel shows when it takes long.
    bool synthesize();
    /// @brief Cancels a running synthesis.
    void cancelSynthesis();

    /// @brief Replaces arc `row` by Bézier pieces within `maxErrorMm` (one undo step); returns
    /// the problem, or empty on success (the achieved error goes to the status bar).
    QString approximateArc(int row, double maxErrorMm);

    /// @brief Rounds the corner at joint K (between rows K-1 and K) by a tangent arc of radius
    /// rho (one undo step); returns the problem with the feasible range, or empty on success.
    QString roundCorner(int joint, double rho);

    /// @brief Replaces the contour by a closed Bézier spline through the points (x, y per line)
    /// with automatic handles; one undo step. Returns the problem, empty on success.
    QString contourThroughPoints(const QString& pointsText, int rule, double bulge);

    /// @brief Puts the cursor at time t (s): readout, follower ray and plot cursors.
    void setCursorTime(double t);
    /// @brief Puts the cursor at x of the plots' shared axis (degrees or seconds).
    void setCursorAtPlotX(double x);

    /// @brief The widget that draws this plot.
    [[nodiscard]] QCustomPlot* plotWidget(PlotKind kind) const;
    /// @brief The plots that can be drawn now: every plot once a result is shown, the
    /// machining plots only while the Machining panel shows times of a machining section.
    [[nodiscard]] std::vector<PlotKind> drawablePlots() const;
    /// @brief The plot as a picture titled "PROJECT — PLOT" (renderPlotPicture), at `size`
    /// (empty: the plot's size on screen). Empty with `problem` set when it cannot be drawn.
    [[nodiscard]] QByteArray plotPicture(PlotKind kind, PictureFormat format, QSize size,
                                         QString* problem);
    /// @brief Writes the export (File → Export… after its dialog): text formats are made and
    /// written in a worker thread, plot pictures drawn here and written at once. Reports in the
    /// status bar, or in a message box naming the problem; emits exportFinished() either way.
    void exportFile(const ExportRequest& request);
    /// @brief Shows the Machining panel (its plots and times are computed only while shown).
    void showMachiningPanel();

    /// @brief Runs the event loop until the plots show the result of the newest request, with
    /// every plot level.
    bool waitForCurrentResult(int timeoutMs);
    /// @brief The last result that could be computed: what the views draw (null before one).
    [[nodiscard]] const ComputeResultPtr& shownResult() const;

signals:
    /// The plots show this result (emitted after they were updated); a first picture's result
    /// is followed by the same one with its finer plot levels (PlotCurves::partial).
    void resultShown(const cam::ComputeResultPtr& result);
    /// A synthesis ended: `problem` is empty when the contour was replaced (one undo step).
    void synthesisFinished(const QString& problem);
    /// An export ended: `problem` is empty when `path` was written.
    void exportFinished(const QString& path, const QString& problem);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void wireResults();
    void wireCursor();
    void requestCompute();
    void updateTitle();

    std::unique_ptr<Ui::MainWindow> m_ui;
    ProjectDocument* m_document;
    SegmentTableModel* m_model;
    ComputeEngine* m_engine;
    ProjectFiles* m_files = nullptr;
    Autosave* m_autosave = nullptr;
    DockLayout* m_views = nullptr;
    ResultHub* m_results = nullptr;
    CursorModel* m_cursor = nullptr;
    StatusLabels* m_labels = nullptr;
    WindowActions* m_actions = nullptr;
    PlayController* m_play = nullptr;
    SynthesisController* m_synthesis = nullptr;
    RecoveryPrompt* m_recovery = nullptr;
    ExportController* m_exports = nullptr;
};

}  // namespace cam
