#pragma once
/// @file
/// @brief The window's views and docks, made and arranged once: the contour and the plots in
/// the middle, which dock holds which panel, which are tabbed together, their shortcuts and
/// What's This texts, the layout the user left (restored at start, saved at close), and the
/// Segments dock fitted to a short contour.

#include <QHash>
#include <QObject>
#include <vector>

class QCustomPlot;
class QDockWidget;
class QMainWindow;

namespace Ui {
class MainWindow;
}

namespace cam {

class ContourView;
class ControlPointsPanel;
class FollowerPanel;
class ForcesPanel;
class JointsPanel;
class KinematicsPlots;
class MachiningPanel;
class MotionDesignPanel;
class MotionPanel;
class PathStudyPanel;
class ProjectDocument;
class SegmentTableModel;
class StateReadout;

class DockLayout : public QObject {
    Q_OBJECT
public:
    DockLayout(QMainWindow* window, Ui::MainWindow& ui, ProjectDocument* document,
               SegmentTableModel* model);

    /// @brief Hides the docks a new user does not need yet, tabs the right-hand ones together
    /// and restores the layout the user left.
    void restore();
    /// @brief Remembers the layout (at close).
    void save() const;
    /// @brief Sizes the Segments dock (and its tabs) to the contour's rows, at least
    /// kMinSegmentRowsShown, when a project is opened or made: a short contour leaves the
    /// plots the room it does not need; a long one gets back the height the dock had.
    void fitSegmentsDock();
    /// @brief The docks' plots over the turn (the follower's and the forces'), which share the
    /// kinematics plots' x axis and move the cursor.
    [[nodiscard]] std::vector<QCustomPlot*> turnPlots() const;

    // The views, for the window's wiring (nobody else keeps them).
    ContourView* contour;
    KinematicsPlots* plots;
    StateReadout* readout;
    MotionPanel* motion;
    MachiningPanel* machining;
    FollowerPanel* follower;
    QDockWidget* followerDock;
    ForcesPanel* forces;
    QDockWidget* forcesDock;
    JointsPanel* joints;
    ControlPointsPanel* controlPoints;
    QDockWidget* controlPointsDock;
    PathStudyPanel* pathStudy;
    MotionDesignPanel* design;
    QDockWidget* designDock;

protected:
    /// The docks' resizes (see giveDocksTheirWidthsBack).
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void makeCentre();
    void makeBottomDocks();
    void makeRightDocks();
    void linkFollowerAxes();
    void setWhatsThis();
    /// A project that names a follower or has a design opens with its dock shown.
    void showWhatTheProjectHas();
    /// The side docks' widths as the user left them (a separator drag, a dock opened or
    /// widened for a project: any change the window's own resizing did not make) come back
    /// when the window grows again: shrunk and grown, QMainWindow gave all the room to the
    /// centre and the right dock stayed clipped (issue 31).
    void giveDocksTheirWidthsBack();

    static constexpr int kMinSegmentRowsShown = 4;
    QMainWindow* m_window;
    Ui::MainWindow& m_ui;
    ProjectDocument* m_document;
    SegmentTableModel* m_model;
    int m_dockWidths[2] = {0, 0};          ///< left, right: the width the user chose (0: none yet)
    QHash<QObject*, int> m_windowWidthAt;  ///< each dock: the window's width at its last resize
    bool m_givingWidthsBack = false;
    int m_segmentsDockRoom = 0;     ///< the dock's height before fitting (layout or user)
    int m_segmentsDockFitted = -1;  ///< its height after the last fit
};

}  // namespace cam
