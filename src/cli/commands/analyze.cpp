#include "cli/commands.h"

#include <ostream>

#include "analysis/analysis.h"
#include "cli/command_support.h"
#include "cli/result_json.h"
#include "common/angles.h"

namespace cam::cli {

int runAnalyze(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
    const Loaded loaded = load(args.positional.at(0));
    const ContourAnalysis analysis = analyzeContour(loaded.contour, loaded.omega);
    const auto joint = [&analysis](std::size_t k) {
        const JointAnalysis& j = analysis.joints[k];
        return Json{{"joint", j.right},
                    {"left", j.left},
                    {"right", j.right},
                    {"phi_deg", radToDeg(j.phi)},
                    {"continuity", continuityName(j.continuity)},
                    {"c0_gap_mm", j.gapMm},
                    {"tangent_break_deg", j.tangentBreakDeg},
                    {"jump_dr", j.jumpDr},
                    {"jump_d2r", j.jumpD2r},
                    {"jump_d3r", j.jumpD3r},
                    {"jump_a_r", j.jumpAR},
                    {"jump_j_r", j.jumpJR},
                    {"jump_dP_dphi", {j.jumpD1.x(), j.jumpD1.y()}},
                    {"relative_jump_dP_dphi", j.relativeD1},
                    {"jump_d2P_dphi2", {j.jumpD2.x(), j.jumpD2.y()}},
                    {"relative_jump_d2P_dphi2", j.relativeD2},
                    {"geometric", continuityName(j.geometric)},
                    {"curve_jump_d1", {j.curveJumpD1.x(), j.curveJumpD1.y()}},
                    {"curve_relative_jump_d1", j.curveRelativeD1},
                    {"curve_jump_d2", {j.curveJumpD2.x(), j.curveJumpD2.y()}},
                    {"curve_relative_jump_d2", j.curveRelativeD2}};
    };
    Json extremes = Json::object();
    for (const QuantityExtremes& e : analysis.extremes) {
        auto one = [](const Extremum& x) {
            return Json{{"value", x.value}, {"phi_deg", radToDeg(x.phi)}, {"segment", x.segment}};
        };
        extremes[quantityName(e.quantity)] = Json{{"min", one(e.min)}, {"max", one(e.max)}};
    }
    // Where the acceleration jumps the jerk is unbounded: the extremes of j and j_r above are
    // those between joints, and say so.
    Json unbounded = Json::array();
    for (const UnboundedJerk& u : unboundedJerk(analysis.joints, loaded.omega)) {
        unbounded.push_back({{"joint", u.right},
                             {"left", u.left},
                             {"right", u.right},
                             {"phi_deg", radToDeg(u.phi)},
                             {"acceleration_jump", u.accelerationJump}});
    }
    const bool between = !unbounded.empty();
    for (const char* q : {"j", "j_r"}) {
        if (extremes.contains(q)) extremes[q]["between_joints_only"] = between;
    }
    Json result{{"omega_rad_s", loaded.omega},
                {"units", {{"length", "mm"}, {"angle", "deg"}, {"time", "s"}}},
                {"joints", nullptr},  // written one by one: see printJsonWithArray
                {"extremes", std::move(extremes)},
                {"jerk_unbounded_at", std::move(unbounded)},
                {"follower", followerAnalysisJson(loaded)}};
    if (loaded.project.dynamics) result["forces"] = forcesAnalysisJson(loaded);
    // A conjugate pair: its second plate and the play it leaves the second roller.
    if (const auto plate = secondPlate(loaded, args.positional.at(0))) {
        result["follower"]["conjugate"] = conjugateJson(loaded, *plate);
    }
    // The follower's jerk jumps with the contour's acceleration at the same joints.
    for (const char* q : {"j", "jerk_arm"}) {
        if (result["follower"].contains(q)) result["follower"][q]["between_joints_only"] = between;
    }
    printJsonWithArray(out, std::move(result), "joints", analysis.joints.size(), joint);
    return kOk;
}

}  // namespace cam::cli
