#include "cli/result_json.h"

#include <cmath>

#include "common/angles.h"
#include "evaluation/force_evaluation.h"
#include "follower/follower_analysis.h"
#include "project/follower_kind.h"

namespace cam::cli {
namespace {

/// A radius of curvature: null where the curve is straight (an infinite radius).
Json radiusJson(double rho) { return std::isfinite(rho) ? Json(rho) : Json(nullptr); }

const char* motionName(const FollowerModel& model) {
    return model.oscillating() ? "oscillating" : "translating";
}

}  // namespace

Json stateJson(const KinematicState& s) {
    const PolarMotion& m = s.motion;
    return Json{{"t", s.t},
                {"phi_deg", radToDeg(s.phi)},
                {"segment", s.segment},
                {"r", s.polar.r},
                {"v_r", m.vR},
                {"v_phi", m.vPhi},
                {"v", m.v},
                {"a_r", m.aR},
                {"a_phi", m.aPhi},
                {"a", m.a},
                {"j_r", m.jR},
                {"j_phi", m.jPhi},
                {"j", m.j}};
}

Json followerJson(const FollowerModel& model, const FollowerState& f) {
    Json json{{"type", followerKind(model.spec().type).name}, {"motion", motionName(model)}};
    if (model.oscillating()) {
        json.update(Json{{"psi_deg", radToDeg(f.s)},
                         {"lift", model.lift(f)},
                         {"omega_arm", f.v},
                         {"alpha_arm", f.a},
                         {"jerk_arm", f.j}});
    } else {
        json.update(Json{{"s", f.s}, {"lift", model.lift(f)}, {"v", f.v}, {"a", f.a}, {"j", f.j}});
    }
    json.update(Json{{"center", {f.center.x(), f.center.y()}},
                     {"contact", {f.contact.x(), f.contact.y()}},
                     {"pressure_angle_deg", radToDeg(f.pressureAngle)},
                     {"rho_profile", radiusJson(f.rhoProfile)},
                     {"rho_pitch", radiusJson(f.rhoPitch)}});
    return json;
}

Json outerFlankJson(const FollowerModel& inner, const FollowerState& f) {
    Json json = followerJson(inner, f);
    json.erase("type");
    json.erase("motion");
    return json;
}

Json conjugateJson(const Loaded& loaded, const ConjugatePlate& plate) {
    const FollowerSpec& spec = loaded.follower.spec();
    // The plate's tightest arcs, at the cam angle the second roller touches their middle.
    const auto bend = [](const std::optional<RadialExtreme>& b) {
        if (!b) return Json(nullptr);
        return Json{{"value", b->radius},
                    {"phi_deg", radToDeg(b->phi)},
                    {"point", {b->point.x(), b->point.y()}}};
    };
    Json out = spec.motion == FollowerMotion::Oscillating
                   ? Json{{"angle_deg", spec.conjugateAngleDeg},
                          {"arm_length_mm", spec.conjugateArmLength}}
                   : Json{{"distance_mm", spec.conjugateDistance}};
    out.update(Json{{"roller_radius", spec.conjugateRadius},
                    {"tolerance_mm", conjugateTolerance(loaded.project)},
                    {"plate_arcs", plate.fit.arcs.size()},
                    {"max_play_mm", plate.maxPlay},
                    {"max_play_at_deg", radToDeg(plate.maxPlayAt)},
                    {"min_play_mm", plate.minPlay},
                    {"min_play_at_deg", radToDeg(plate.minPlayAt)},
                    {"pressure_angle",
                     {{"max",
                       {{"value_deg", radToDeg(plate.maxPressureAngle)},
                        {"phi_deg", radToDeg(plate.maxPressureAt)}}}}},
                    {"curvature",
                     {{"min_convex", bend(plate.bends.minConvex)},
                      {"min_concave", bend(plate.bends.minConcave)}}}});
    return out;
}

namespace {

/// analyze's `groove` of a grooved cam: the outer flank's checks (its pressure angle and
/// curvature where the roller touches it, pressed outwards) and the lands.
Json grooveAnalysisJson(const Loaded& loaded) {
    const FollowerSpec& spec = loaded.follower.spec();
    const double width = 2.0 * spec.radius + spec.grooveClearance;
    const FollowerAnalysis wide =
        analyzeFollower(*loaded.outerFlank, loaded.omega, loaded.contour.phiBegin(),
                        kFollowerCheckSamples, nullptr, phasesOf(loaded.project));
    // The outer flank's tightest arcs, bending round the cam centre's side and away.
    const PathBends bends = pathBends(loaded.groove->outer);
    const auto bend = [](const std::optional<RadialExtreme>& b) {
        if (!b) return Json(nullptr);
        return Json{{"value", b->radius}, {"phi_deg", radToDeg(b->phi)}};
    };
    const GrooveLands lands =
        grooveLands(*loaded.groove, spec.innerLandRadius, spec.outerLandRadius);
    const auto land = [](const RadialExtreme& at, const std::optional<double>& limit, bool kept) {
        return Json{{"radius", at.radius},
                    {"phi_deg", radToDeg(at.phi)},
                    {"point", {at.point.x(), at.point.y()}},
                    {"land_radius", limit ? Json(*limit) : Json(nullptr)},
                    {"kept", kept}};
    };
    return Json{
        {"roller_radius", spec.radius},
        {"clearance_mm", spec.grooveClearance},
        {"width_mm", width},
        {"outer_flank",
         {{"pressure_angle",
           {{"max",
             {{"value_deg", radToDeg(wide.pressure.max.value)},
              {"phi_deg", radToDeg(wide.pressure.max.phi)}}}}},
          {"curvature",
           {{"min_convex", bend(bends.minConvex)}, {"min_concave", bend(bends.minConcave)}}}}},
        {"lands",
         {{"inner", land(lands.innerMost, lands.innerLand, lands.innerKept())},
          {"outer", land(lands.outerMost, lands.outerLand, lands.outerKept())}}}};
}

}  // namespace

/// cli.md's `follower` object of `analyze`: the design checks of math.md §7.
Json followerAnalysisJson(const Loaded& loaded) {
    const FollowerModel& model = loaded.follower;
    const FollowerAnalysis a =
        analyzeFollower(model, loaded.omega, loaded.contour.phiBegin(), kFollowerCheckSamples,
                        nullptr, phasesOf(loaded.project));
    const auto one = [](const FollowerExtremum& e) {
        return Json{{"value", radiusJson(e.value)}, {"phi_deg", radToDeg(e.phi)}};
    };
    const auto angle = [](const FollowerExtremum& e) {
        return Json{{"value_deg", radToDeg(e.value)}, {"phi_deg", radToDeg(e.phi)}};
    };
    const auto angleOrNull = [&](const std::optional<FollowerExtremum>& e) {
        return e ? angle(*e) : Json(nullptr);
    };
    const auto radiusOrNull = [&](const std::optional<FollowerExtremum>& e) {
        return e ? one(*e) : Json(nullptr);
    };
    const auto curvature = [&](const CurvatureExtremes& c) {
        return Json{{"min_convex", radiusOrNull(c.minConvex)},
                    {"min_concave", radiusOrNull(c.minConcave)}};
    };
    Json exceeded = Json::array();
    for (const AngleRange& r : a.pressureExceeded) {
        exceeded.push_back({{"from_deg", radToDeg(r.from)},
                            {"to_deg", radToDeg(r.to)},
                            {"peak_deg", radToDeg(r.peak.value)},
                            {"peak_phi_deg", radToDeg(r.peak.phi)},
                            {"excess_deg", radToDeg(r.peak.value - a.limitRad)}});
    }
    Json undercut = Json::array();
    for (const NonContact& c : a.undercut) {
        undercut.push_back({{"phi_deg", radToDeg(c.phi)},
                            {"from", {c.from.x(), c.from.y()}},
                            {"to", {c.to.x(), c.to.y()}},
                            {"profile_from_deg", radToDeg(std::atan2(c.from.y(), c.from.x()))},
                            {"profile_to_deg", radToDeg(std::atan2(c.to.y(), c.to.x()))}});
    }
    const bool arm = model.oscillating();
    const auto range = [&](const FollowerExtremum& lo, const FollowerExtremum& hi) {
        return Json{{"min", one(lo)}, {"max", one(hi)}};
    };
    const auto degrees = [](FollowerExtremum e) {
        e.value = radToDeg(e.value);
        return e;
    };
    Json f{{"type", followerKind(model.spec().type).name}, {"motion", motionName(model)}};
    if (arm) {
        f["psi_deg"] = range(degrees(a.sMin), degrees(a.sMax));
        f["lift"] = radToDeg(a.sMax.value - a.sMin.value);
        f["omega_arm"] = range(a.vMin, a.vMax);
        f["alpha_arm"] = range(a.aMin, a.aMax);
        f["jerk_arm"] = range(a.jMin, a.jMax);
    } else {
        f["s"] = range(a.sMin, a.sMax);
        f["lift"] = a.sMax.value - a.sMin.value;
        f["v"] = range(a.vMin, a.vMax);
        f["a"] = range(a.aMin, a.aMax);
        f["j"] = range(a.jMin, a.jMax);
    }
    Json curvatures{{"profile", curvature(a.profileCurvature)},
                    {"pitch", curvature(a.pitchCurvature)}};
    const double toolRadius = loaded.project.machining ? loaded.project.machining->toolRadius : 0.0;
    const CurvatureVerdict verdict = curvatureVerdict(a, model.spec(), toolRadius);
    if (verdict.rollerFits) {
        curvatures["roller_radius"] = model.spec().radius;
        curvatures["roller_fits"] = *verdict.rollerFits;
    }
    if (verdict.toolFits) {
        curvatures["tool_radius"] = toolRadius;
        curvatures["tool_fits"] = *verdict.toolFits;
    }
    f.update(Json{{"pressure_angle",
                   {{"rise", angleOrNull(a.pressure.rise)},
                    {"return", angleOrNull(a.pressure.fall)},
                    {"dwell", angleOrNull(a.pressure.dwell)},
                    {"max", angle(a.pressure.max)},
                    // As given (or the default), not back from radians: 30, not 29.999999999999996.
                    {"limit_deg", model.spec().maxPressureAngleOrDefault()},
                    {"exceeded", std::move(exceeded)}}},
                  {"curvature", std::move(curvatures)},
                  {"undercut", std::move(undercut)}});
    if (followerKind(model.spec().type).flatFace) f["face_width"] = a.faceWidth;
    if (loaded.groove && loaded.outerFlank) f["groove"] = grooveAnalysisJson(loaded);
    return f;
}

namespace {

Json finiteOrNull(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

}  // namespace

Json forcesJson(const ForceModel& model, const ForcePoint& f) {
    Json j = Json::object();
    j[model.swinging ? "moment_Nm" : "axial_N"] = f.load;
    j["normal_N"] = f.normal;
    if (!model.swinging) j["lateral_N"] = f.lateral;
    j["torque_Nm"] = f.torque;
    j["power_W"] = f.power;
    j["contact_stress_MPa"] = finiteOrNull(f.stress);
    j["contact_half_width_mm"] = finiteOrNull(f.halfWidth);
    j["max_shear_stress_MPa"] = finiteOrNull(f.shear);
    return j;
}

Json forcesAnalysisJson(const Loaded& loaded) {
    ForceEvaluation evaluation;
    evaluateForces(loaded.project, loaded.follower, loaded.omega, evaluation);
    const ForceModel& model = evaluation.model;
    const ForceSummary& s = evaluation.summary;
    const std::size_t n = evaluation.turn.size();
    const auto degrees = [](double rad) { return radToDeg(rad); };
    Json liftOff = Json::array();
    for (const auto& [from, to] : s.liftOff) liftOff.push_back({degrees(from), degrees(to)});
    const double rpm = 60.0 / kTwoPi;
    Json j{{"samples", n}};
    if (model.formClosed()) {
        // Form-closed, the follower never leaves the cam: where the load turns negative the
        // roller crosses its clearance and the outer flank carries it, or the second roller of
        // a conjugate pair does; a spring's jump speed and preload mean nothing.
        const bool groove = model.grooved();
        Json crossovers = Json::array();
        for (const auto& [from, to] : s.liftOff) {
            crossovers.push_back({{groove ? "to_outer_deg" : "to_second_deg", degrees(from)},
                                  {groove ? "to_inner_deg" : "to_first_deg", degrees(to)}});
        }
        j[groove ? "outer_flank_carries_deg" : "second_roller_carries_deg"] = std::move(liftOff);
        j["crossovers"] = std::move(crossovers);
        j["jump_speed_rpm"] = nullptr;
        j["jump_speed_at_deg"] = nullptr;
        j[model.swinging ? "min_preload_Nm" : "min_preload_N"] = nullptr;
        j["min_preload_at_deg"] = nullptr;
    } else {
        j["lift_off_deg"] = std::move(liftOff);
        j["jump_speed_rpm"] = finiteOrNull(s.jumpSpeed * rpm);
        j["jump_speed_at_deg"] = std::isfinite(s.jumpSpeed) ? Json(degrees(s.jumpSpeedAt)) : Json();
        j[model.swinging ? "min_preload_Nm" : "min_preload_N"] = s.minPreload;
        j["min_preload_at_deg"] = degrees(s.minPreloadAt);
    }
    j["max_normal_N"] = s.maxNormal;
    j["max_normal_at_deg"] = degrees(s.maxNormalAt);
    j["peak_torque_Nm"] = s.peakTorque;
    j["peak_torque_at_deg"] = degrees(s.peakTorqueAt);
    j["rms_torque_Nm"] = s.rmsTorque;
    j["peak_power_W"] = s.peakPower;
    j["max_contact_stress_MPa"] = s.maxStress ? Json(*s.maxStress) : Json();
    j["max_contact_stress_at_deg"] = s.maxStressAt ? Json(degrees(*s.maxStressAt)) : Json();
    j["allowable_contact_stress_MPa"] = model.allowableMpa ? Json(*model.allowableMpa) : Json();
    // The larger of both contacts' when form-closed.
    const std::optional<double> worst =
        s.maxStressSecond && (!s.maxStress || *s.maxStressSecond > *s.maxStress) ? s.maxStressSecond
                                                                                 : s.maxStress;
    j["contact_stress_ratio"] =
        worst && model.allowableMpa ? Json(*worst / *model.allowableMpa) : Json();
    if (model.formClosed()) {
        const auto orNull = [](const std::optional<double>& v) { return v ? Json(*v) : Json(); };
        const auto atDeg = [&](const std::optional<double>& v) {
            return v ? Json(degrees(*v)) : Json();
        };
        j[model.grooved() ? "outer_flank" : "second_roller"] = {
            {"max_normal_N", orNull(s.maxNormalSecond)},
            {"max_normal_at_deg", atDeg(s.maxNormalSecondAt)},
            {"max_contact_stress_MPa", orNull(s.maxStressSecond)},
            {"max_contact_stress_at_deg", atDeg(s.maxStressSecondAt)}};
    }
    // Where the contact passes a joint and the forces jump: both sides (an arc table's s''
    // jumps at every joint).
    Json jumps = Json::array();
    for (const ForceJump& jump : s.jumps) {
        const auto sides = [](double before, double after) {
            return Json::array({finiteOrNull(before), finiteOrNull(after)});
        };
        jumps.push_back(
            {{"phi_deg", degrees(jump.phi)},
             {model.swinging ? "moment_Nm" : "axial_N", sides(jump.before.load, jump.after.load)},
             {"normal_N", sides(jump.before.normal, jump.after.normal)},
             {"torque_Nm", sides(jump.before.torque, jump.after.torque)},
             {"contact_stress_MPa", sides(jump.before.stress, jump.after.stress)}});
    }
    j["jumps_at_joints"] = std::move(jumps);
    return j;
}

}  // namespace cam::cli
