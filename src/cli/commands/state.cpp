#include "cli/commands.h"

#include <cmath>
#include <ostream>

#include "cli/command_support.h"
#include "cli/result_json.h"
#include "common/angles.h"

namespace cam::cli {
namespace {

/// Beyond 1e15 turns one rounding of t/T moves the angle by more than a tenth of a turn: the
/// instant no longer names a cam angle.
constexpr double kMaxTurns = 1e15;

}  // namespace

int runState(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
    const auto tText = args.option("--t");
    if (!tText) throw CliError{kUsage, "--t", "is required (the time in seconds)"};
    const double t = parseFiniteNumber("--t", *tText, "seconds");
    const Loaded loaded = load(args.positional.at(0));
    if (!(std::abs(turnsAt(loaded.project.motion, t)) <= kMaxTurns)) {
        throw CliError{kInvalidInput, "--t",
                       "must be within " + formatNumber(kMaxTurns) + " turns of 0 (got " +
                           formatNumber(t) + " s, " +
                           formatNumber(turnsAt(loaded.project.motion, t)) +
                           " turns): beyond that a double no longer resolves the cam angle"};
    }
    Json state = stateJson(stateAt(loaded.contour, loaded.project.motion, t));
    // The follower (math.md §7), at the same exactly reduced angle; the seed's knife edge on
    // the radial line when the project names none.
    const FollowerModel& follower = loaded.follower;
    const double turns = turnsAt(loaded.project.motion, t);
    const double reduced = kTwoPi * (turns - std::floor(turns));
    const FollowerState at = follower.at(reduced, loaded.omega);
    state["follower"] = followerJson(follower, at);
    // A grooved cam: the roller pressed against the outer flank instead, at the same angle.
    if (loaded.outerFlank) {
        const FollowerSpec& spec = follower.spec();
        state["follower"]["outer_flank"] =
            outerFlankJson(follower, onOuterFlank(loaded.outerFlank->at(reduced, loaded.omega),
                                                  spec.radius, spec.grooveClearance));
    }
    // A conjugate pair: the second roller on the second plate (exact, not the fitted arcs).
    if (const auto yoke = SecondRoller::of(loaded.project)) {
        const ConjugatePoint p = conjugatePoint(follower, *yoke, reduced);
        state["follower"]["second_roller"] = {
            {"center", {p.centre.x(), p.centre.y()}},
            {"contact", {p.plate.x(), p.plate.y()}},
            {"pressure_angle_deg", radToDeg(p.pressureAngle)},
            {"rho_plate", std::isfinite(p.rhoPlate) ? Json(p.rhoPlate) : Json(nullptr)}};
    }
    // With dynamics, the forces there (math.md §9).
    if (loaded.project.dynamics) {
        const ForceModel model = ForceModel::of(*loaded.project.dynamics, follower.spec());
        state["forces"] =
            forcesJson(model, forceAt(model, forceMotion(follower, at), loaded.omega));
    }
    printJson(out, state);
    return kOk;
}

}  // namespace cam::cli
