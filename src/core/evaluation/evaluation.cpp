#include "evaluation/evaluation.h"

#include <cmath>

#include "closure/conjugate.h"
#include "common/angles.h"
#include "design/motion_design.h"
#include "project/validate.h"

namespace cam {

const char* evaluationStatusName(EvaluationStatus status) {
    switch (status) {
        case EvaluationStatus::Computed:
            return "computed";
        case EvaluationStatus::Invalid:
            return "invalid";
        case EvaluationStatus::AwaitsContour:
            return "awaits contour";
        case EvaluationStatus::Failed:
            return "failed";
    }
    return "";
}

std::optional<double> usableOmega(const MotionSpec& motion) {
    // What validateProject accepts, so that a valid project always has its speed.
    const ValueRange range = speedRange(motion.unit);
    if (motion.unit == SpeedUnit::PeriodS && !(motion.value > 0.0)) return std::nullopt;
    if (!(std::abs(motion.value) >= range.lo && std::abs(motion.value) <= range.hi)) {
        return std::nullopt;
    }
    return motion.omegaRadS();
}

Diagnostics documentProblems(const Project& project) {
    Diagnostics problems = validateProject(project);
    Diagnostics design = designProblems(project);
    problems.insert(problems.end(), design.begin(), design.end());
    return problems;
}

ProjectEvaluation evaluateProject(const Project& project) {
    ProjectEvaluation e;
    e.problems = documentProblems(project);
    if (const auto omega = usableOmega(project.motion)) {
        e.omega = *omega;
        e.period = kTwoPi / std::abs(*omega);
    }
    const bool sound = !hasErrors(e.problems);
    if (project.contour.empty()) {
        e.status = sound ? EvaluationStatus::AwaitsContour : EvaluationStatus::Invalid;
        return e;
    }
    // A contour whose only problems are joints that do not meet or its design's is still
    // compiled: the window draws it (r jumps at the open joint) while the designer edits.
    const bool compilable =
        sound || !hasErrors(validateProject(project, ValidationOptions{.checkJoints = false}));
    if (compilable) {
        auto contour = Contour::buildValidated(project);
        if (contour.ok()) e.contour = std::move(contour).value();
    }
    if (e.contour) {
        // A follower that cannot ride this cam (a pivot inside it, an arm that cannot reach it,
        // a roller wider than a concave arc) makes the project invalid.
        const FollowerSpec spec = project.follower.value_or(FollowerSpec{});
        auto follower = FollowerModel::build(*e.contour, spec);
        if (follower.ok()) {
            e.follower = std::make_shared<const FollowerModel>(std::move(follower).value());
        } else {
            e.followerProblems = follower.errors();
        }
        // A groove whose outer flank would fold cannot be milled: the roller cannot run in it.
        if (e.follower && spec.grooved() && spec.type == FollowerType::Roller) {
            auto groove = grooveFlanks(*e.contour, spec.radius, spec.grooveClearance);
            auto wide = FollowerModel::build(*e.contour, outerFlankRoller(spec));
            if (groove.ok() && wide.ok()) {
                e.groove = std::move(groove).value();
                e.outerFlankFollower =
                    std::make_shared<const FollowerModel>(std::move(wide).value());
            } else if (!groove.ok()) {
                e.follower.reset();
                e.followerProblems = groove.errors();
            } else {
                // Pressed on the outer flank, a swinging arm's roller may not reach the cam.
                e.follower.reset();
                e.followerProblems = wide.errors();
            }
        }
        // A conjugate pair whose second roller cannot stand beyond the centre, or whose second
        // plate would fold, cannot be made (the plate itself is fitted by its consumers).
        if (const auto yoke = SecondRoller::of(project); e.follower && yoke) {
            if (Diagnostics problems = conjugateProblems(*e.follower, *yoke); !problems.empty()) {
                e.follower.reset();
                e.followerProblems = std::move(problems);
            }
        }
    }
    // Only once nothing else is wrong: a follower placed on a contour with problems says little.
    if (sound)
        e.problems.insert(e.problems.end(), e.followerProblems.begin(), e.followerProblems.end());
    e.status = hasErrors(e.problems) ? EvaluationStatus::Invalid : EvaluationStatus::Computed;
    return e;
}

Diagnostics projectProblems(const Project& project) { return evaluateProject(project).problems; }

}  // namespace cam
