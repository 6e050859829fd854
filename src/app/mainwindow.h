#pragma once
/// @file
/// @brief The main window: actions, docks and wiring. Views draw; the engine computes.

#include <QElapsedTimer>
#include <QMainWindow>
#include <QTimer>
#include <memory>

#include "design/synthesis.h"
#include "engine/compute_result.h"
#include "export/export_request.h"
#include "files/autosave.h"

class QCustomPlot;
class QComboBox;
class QLabel;
class QProgressDialog;

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
class MachiningPanel;
class MotionPanel;
class MotionDesignPanel;
class SynthesisRunner;
class ProjectDocument;
class ProjectFiles;
struct EditOutcome;
class StateReadout;

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
    [[nodiscard]] KinematicsPlots* plots() const { return m_plots; }
    [[nodiscard]] ContourView* contourView() const { return m_contour; }
    [[nodiscard]] StateReadout* readout() const { return m_readout; }
    [[nodiscard]] FollowerPanel* followerPanel() const { return m_follower; }
    [[nodiscard]] ControlPointsPanel* controlPointsPanel() const { return m_controlPoints; }
    /// @brief The user guide, once F1 has opened it (else null).
    [[nodiscard]] UserGuide* userGuide() const { return m_guide; }
    /// @brief The cursor's instant (s, within the turn).
    [[nodiscard]] double cursorTime() const { return m_cursorT; }
    [[nodiscard]] QAction* playAction() const { return m_playAction; }
    /// @brief The fraction of the real speed Play turns the cam at.
    [[nodiscard]] double playSpeedFactor() const;
    [[nodiscard]] MachiningPanel* machiningPanel() const { return m_machining; }
    [[nodiscard]] JointsPanel* jointsPanel() const { return m_joints; }
    [[nodiscard]] PathStudyPanel* pathStudyPanel() const { return m_pathStudy; }
    [[nodiscard]] MotionDesignPanel* motionDesignPanel() const { return m_design; }
    [[nodiscard]] QAction* synthesizeAction() const { return m_synthesizeAction; }

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
    [[nodiscard]] const ComputeResultPtr& shownResult() const { return m_shown; }

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
    void setUpActions();
    /// File → Export… and right-click → Export Plot… on every plot.
    void setUpExports();
    void askExportPlot(PlotKind kind);
    void finishExport(const QString& path, const QString& what, qint64 bytes,
                      const QString& problem);
    /// The project's file name without .cam.json ("untitled" before it has one).
    [[nodiscard]] QString exportBaseName() const;
    /// The project's name, or without one its file's base name: the title of a picture.
    [[nodiscard]] QString exportTitle() const;
    void setUpDocks();
    /// Shows what a contour edit did (status bar, selection) or why not (a message box titled
    /// `title`; none when empty).
    void report(const EditOutcome& outcome, const QString& title = {});
    void requestCompute();
    void showResult(const ComputeResultPtr& result);
    /// The views beside the plots: contour, Joints tab, path study, motion design.
    void showBesidePlots(const ComputeResultPtr& result);
    void updateStatus();
    void updateTitle();
    int selectedRow() const;

    std::unique_ptr<Ui::MainWindow> m_ui;
    ProjectDocument* m_document;
    ProjectFiles* m_files = nullptr;
    SegmentTableModel* m_model;
    ComputeEngine* m_engine;
    ContourView* m_contour;
    KinematicsPlots* m_plots;
    StateReadout* m_readout;
    MotionPanel* m_motion;
    MachiningPanel* m_machining;
    FollowerPanel* m_follower;
    QDockWidget* m_followerDock;
    JointsPanel* m_joints;
    ControlPointsPanel* m_controlPoints;
    QDockWidget* m_controlPointsDock;
    PathStudyPanel* m_pathStudy;
    QLabel* m_validationLabel;
    QLabel* m_computeLabel;
    /// Fires when a request has waited kBusyAfterMs without its result: the label then says
    /// "computing…" instead of describing a result of the project as it was.
    QTimer* m_busyTimer;
    /// Play: turns the cam at a fraction of its real speed, the cursor (and the follower on
    /// the contour) moving with it; only markers move, nothing is computed.
    QAction* m_playAction = nullptr;
    int m_pickRow = -1;
    UserGuide* m_guide = nullptr;  ///< made when first asked for  ///< the row a tangent arc
                                   ///< continues, while a point is being picked
    QComboBox* m_playSpeed = nullptr;
    QTimer* m_playTimer = nullptr;
    QElapsedTimer m_playClock;
    void setUpPlay();
    void setUpDesign();
    /// Icons of every action and dock toggle; every tooltip names its shortcut.
    void setUpIcons();
    void setUpWhatsThis();
    /// @brief Sizes the Segments dock (and its tabs) to the contour's rows, at least
    /// kMinSegmentRowsShown, when a project is opened or made: a short contour leaves the
    /// plots the room it does not need; a long one gets back the height the dock had.
    void fitSegmentsDock();
    static constexpr int kMinSegmentRowsShown = 4;
    int m_segmentsDockRoom = 0;     ///< the dock's height before fitting (layout or user)
    int m_segmentsDockFitted = -1;  ///< its height after the last fit
    void finishSynthesis(const std::shared_ptr<const Result<Synthesis>>& result, bool cancelled);
    Autosave* m_autosave = nullptr;
    MotionDesignPanel* m_design = nullptr;
    QDockWidget* m_designDock = nullptr;
    QAction* m_synthesizeAction = nullptr;
    SynthesisRunner* m_synthesis = nullptr;
    QProgressDialog* m_synthesisProgress = nullptr;
    QElapsedTimer m_synthesisClock;
    bool m_synthesisInteractive = false;
    double m_cursorT = 0.0;
    ComputeResultPtr m_shown;  ///< the last result that could be computed: what the views draw
    /// The request of the last result handed to the views (computable or not; its refinement
    /// has the same).
    std::uint64_t m_handedGeneration = 0;
};

}  // namespace cam
