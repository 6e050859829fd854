#pragma once
/// @file
/// @brief One evaluation of a project, the only place that decides whether a project is valid:
/// the window's document, its compute engine and every CLI command ask it, so they all give the
/// same verdict and the same problems (docs/architecture.md, "One evaluation").
///
/// evaluateProject() is the verdict and what every consumer needs (the contour, the follower
/// placed on it, the speed); the heavier parts the engine runs beside each other on its pool
/// and the CLI runs as it needs them: evaluateDesign() (design_curves.h), analyzeJoints()
/// (analysis.h), analyzeFollower() and sampleFollowerTurn() (follower/).

#include <memory>
#include <optional>

#include "closure/groove.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "follower/follower.h"
#include "project/project.h"

namespace cam {

enum class EvaluationStatus {
    /// Valid: the contour is built and the follower rides it.
    Computed,
    /// The project has problems (`problems`, each located). The contour may still be built
    /// (joints that do not meet, a design with problems, a follower that cannot ride it): the
    /// window draws it while the designer edits; nothing is exported from it.
    Invalid,
    /// Valid, but a motion design whose contour was never synthesised: there is nothing to
    /// compute but the design's own curves.
    AwaitsContour,
    /// The computation itself failed (out of memory, say); `problems` holds why. Only the
    /// engine, which catches what the core throws, reports it.
    Failed,
};

/// @brief The stable English name of a status ("computed", "invalid", "awaits contour",
/// "failed"), for test output and logs.
[[nodiscard]] const char* evaluationStatusName(EvaluationStatus status);

/// @brief The verdict on a project and what follows from the project alone.
struct ProjectEvaluation {
    EvaluationStatus status = EvaluationStatus::Invalid;
    /// Every problem that makes the project invalid (documentProblems', then, when those leave
    /// none, why the follower cannot ride the cam), in that order; informational notes of
    /// validateProject too. Empty for Computed and AwaitsContour unless notes.
    Diagnostics problems;
    /// The compiled contour; empty when there are no segments or they cannot be compiled. (The
    /// follower model does not refer to it: the contour can be moved elsewhere.)
    std::optional<Contour> contour;
    /// The project's follower (a radial knife when it names none) placed on the contour; null
    /// without a contour or when it cannot ride it (then `followerProblems` says why).
    std::shared_ptr<const FollowerModel> follower;
    Diagnostics followerProblems;
    /// A grooved cam's flanks (closure/groove.h), with the follower; a groove that cannot be
    /// milled (its outer flank folds) is one of `followerProblems`.
    std::optional<GrooveFlanks> groove;
    /// With a groove: the roller pressed against its outer flank (outerFlankRoller, placed
    /// like `follower`; onOuterFlank turns its states into the outer flank's contacts).
    std::shared_ptr<const FollowerModel> outerFlankFollower;
    /// The cam's speed (rad/s, signed) and the time of one turn (s); 0 while the project's
    /// motion gives none a computation can use.
    double omega = 0.0;
    double period = 0.0;

    [[nodiscard]] bool valid() const {
        return status == EvaluationStatus::Computed || status == EvaluationStatus::AwaitsContour;
    }
};

/// @brief Validates the project, compiles its contour and places its follower on it.
[[nodiscard]] ProjectEvaluation evaluateProject(const Project& project);

/// @brief Every problem of the document itself: validateProject's, then its motion design's
/// (designProblems). What evaluateProject adds is whether the follower rides the contour.
[[nodiscard]] Diagnostics documentProblems(const Project& project);

/// @brief evaluateProject(project).problems: what a document lists and refuses to export.
[[nodiscard]] Diagnostics projectProblems(const Project& project);

/// @brief The project's speed (rad/s) when validateProject accepts it (finite, non-zero, within
/// the range of its unit), also when the rest of the project has problems.
[[nodiscard]] std::optional<double> usableOmega(const MotionSpec& motion);

}  // namespace cam
