#pragma once
/// @file
/// @brief The Motion Design dock (math.md §8): the design's segments (law, end angle, lift,
/// poly5's boundary values; every edit an undo command) with each law's Cv, Ca, Cj; base radius
/// and tolerance; the law's lift, velocity, acceleration and jerk over the turn with the
/// follower on the contour drawn over it; and what the last synthesis reported.

#include <QWidget>
#include <array>
#include <functional>

#include "design/sizing.h"
#include "design/synthesis.h"
#include "engine/compute_result.h"

class QAction;
class QCheckBox;
class QCPItemStraightLine;
class QCustomPlot;
class QLabel;
class QPushButton;
class QTableView;
class QToolButton;

namespace cam {

class DesignTableModel;
class FeasibleRegionPlot;
class NumberSpinBox;
class ProjectDocument;

class MotionDesignPanel : public QWidget {
    Q_OBJECT
public:
    explicit MotionDesignPanel(ProjectDocument* document, QWidget* parent = nullptr);

    /// @brief The button under the table triggers this action (the main window's Synthesize).
    void setSynthesizeAction(QAction* action);
    /// @brief Draws the design's curves of a result (the newest, computable or not).
    void setResult(const ComputeResultPtr& result);
    /// @brief What the last synthesis reported (segments, deviation, the price of arcs), for
    /// the project `after` it: the text shows only while the project's contour, design,
    /// follower and speed are that (not after an Undo, an edit, another file; again after Redo).
    void setReport(const SynthesisReport& report, const Project& after);
    /// @brief Moves the plots' cursor line to x (degrees or seconds).
    void setCursorX(double x);

    [[nodiscard]] DesignTableModel* model() const { return m_model; }
    [[nodiscard]] QTableView* table() const { return m_table; }
    /// Lift, velocity, acceleration, jerk.
    [[nodiscard]] QCustomPlot* plot(int i) const { return m_plots[static_cast<std::size_t>(i)]; }
    [[nodiscard]] QString reportText() const;
    [[nodiscard]] QString notesText() const;

    /// @brief Starts a design: the cycloidal dwell–rise–dwell–return of math.md §8 (one undo
    /// step); replaces nothing when there is one.
    void newDesign();
    /// @brief Splits segment `row` at its middle angle: the first half keeps the law and the
    /// end lift, the second half dwells there (one undo step).
    void splitSegment(int row);
    /// @brief Deletes segment `row`; the segment before it (the next for the first) takes over
    /// its stretch and end lift (one undo step). The last segment cannot be deleted.
    void deleteSegment(int row);
    /// @brief Suggest: the recommended law for segment `row`, or for every segment that is not a
    /// dwell or a line when row < 0, from the boundary classes its neighbours demand
    /// (design/boundary_classes.h suggestLaws; one undo step). The status line says what
    /// changed.
    void suggestLaw(int row);
    /// @brief Makes segment `row` a motion table with the points of `text` (two or three
    /// columns, x and y from 0 to 1: design/motion_table.h parseMotionTable; one undo step).
    /// Returns the message of text it cannot read (empty when it took it).
    QString importTable(int row, const QString& text);
    /// @brief Finds the smallest base radius that passes every check (design/sizing.h) in the
    /// background and sets it (one undo step), unless the design or the follower changed
    /// meanwhile; the panel's sizing line says which check binds, or why none passes.
    void sizeBaseRadius();
    /// @brief Finds the offset of a translating knife or roller, or the pivot distance of a
    /// swinging arm, that allows the smallest base radius (design/sizing.h sizePlacement) in
    /// the background, sets both (one undo step) unless the design or the follower changed
    /// meanwhile, and draws the feasible region.
    void sizePlacement();
    /// @brief The feasible region over base radius × offset or pivot distance (hidden before
    /// the first sizePlacement).
    [[nodiscard]] FeasibleRegionPlot* feasibleRegion() const { return m_region; }
    /// @brief The sizing line under the base radius ("" before the first sizing).
    [[nodiscard]] QString sizingText() const;
    /// @brief Whether a sizing runs now.
    [[nodiscard]] bool sizing() const { return m_sizingRuns; }

signals:
    /// @brief A sizing finished (applied, refused, or dropped as stale).
    void sizingFinished();

private:
    void refresh();
    /// Shows only what describes the project as it is: the synthesis report and the sizing
    /// line (each holds for the project it was made for) and the feasible region (holds while
    /// the design's laws and the follower are the same but for base radius and placement; its
    /// design marker follows the project).
    void dropStaleTexts();
    /// Smallest and Best Offset (Best Pivot for an arm) are on while there is a design (Best
    /// Offset: for a follower whose offset matters) and no sizing runs.
    void updateSizingButtons();
    /// "The design changed while it was sized: try again." (outside the template, where
    /// lupdate finds its context).
    [[nodiscard]] static QString staleSizingText();
    [[nodiscard]] static QString synthesizeHint();
    [[nodiscard]] static QString noDesignText();
    /// Runs `job` on a snapshot of the design and follower in the background; `apply` takes
    /// its answer if they are still what was sized, else the sizing line says why not.
    template <class Answer>
    void runSizing(
        const QString& busy, Result<Answer> (*job)(const DesignSpec&, const FollowerSpec&),
        const std::function<void(const Answer&, const DesignSpec&, const FollowerSpec&)>& apply);
    void editDesign(const std::function<void(DesignSpec&)>& change, const QString& text,
                    int gesture);
    [[nodiscard]] int currentRow() const;

    ProjectDocument* m_document;
    DesignTableModel* m_model;
    QPushButton* m_newDesign;
    QPushButton* m_removeDesign;
    NumberSpinBox* m_baseRadius;
    QPushButton* m_size;
    QPushButton* m_bestPlacement;  ///< Best Offset or Best Pivot
    QLabel* m_sizing;
    FeasibleRegionPlot* m_region;
    bool m_sizingRuns = false;
    NumberSpinBox* m_tolerance;
    QCheckBox* m_strict;
    QTableView* m_table;
    QPushButton* m_split;
    QPushButton* m_delete;
    QPushButton* m_suggest;
    QPushButton* m_suggestAll;
    QPushButton* m_importTable;
    QLabel* m_suggestion;
    QToolButton* m_synthesize;
    QLabel* m_report;
    QLabel* m_notes;
    QWidget* m_plotArea;
    std::array<QCustomPlot*, 4> m_plots{};
    std::array<QCPItemStraightLine*, 4> m_cursors{};
    std::vector<QCPItemStraightLine*> m_joints;
    QString m_reportText;
    /// The project the synthesis report and the sizing line were made for (the part that
    /// matters to each).
    struct Basis {
        std::vector<SegmentSpec> contour;
        std::optional<DesignSpec> design;
        std::optional<FollowerSpec> follower;
        MotionSpec motion;
        QString text;  ///< what it says (not compared)
        friend bool operator==(const Basis& a, const Basis& b) {
            return a.contour == b.contour && a.design == b.design && a.follower == b.follower &&
                   a.motion == b.motion;
        }
    };
    std::optional<Basis> m_reportFor;
    std::optional<Basis> m_sizingFor;
    std::optional<Basis> m_regionFor;  ///< its base radius and placement are the axes
    Placement m_regionPlacement = Placement::Offset;
    int m_gesture = 0;
    bool m_refreshing = false;
    bool m_fitted = false;
};

}  // namespace cam
