#pragma once
/// @file
/// @brief What the compute engine hands back: immutable, shared, plain data (no plotting
/// library types). What a view needs beyond that it prepares itself in the worker thread,
/// through a PlotDataPreparer (plot_data_preparer.h).

#include <QMetaType>
#include <QPointF>
#include <QVector>
#include <array>
#include <atomic>
#include <memory>
#include <optional>

#include "analysis/analysis.h"
#include "closure/conjugate.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "engine/plot_levels.h"
#include "evaluation/design_curves.h"
#include "evaluation/evaluation.h"
#include "evaluation/force_evaluation.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"
#include "kinematics/kinematics.h"
#include "project/project.h"
#include "spline/path_study.h"
#include "timing/machining_time.h"

namespace cam {

class PlotDataPreparer;

/// @brief Opaque data a view derived from a result in the worker thread, ready to draw (for
/// instance the plotting library's containers). The engine only carries it.
class PreparedPlotData {
public:
    virtual ~PreparedPlotData() = default;
};
using PreparedPlotDataPtr = std::shared_ptr<const PreparedPlotData>;

struct ComputeRequest {
    std::uint64_t generation = 0;
    std::shared_ptr<const Project> project;
    PlotAxis axis = PlotAxis::Angle;
    bool timing = false;  ///< also compute the machining times (when the panel is shown)
    TimingMethod plotMethod = TimingMethod::Optimal;
    /// With a value > 0 the result is a first picture: the plot levels stop at this many
    /// buckets (see buildPlotCurves) and the follower's design checks are left out;
    /// refineResult() adds both. 0: everything at once.
    std::size_t firstPictureBuckets = 0;
};

/// @brief The project's motion design over the turn (evaluation/design_curves.h), on the plots'
/// x axis.
struct DesignCurves : DesignEvaluation {
    /// The design's segment ends (to_deg) on the plots' x axis.
    std::vector<double> jointsX;
    /// kFollowerCurvePoints + 1 equal time steps, as followerX.
    std::vector<double> x;
    /// Per quantity, the smallest and largest value of law and onContour together (jerk: the
    /// law's only).
    std::array<PlotRange, 4> yRanges{};
};

/// @brief The forces of the project's dynamics (evaluation/force_evaluation.h): the summary
/// `camwright-cli analyze` reports, and the curves the Forces dock plots.
struct ForceCurves {
    ForceModel model;
    ForceSummary summary;
    std::size_t samples = 0;  ///< of the turn the summary was found on (the project's)
    /// Load, normal force, torque and stress at kFollowerCurvePoints + 1 equal time steps, on
    /// followerX (the last closes the turn).
    ForceTurn curves;
    /// Where the contact that carries the load lies at the same steps (mm, the cam's frame):
    /// the contour view colours the profile by the stress there. Form-closed, where the load
    /// is negative, that is the second contact: a groove's outer flank (ρ across the roller),
    /// a conjugate pair's second plate.
    std::vector<double> contactX, contactY;
};

/// @brief A grooved cam (closure/groove.h): its flanks, their checks, and the outer flank and
/// the roller's pitch curve as the contour view draws them (x, y in mm, closed).
struct GrooveView {
    GrooveFlanks flanks;
    GrooveLands lands;
    PathBends outerBends;
    QVector<QPointF> outer, pitch;
};

/// @brief A conjugate pair's second plate (closure/conjugate.h), fitted in the worker, and its
/// outline as the contour view draws it (x, y in mm, closed).
struct ConjugateView {
    SecondRoller yoke;
    double toleranceMm = 0.0;  ///< what the plate was fitted within
    ConjugatePlate plate;
    QVector<QPointF> outline;
};

/// @brief One finished computation. Never modified after it leaves the worker.
struct ComputeResult {
    std::uint64_t generation = 0;
    std::shared_ptr<const Project> project;
    PlotAxis axis = PlotAxis::Angle;
    /// The verdict on the project (evaluation/evaluation.h): Failed when the computation itself
    /// failed (e.g. out of memory).
    EvaluationStatus status = EvaluationStatus::Invalid;
    /// Every problem of the project, as the document and the CLI report them.
    Diagnostics problems;
    /// Non-empty: nothing was computed — the contour cannot be compiled, it awaits its first
    /// synthesis, or the computation failed; the views mark what they still show as out of
    /// date. (An invalid project whose contour compiles — an open joint, a follower that
    /// cannot ride it — is still computed: the contour view draws it and the Joints tab lists
    /// its joints while the designer edits, but the plots show it as not computed, see
    /// valid().)
    Diagnostics errors;
    std::optional<Contour> contour;
    double omega = 0.0;           ///< rad/s
    double period = 0.0;          ///< s
    std::size_t sampleCount = 0;  ///< samples per turn that were computed (in chunks)
    /// The joints, as the Joints tab and the plots' joint markers show them. (The window shows
    /// no extremes: their search cost 4 ms of every edit; `camwright-cli analyze` reports them.)
    std::vector<JointAnalysis> joints;
    /// Per segment, its outline for the contour view (x, y in mm), ends included.
    std::vector<QVector<QPointF>> outlines;
    /// A grooved cam's flanks (null for a spring-closed cam, or one whose groove cannot be
    /// made: then `problems` says why).
    std::shared_ptr<const GrooveView> groove;
    /// A conjugate pair's second plate (null for another closure, while the design checks are
    /// pending — see followerChecksPending — or when it cannot be fitted: then `conjugateErrors`
    /// says why, e.g. a tolerance no arcs meet).
    std::shared_ptr<const ConjugateView> conjugate;
    Diagnostics conjugateErrors;
    /// The kinematics curves over angle or time at several resolutions, with their ranges.
    PlotCurves curves;
    double computeMs = 0.0;
    /// The path study of the contour's spline segments, in contour order (empty: none).
    PathStudy pathStudy;
    /// The project's follower on the contour (null when the project names none, or when it
    /// cannot ride this contour: then followerErrors says why), and its design checks.
    std::shared_ptr<const FollowerModel> follower;
    Diagnostics followerErrors;
    FollowerAnalysis followerChecks;
    /// The design checks (and a conjugate pair's second plate) are not computed yet (a first
    /// picture: a swinging arm's take longer than the kinematics); refineResult() adds them.
    bool followerChecksPending = false;
    /// The pressure angle (deg) over the turn at kFollowerCurvePoints + 1 equal time steps, on
    /// the plots' x axis (degrees or seconds, as `curves`).
    std::vector<double> followerX, followerPressureDeg;
    /// The signed radii of curvature (mm, positive where convex, +∞ where straight) of the
    /// profile at the contact and of the pitch curve, at the same steps.
    std::vector<double> followerRhoProfile, followerRhoPitch;
    /// The follower's lift, velocity, acceleration and jerk at the same steps, in the lift's
    /// unit and sense (FollowerModel::liftMotion: mm, or degrees swung away from the cam; per
    /// s, s², s³), and each one's smallest and largest value.
    std::array<std::vector<double>, 4> followerMotion;
    std::array<PlotRange, 4> followerMotionRanges{};
    /// Where on the plots' x axis the contact passes from one segment to the next (halfway
    /// between the two steps), and the left segment of that joint (JointAnalysis::left).
    std::vector<double> followerJointX;
    std::vector<std::size_t> followerJointLeft;
    static constexpr std::size_t kFollowerCurvePoints = 3600;
    /// The forces of the project's `dynamics` on its follower (null without dynamics, or
    /// without a follower that rides the cam).
    std::shared_ptr<const ForceCurves> forces;
    /// The motion design's curves (null when the project has no design). Computed also when
    /// the contour is not (a design waiting for its first synthesis).
    std::shared_ptr<const DesignCurves> design;
    /// What the views' preparer made of this result (null without a preparer).
    PreparedPlotDataPtr prepared;

    [[nodiscard]] bool ok() const { return errors.empty() && contour.has_value(); }
    /// @brief Computed and the project valid: what the plots may draw as the project's motion.
    /// A computed project with problems (status Invalid) is not: nothing is exported from it,
    /// so no plot may show its curves as if they were the cam's.
    [[nodiscard]] bool valid() const { return ok() && status == EvaluationStatus::Computed; }
    /// @brief Why the plots do not show this result: its errors, else its problems that are
    /// errors (notes are not reasons); empty for a valid result.
    [[nodiscard]] Diagnostics reasonsNotShown() const;
    /// @brief Nothing of it is left for refineResult(): every plot level, every check.
    [[nodiscard]] bool complete() const { return !curves.partial && !followerChecksPending; }
    /// @brief A design whose contour was never synthesised: nothing to draw but the design.
    [[nodiscard]] bool awaitsContour() const { return status == EvaluationStatus::AwaitsContour; }
    /// @brief The computation itself failed (e.g. out of memory).
    [[nodiscard]] bool failed() const { return status == EvaluationStatus::Failed; }
};

using ComputeResultPtr = std::shared_ptr<const ComputeResult>;

/// @brief The machining times of one request: computed after its kinematics, reported apart so
/// the plots never wait for them.
struct TimingOutcome {
    std::uint64_t generation = 0;
    Diagnostics errors;  ///< non-empty: no tool path (e.g. the tool is wider than a notch)
    std::array<double, 3> timesS{};  ///< seed, exact stop, optimal
    /// Per method: whether the planner's refinement reached its tolerance (the seed always
    /// does), and the estimated relative error of its time (TimingResult).
    std::array<bool, 3> converged{true, true, true};
    std::array<double, 3> convergence{};
    std::size_t gridPoints = 0;  ///< of the optimal plan
    double lengthMm = 0.0;
    TimingMethod plotted = TimingMethod::Optimal;
    MachineLimits limits;
    /// Feed (mm/s) and per-axis acceleration (mm/s²) over the path length (mm).
    TimingProfile profile;
    double computeMs = 0.0;
    /// What the views' preparer made of this outcome (null without a preparer).
    PreparedPlotDataPtr prepared;
};
using TimingOutcomePtr = std::shared_ptr<const TimingOutcome>;

/// @brief Tool path, the three times and the profile of the plotted method. Null if cancelled.
TimingOutcomePtr computeTiming(const ComputeRequest& request, const Contour& contour,
                               const std::atomic<bool>& cancel);

/// @brief Does the whole computation for one request; polls `cancel`. Returns null if
/// cancelled. With a preparer, its data for the views is made here too (in the caller's
/// thread, the worker's).
ComputeResultPtr computeProject(const ComputeRequest& request, const std::atomic<bool>& cancel,
                                const PlotDataPreparer* preparer = nullptr);

/// @brief The first picture's result with every plot level (and the views' data for them) and
/// the follower's design checks: the same result otherwise. Null if cancelled, or if `first`
/// is complete already.
ComputeResultPtr refineResult(const ComputeResult& first, const std::atomic<bool>& cancel,
                              const PlotDataPreparer* preparer = nullptr);

/// @brief A result that says the computation failed and why (the message is shown as is).
ComputeResultPtr failedResult(const ComputeRequest& request, const std::string& message);

}  // namespace cam

Q_DECLARE_METATYPE(cam::ComputeResultPtr)
Q_DECLARE_METATYPE(cam::TimingOutcomePtr)
