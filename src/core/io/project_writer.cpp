#include "io/project_writer.h"

#include <charconv>
#include <cmath>
#include <cstdint>

#include "design/motion_law.h"
#include "io/json_syntax.h"
#include "io/project_json.h"
#include "io/project_reader.h"
#include "project/dynamics.h"
#include "project/follower_kind.h"

namespace cam {

double fileValue(double internal, double factor) {
    if (factor == 1.0 || !std::isfinite(internal)) return internal;
    const double guess = internal / factor;
    char buffer[40];
    for (int digits = 1; digits <= 17; ++digits) {
        const auto written = std::to_chars(buffer, buffer + sizeof buffer, guess,
                                           std::chars_format::general, digits);
        double candidate = 0.0;
        std::from_chars(buffer, written.ptr, candidate);
        if (candidate * factor == internal) return candidate;
    }
    // No decimal of up to 17 digits near the quotient maps back exactly: try its neighbours.
    for (double candidate : {std::nextafter(guess, -INFINITY), std::nextafter(guess, INFINITY)}) {
        if (candidate * factor == internal) return candidate;
    }
    return guess;
}

namespace {

/// Every number of the tree that is a whole number written as one ("rpm": 60, not 60.0, as
/// the user typed it; "center": [25.7, 0]). Reading gives the same double back: |v| < 2^53.
void wholeNumbersAsIntegers(Json& j) {
    if (j.is_number_float()) {
        const double v = j.get<double>();
        if (std::isfinite(v) && v == std::trunc(v) && std::abs(v) < 9007199254740992.0) {
            j = static_cast<std::int64_t>(v);
        }
    } else if (j.is_structured()) {
        for (Json& child : j) wholeNumbersAsIntegers(child);
    }
}

}  // namespace

std::string serializeProject(const Project& p) {
    Json root;
    root["format"] = "camwright";
    root["version"] = kProjectFormatVersion;
    root["name"] = p.name;
    const double mm = p.units.lengthFactor();
    const double deg = p.units.angleFactor();
    auto length = [mm](double v) { return fileValue(v, mm); };
    auto point = [&](const Eigen::Vector2d& v) {
        return Json::array({length(v.x()), length(v.y())});
    };
    root["units"] = {{"length", p.units.length == LengthUnit::M ? "m" : "mm"},
                     {"angle", p.units.angle == AngleUnit::Rad ? "rad" : "deg"}};
    const char* speedKey = p.motion.unit == SpeedUnit::OmegaRadS ? "omega_rad_s"
                           : p.motion.unit == SpeedUnit::Rpm     ? "rpm"
                                                                 : "period_s";
    root["motion"] = {{speedKey, p.motion.value}};
    Json contour = Json::array();
    for (const SegmentSpec& s : p.contour) {
        Json j;
        if (const auto* arc = s.as<Arc>()) {
            j["type"] = "arc";
            j["center"] = point(arc->center);
            j["radius"] = length(arc->radius);
            j["branch"] = arc->branch == Branch::Outer ? "outer" : "inner";
        } else if (const auto* line = s.as<Line>()) {
            j["type"] = "line";
            j["from"] = point(line->from);
            j["to"] = point(line->to);
        } else if (const auto* bezier = s.as<CubicBezier>()) {
            j["type"] = "bezier";
            j["points"] = Json::array({point(bezier->p[0]), point(bezier->p[1]),
                                       point(bezier->p[2]), point(bezier->p[3])});
        } else {
            const HermiteCurve& h = *s.as<HermiteCurve>();
            j["type"] = "hermite";
            j["p0"] = point(h.p0);
            j["t0"] = point(h.t0);
            j["p3"] = point(h.p3);
            j["t1"] = point(h.t1);
        }
        j["phi_start"] = fileValue(s.phiStartDeg, deg);
        j["phi_end"] = fileValue(s.phiEndDeg, deg);
        contour.push_back(std::move(j));
    }
    root["contour"] = std::move(contour);
    if (p.follower) {
        const FollowerSpec& f = *p.follower;
        Json j;
        j["type"] = std::string(followerKind(f.type).name);
        if (f.motion == FollowerMotion::Oscillating) {
            j["motion"] = "oscillating";
            j["pivot"] = {length(f.pivot.x()), length(f.pivot.y())};
            j["arm_length"] = length(f.armLength);
            j["arm"] = f.arm == ArmSide::Ccw ? "ccw" : "cw";
        } else {
            j["offset"] = length(f.offset);
        }
        if (followerKind(f.type).hasRadius) j["radius"] = length(f.radius);
        if (f.maxPressureAngleDeg) j["max_pressure_angle_deg"] = *f.maxPressureAngleDeg;
        if (f.closure == Closure::Groove) {
            j["closure"] = "groove";
            j["groove_clearance_mm"] = f.grooveClearance;
        }
        if (f.closure == Closure::Conjugate) {
            j["closure"] = "conjugate";
            if (f.motion == FollowerMotion::Oscillating) {
                j["conjugate_angle_deg"] = f.conjugateAngleDeg;
                j["conjugate_arm_length_mm"] = f.conjugateArmLength;
            } else {
                j["conjugate_distance_mm"] = f.conjugateDistance;
            }
            j["conjugate_radius_mm"] = f.conjugateRadius;
        }
        if (f.innerLandRadius) j["inner_land_radius_mm"] = *f.innerLandRadius;
        if (f.outerLandRadius) j["outer_land_radius_mm"] = *f.outerLandRadius;
        root["follower"] = std::move(j);
    }
    if (p.samplesPerTurn) root["sampling"] = {{"samples_per_turn", *p.samplesPerTurn}};
    if (p.machining) {
        const MachiningSpec& m = *p.machining;
        Json j;
        auto lengths = [&](const std::vector<double>& values) {
            Json list = Json::array();
            for (double v : values) list.push_back(length(v));
            return list;
        };
        j["axis_accel"] = lengths(m.axisAccel);
        if (!m.axisVmax.empty()) j["axis_vmax"] = lengths(m.axisVmax);
        j["feed_max"] = length(m.feedMax);
        j["tool_radius"] = length(m.toolRadius);
        j["step"] = length(m.step);
        root["machining"] = std::move(j);
    }
    if (p.design) {
        const DesignSpec& d = *p.design;
        const bool swinging = p.follower && p.follower->motion == FollowerMotion::Oscillating;
        const auto lift = [&](double v) { return swinging ? v : length(v); };
        Json segments = Json::array();
        for (const DesignSegmentSpec& s : d.segments) {
            Json j;
            j["law"] = std::string(lawName(s.law));
            j["to_deg"] = s.toDeg;
            j["lift"] = lift(s.lift);
            // The keys a law takes are its row's (design/motion_law.cpp).
            for (auto [part, value] :
                 {std::pair{DesignPart::V0, s.v0}, std::pair{DesignPart::A0, s.a0},
                  std::pair{DesignPart::J0, s.j0}, std::pair{DesignPart::V1, s.v1},
                  std::pair{DesignPart::A1, s.a1}, std::pair{DesignPart::J1, s.j1}}) {
                if (lawUses(s.law, part)) j[std::string(designPartKey(part))] = lift(value);
            }
            // λ only where it is not the classic symmetric law's, so that a file of the classic
            // laws reads as it always did.
            if (lawUses(s.law, DesignPart::Lambda) && s.lambda != DesignSegmentSpec{}.lambda) {
                j["lambda"] = s.lambda;
            }
            for (auto [part, value] :
                 {std::pair{DesignPart::SccaB, s.sccaB}, std::pair{DesignPart::SccaD, s.sccaD}}) {
                if (lawUses(s.law, part)) j[std::string(designPartKey(part))] = value;
            }
            if (lawUses(s.law, DesignPart::Points)) {
                Json points = Json::array();
                for (const MotionTablePoint& p : s.table) {
                    Json point = {p.x, p.y};
                    if (p.v) point.push_back(*p.v);
                    points.push_back(std::move(point));
                }
                j["points"] = std::move(points);
            }
            segments.push_back(std::move(j));
        }
        root["design"] = {{"base_radius", length(d.baseRadius)},
                          {"segments", std::move(segments)},
                          {"tolerance", length(d.tolerance)}};
        if (d.strictPressureAngle) root["design"]["strict_pressure_angle"] = true;
    }
    if (p.dynamics) {
        // Each value as given, in the key's own unit; a material only with a value in it.
        Json j = Json::object();
        for (const DynamicsKeyInfo& info : dynamicsKeys()) {
            const std::optional<double>& v = (*p.dynamics)[info.key];
            if (!v) continue;
            const std::string group(dynamicsKeyGroup(info.key));
            const std::string name(dynamicsKeyName(info.key));
            if (group.empty()) {
                j[name] = *v;
            } else {
                j[group][name] = *v;
            }
        }
        root["dynamics"] = std::move(j);
    }
    wholeNumbersAsIntegers(root);
    for (const auto& [key, text] : p.extraKeys) root[key] = Json::parse(text);
    return root.dump(2) + "\n";
}

Diagnostics nonFiniteValues(const Project& p) {
    Diagnostics out;
    auto check = [&](double v, Place where) {
        if (std::isfinite(v)) return;
        out.push_back(Diagnostic::make(std::move(where), DiagnosticCode::NotFiniteForFile));
    };
    auto checkPoint = [&](const Eigen::Vector2d& v, SegmentPlace place) {
        for (int axis = 0; axis < 2; ++axis) {
            place.axis = axis;
            check(v[axis], place);
        }
    };
    check(p.motion.value, FieldPlace{Field::Motion});
    for (std::size_t k = 0; k < p.contour.size(); ++k) {
        const SegmentSpec& s = p.contour[k];
        check(s.phiStartDeg, SegmentPlace{k, SegmentPart::PhiStart});
        check(s.phiEndDeg, SegmentPlace{k, SegmentPart::PhiEnd});
        if (const auto* arc = s.as<Arc>()) {
            checkPoint(arc->center, {k, SegmentPart::Center});
            check(arc->radius, SegmentPlace{k, SegmentPart::Radius});
        } else if (const auto* line = s.as<Line>()) {
            checkPoint(line->from, {k, SegmentPart::From});
            checkPoint(line->to, {k, SegmentPart::To});
        } else if (const auto* b = s.as<CubicBezier>()) {
            for (int i = 0; i < 4; ++i) {
                checkPoint(b->p[static_cast<std::size_t>(i)], {k, SegmentPart::Points, i});
            }
        } else {
            const HermiteCurve& h = *s.as<HermiteCurve>();
            checkPoint(h.p0, {k, SegmentPart::P0});
            checkPoint(h.t0, {k, SegmentPart::T0});
            checkPoint(h.p3, {k, SegmentPart::P3});
            checkPoint(h.t1, {k, SegmentPart::T1});
        }
    }
    if (p.follower) {
        check(p.follower->offset, FieldPlace{Field::FollowerOffset});
        check(p.follower->radius, FieldPlace{Field::FollowerRadius});
        check(p.follower->grooveClearance, FieldPlace{Field::FollowerGrooveClearance});
        check(p.follower->conjugateDistance, FieldPlace{Field::FollowerConjugateDistance});
        check(p.follower->conjugateRadius, FieldPlace{Field::FollowerConjugateRadius});
        check(p.follower->conjugateAngleDeg, FieldPlace{Field::FollowerConjugateAngle});
        check(p.follower->conjugateArmLength, FieldPlace{Field::FollowerConjugateArmLength});
        if (p.follower->innerLandRadius) {
            check(*p.follower->innerLandRadius, FieldPlace{Field::FollowerInnerLandRadius});
        }
        if (p.follower->outerLandRadius) {
            check(*p.follower->outerLandRadius, FieldPlace{Field::FollowerOuterLandRadius});
        }
    }
    if (p.design) {
        check(p.design->baseRadius, FieldPlace{Field::DesignBaseRadius});
        check(p.design->tolerance, FieldPlace{Field::DesignTolerance});
        for (std::size_t k = 0; k < p.design->segments.size(); ++k) {
            const DesignSegmentSpec& s = p.design->segments[k];
            for (auto [part, v] :
                 {std::pair{DesignPart::ToDeg, s.toDeg}, std::pair{DesignPart::Lift, s.lift},
                  std::pair{DesignPart::V0, s.v0}, std::pair{DesignPart::A0, s.a0},
                  std::pair{DesignPart::V1, s.v1}, std::pair{DesignPart::A1, s.a1},
                  std::pair{DesignPart::J0, s.j0}, std::pair{DesignPart::J1, s.j1},
                  std::pair{DesignPart::Lambda, s.lambda}, std::pair{DesignPart::SccaB, s.sccaB},
                  std::pair{DesignPart::SccaD, s.sccaD}}) {
                check(v, DesignSegmentPlace{k, part});
            }
            for (const MotionTablePoint& point : s.table) {
                for (double v : {point.x, point.y, point.v.value_or(0.0)}) {
                    check(v, DesignSegmentPlace{k, DesignPart::Points});
                }
            }
        }
    }
    if (p.dynamics) {
        for (const DynamicsKeyInfo& info : dynamicsKeys()) {
            if (const auto& v = (*p.dynamics)[info.key]) check(*v, DynamicsPlace{info.key});
        }
    }
    if (p.machining) {
        const MachiningSpec& m = *p.machining;
        for (std::size_t i = 0; i < m.axisAccel.size(); ++i) {
            check(m.axisAccel[i], FieldPlace{Field::MachiningAxisAccel, static_cast<int>(i)});
        }
        for (std::size_t i = 0; i < m.axisVmax.size(); ++i) {
            check(m.axisVmax[i], FieldPlace{Field::MachiningAxisVmax, static_cast<int>(i)});
        }
        check(m.feedMax, FieldPlace{Field::MachiningFeedMax});
        check(m.toolRadius, FieldPlace{Field::MachiningToolRadius});
        check(m.step, FieldPlace{Field::MachiningStep});
    }
    return out;
}

}  // namespace cam

namespace cam {

std::string jsonLibraryVersion() {
    return std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
           std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
           std::to_string(NLOHMANN_JSON_VERSION_PATCH);
}

}  // namespace cam
