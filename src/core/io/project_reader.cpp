#include "io/project_reader.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <span>
#include <string_view>
#include <vector>

#include "common/angles.h"
#include "common/translate_marker.h"
#include "design/motion_law.h"
#include "project/dynamics.h"
#include "project/follower_kind.h"
#include "project/validate.h"

namespace cam {
namespace {

/// What a JSON value is, as a term of the diagnostic catalogue (or the JSON literal null).
const char* typeName(const Json& j) {
    if (j.is_string()) return CAM_TRANSLATE_NOOP("Diagnostic", "a string");
    if (j.is_boolean()) return CAM_TRANSLATE_NOOP("Diagnostic", "a boolean");
    if (j.is_number()) return CAM_TRANSLATE_NOOP("Diagnostic", "a number");
    if (j.is_array()) return CAM_TRANSLATE_NOOP("Diagnostic", "an array");
    if (j.is_object()) return CAM_TRANSLATE_NOOP("Diagnostic", "an object");
    return "null";
}

/// Reads typed fields out of the DOM, recording located errors instead of throwing.
class Reader {
public:
    Diagnostics errors;

    /// A problem of the file at the key `location` (its path in the file).
    void error(const std::string& location, DiagnosticCode code,
               std::vector<DiagnosticArg> args = {}) {
        errors.push_back(Diagnostic::make(FileKeyPlace{location}, code, std::move(args)));
    }

    /// "must be <what> (got <a JSON type>)": `what` is a term of the diagnostic catalogue.
    void wrongType(const std::string& location, const char* what, const std::string& got) {
        error(location, DiagnosticCode::WrongType, {what, got});
    }

    /// "must be "a", "b" or "c" (got "d")".
    void notOneOf(const std::string& location, std::initializer_list<std::string_view> choices,
                  const std::string& got) {
        notOneOf(location, std::span<const std::string_view>(choices.begin(), choices.size()), got);
    }
    void notOneOf(const std::string& location, std::span<const std::string_view> choices,
                  const std::string& got) {
        // All but the last choice, quoted and listed with commas; the code words the "or".
        // (Built by appends: GCC 12 warns falsely on "\"" + string, PR105651.)
        const auto quoted = [](std::string_view choice) {
            std::string out = "\"";
            return out.append(choice).append(1, '"');
        };
        std::string others;
        for (std::size_t i = 0; i + 1 < choices.size(); ++i) {
            if (i > 0) others += ", ";
            others += quoted(choices[i]);
        }
        const std::string last = quoted(choices.back());
        if (others.empty()) {
            error(location, DiagnosticCode::NotTheValue, {last, got});
        } else {
            error(location, DiagnosticCode::NotOneOf, {others, last, got});
        }
    }

    const Json* field(const Json& obj, const std::string& at, const char* key, bool required) {
        const auto it = obj.find(key);
        if (it == obj.end()) {
            if (required) error(join(at, key), DiagnosticCode::Missing);
            return nullptr;
        }
        return &*it;
    }

    static std::string join(const std::string& at, const char* key) {
        return at.empty() ? std::string(key) : at + "." + key;
    }

    std::optional<double> number(const Json& j, const std::string& at) {
        if (!j.is_number()) {
            wrongType(at, CAM_TRANSLATE_NOOP("Diagnostic", "a number"), typeName(j));
            return std::nullopt;
        }
        return j.get<double>();
    }

    std::optional<double> number(const Json& obj, const std::string& at, const char* key,
                                 bool required) {
        const Json* j = field(obj, at, key, required);
        return j ? number(*j, join(at, key)) : std::nullopt;
    }

    std::optional<bool> boolean(const Json& obj, const std::string& at, const char* key,
                                bool required) {
        const Json* j = field(obj, at, key, required);
        if (!j) return std::nullopt;
        if (!j->is_boolean()) {
            wrongType(join(at, key), CAM_TRANSLATE_NOOP("Diagnostic", "true or false"),
                      typeName(*j));
            return std::nullopt;
        }
        return j->get<bool>();
    }

    std::optional<std::string> string(const Json& obj, const std::string& at, const char* key,
                                      bool required) {
        const Json* j = field(obj, at, key, required);
        if (!j) return std::nullopt;
        if (!j->is_string()) {
            wrongType(join(at, key), CAM_TRANSLATE_NOOP("Diagnostic", "a string"), typeName(*j));
            return std::nullopt;
        }
        return j->get<std::string>();
    }

    std::optional<Eigen::Vector2d> point(const Json& obj, const std::string& at, const char* key,
                                         bool required) {
        const Json* j = field(obj, at, key, required);
        if (!j) return std::nullopt;
        return pointValue(*j, join(at, key));
    }

    /// A value that must be [x, y].
    std::optional<Eigen::Vector2d> pointValue(const Json& j, const std::string& loc) {
        if (!j.is_array()) {
            wrongType(loc, CAM_TRANSLATE_NOOP("Diagnostic", "an array [x, y] of two numbers"),
                      typeName(j));
            return std::nullopt;
        }
        if (j.size() != 2) {
            error(loc, DiagnosticCode::PointShape, {static_cast<double>(j.size())});
            return std::nullopt;
        }
        const auto x = number(j[0], loc + "[0]");
        const auto y = number(j[1], loc + "[1]");
        if (!x || !y) return std::nullopt;
        return Eigen::Vector2d(*x, *y);
    }

    std::optional<std::vector<double>> numbers(const Json& obj, const std::string& at,
                                               const char* key, bool required) {
        const Json* j = field(obj, at, key, required);
        if (!j) return std::nullopt;
        const std::string loc = join(at, key);
        if (!j->is_array()) {
            wrongType(loc, CAM_TRANSLATE_NOOP("Diagnostic", "an array of numbers"), typeName(*j));
            return std::nullopt;
        }
        std::vector<double> out;
        bool ok = true;
        for (std::size_t i = 0; i < j->size(); ++i) {
            const auto v = number((*j)[i], loc + "[" + std::to_string(i) + "]");
            ok = ok && v.has_value();
            out.push_back(v.value_or(0.0));
        }
        return ok ? std::optional(out) : std::nullopt;
    }

    bool object(const Json& j, const std::string& at) {
        if (!j.is_object()) {
            wrongType(at, CAM_TRANSLATE_NOOP("Diagnostic", "an object"), typeName(j));
            return false;
        }
        return true;
    }

    /// Keys inside known objects must be known: a typo must not be silently ignored.
    void onlyKeys(const Json& obj, const std::string& at, const std::vector<std::string>& keys) {
        for (const auto& [key, value] : obj.items()) {
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
                error(join(at, key.c_str()), DiagnosticCode::UnknownKey);
            }
        }
    }
    void onlyKeys(const Json& obj, const std::string& at, std::initializer_list<const char*> keys) {
        for (const auto& [key, value] : obj.items()) {
            bool known = false;
            for (const char* k : keys) known = known || key == k;
            if (!known) error(join(at, key.c_str()), DiagnosticCode::UnknownKey);
        }
    }
};

void readSegment(Reader& rd, const Json& j, const std::string& at, const UnitsSpec& units,
                 std::optional<double> previousEndDeg, SegmentSpec& s) {
    if (!rd.object(j, at)) return;
    const auto type = rd.string(j, at, "type", true);
    if (!type) return;
    const double mm = units.lengthFactor();
    auto window = [&] {
        const auto start = rd.number(j, at, "phi_start", true);
        const auto end = rd.number(j, at, "phi_end", true);
        if (start) s.phiStartDeg = *start * units.angleFactor();
        if (end) s.phiEndDeg = *end * units.angleFactor();
    };
    // Lines and splines may leave their window out: it follows from their end points.
    auto windowOrDefault = [&](bool complete) {
        if (j.contains("phi_start") || j.contains("phi_end")) {
            window();
        } else if (complete) {
            std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, previousEndDeg.value_or(0.0));
        }
    };
    if (*type == "arc") {
        Arc arc;
        rd.onlyKeys(j, at, {"type", "center", "radius", "branch", "phi_start", "phi_end"});
        if (const auto c = rd.point(j, at, "center", true)) arc.center = *c * mm;
        if (const auto r = rd.number(j, at, "radius", true)) arc.radius = *r * mm;
        if (const auto b = rd.string(j, at, "branch", true)) {
            if (*b == "outer") {
                arc.branch = Branch::Outer;
            } else if (*b == "inner") {
                arc.branch = Branch::Inner;
            } else {
                rd.notOneOf(at + ".branch", {"outer", "inner"}, *b);
            }
        }
        s.shape = arc;
        window();
    } else if (*type == "line") {
        rd.onlyKeys(j, at, {"type", "from", "to", "phi_start", "phi_end"});
        const auto from = rd.point(j, at, "from", true);
        const auto to = rd.point(j, at, "to", true);
        Line line;
        if (from) line.from = *from * mm;
        if (to) line.to = *to * mm;
        s.shape = line;
        windowOrDefault(from && to);
    } else if (*type == "bezier") {
        rd.onlyKeys(j, at, {"type", "points", "phi_start", "phi_end"});
        CubicBezier curve;
        bool complete = false;
        if (const Json* pts = rd.field(j, at, "points", true)) {
            if (!pts->is_array() || pts->size() != 4) {
                rd.error(at + ".points", DiagnosticCode::BezierPointCount);
            } else {
                complete = true;
                for (std::size_t i = 0; i < 4; ++i) {
                    const auto p =
                        rd.pointValue((*pts)[i], at + ".points[" + std::to_string(i) + "]");
                    if (p) curve.p[i] = *p * mm;
                    complete = complete && p.has_value();
                }
            }
        }
        s.shape = curve;
        windowOrDefault(complete);
    } else if (*type == "hermite") {
        rd.onlyKeys(j, at, {"type", "p0", "t0", "p3", "t1", "phi_start", "phi_end"});
        HermiteCurve curve;
        bool complete = true;
        for (auto [key, field] : {std::pair{"p0", &curve.p0}, std::pair{"t0", &curve.t0},
                                  std::pair{"p3", &curve.p3}, std::pair{"t1", &curve.t1}}) {
            const auto p = rd.point(j, at, key, true);
            if (p) *field = *p * mm;
            complete = complete && p.has_value();
        }
        s.shape = curve;
        windowOrDefault(complete);
    } else {
        rd.error(at + ".type", DiagnosticCode::UnknownSegmentType, {*type});
    }
}

void readMotion(Reader& rd, const Json& root, Project& p) {
    const Json* m = rd.field(root, "", "motion", true);
    if (!m || !rd.object(*m, "motion")) return;
    rd.onlyKeys(*m, "motion", {"omega_rad_s", "rpm", "period_s"});
    int given = 0;
    for (auto [key, unit] :
         {std::pair{"omega_rad_s", SpeedUnit::OmegaRadS}, std::pair{"rpm", SpeedUnit::Rpm},
          std::pair{"period_s", SpeedUnit::PeriodS}}) {
        if (!m->contains(key)) continue;
        ++given;
        if (const auto v = rd.number(*m, "motion", key, true)) p.motion = {unit, *v};
    }
    if (given != 1) {
        rd.error("motion", DiagnosticCode::SpeedNotExactlyOne, {static_cast<double>(given)});
    }
}

void readFollower(Reader& rd, const Json& root, const UnitsSpec& units, Project& p) {
    const Json* f = rd.field(root, "", "follower", false);
    if (!f || !rd.object(*f, "follower")) return;
    rd.onlyKeys(*f, "follower",
                {"type", "motion", "offset", "radius", "pivot", "arm_length", "arm",
                 "max_pressure_angle_deg", "closure", "groove_clearance_mm", "inner_land_radius_mm",
                 "outer_land_radius_mm", "conjugate_distance_mm", "conjugate_radius_mm",
                 "conjugate_angle_deg", "conjugate_arm_length_mm"});
    FollowerSpec spec;
    if (const auto type = rd.string(*f, "follower", "type", false)) {
        if (const auto known = followerTypeFromName(*type)) {
            spec.type = *known;
        } else {
            std::vector<std::string_view> names;
            for (const FollowerKind& kind : followerKinds()) names.push_back(kind.name);
            rd.notOneOf("follower.type", names, *type);
        }
    }
    if (const auto motion = rd.string(*f, "follower", "motion", false)) {
        if (*motion == "translating") {
            spec.motion = FollowerMotion::Translating;
        } else if (*motion == "oscillating") {
            spec.motion = FollowerMotion::Oscillating;
        } else {
            rd.notOneOf("follower.motion", {"translating", "oscillating"}, *motion);
        }
    }
    const double mm = units.lengthFactor();
    if (const auto v = rd.number(*f, "follower", "offset", false)) spec.offset = *v * mm;
    const bool needsRadius = followerKind(spec.type).hasRadius;
    if (const auto v = rd.number(*f, "follower", "radius", needsRadius)) spec.radius = *v * mm;
    const bool swinging = spec.motion == FollowerMotion::Oscillating;
    if (const auto v = rd.point(*f, "follower", "pivot", swinging)) spec.pivot = *v * mm;
    if (const auto v = rd.number(*f, "follower", "arm_length", swinging)) spec.armLength = *v * mm;
    if (const auto arm = rd.string(*f, "follower", "arm", false)) {
        if (*arm == "ccw") {
            spec.arm = ArmSide::Ccw;
        } else if (*arm == "cw") {
            spec.arm = ArmSide::Cw;
        } else {
            rd.notOneOf("follower.arm", {"cw", "ccw"}, *arm);
        }
    }
    if (const auto v = rd.number(*f, "follower", "max_pressure_angle_deg", false)) {
        spec.maxPressureAngleDeg = *v;
    }
    if (const auto closure = rd.string(*f, "follower", "closure", false)) {
        if (*closure == "spring") {
            spec.closure = Closure::Spring;
        } else if (*closure == "groove") {
            spec.closure = Closure::Groove;
        } else if (*closure == "conjugate") {
            spec.closure = Closure::Conjugate;
        } else {
            rd.notOneOf("follower.closure", {"spring", "groove", "conjugate"}, *closure);
        }
    }
    // The groove's lengths are in millimetres whatever the project's unit: their keys say so.
    const bool grooved = spec.closure == Closure::Groove;
    if (const auto v = rd.number(*f, "follower", "groove_clearance_mm", grooved)) {
        spec.grooveClearance = *v;
    }
    if (const auto v = rd.number(*f, "follower", "inner_land_radius_mm", false)) {
        spec.innerLandRadius = *v;
    }
    if (const auto v = rd.number(*f, "follower", "outer_land_radius_mm", false)) {
        spec.outerLandRadius = *v;
    }
    // A yoke's distance on a line, a bell crank's second arm on an arm.
    const bool conjugate = spec.closure == Closure::Conjugate;
    if (const auto v = rd.number(*f, "follower", "conjugate_distance_mm", conjugate && !swinging)) {
        spec.conjugateDistance = *v;
    }
    if (const auto v = rd.number(*f, "follower", "conjugate_angle_deg", conjugate && swinging)) {
        spec.conjugateAngleDeg = *v;
    }
    if (const auto v =
            rd.number(*f, "follower", "conjugate_arm_length_mm", conjugate && swinging)) {
        spec.conjugateArmLength = *v;
    }
    if (const auto v = rd.number(*f, "follower", "conjugate_radius_mm", conjugate)) {
        spec.conjugateRadius = *v;
    }
    p.follower = spec;
}

void readSampling(Reader& rd, const Json& root, Project& p) {
    const Json* s = rd.field(root, "", "sampling", false);
    if (!s || !rd.object(*s, "sampling")) return;
    rd.onlyKeys(*s, "sampling", {"samples_per_turn"});
    const auto n = rd.number(*s, "sampling", "samples_per_turn", true);
    if (!n) return;
    if (!(std::floor(*n) == *n) || std::abs(*n) > 9e15) {
        rd.error("sampling.samples_per_turn", DiagnosticCode::NotWholeSampleCount, {*n});
        return;
    }
    p.samplesPerTurn = static_cast<std::int64_t>(*n);
}

void readMachining(Reader& rd, const Json& root, const UnitsSpec& units, Project& p) {
    const Json* m = rd.field(root, "", "machining", false);
    if (!m || !rd.object(*m, "machining")) return;
    const std::string at = "machining";
    rd.onlyKeys(*m, at, {"axis_accel", "axis_vmax", "feed_max", "tool_radius", "step"});
    MachiningSpec spec;
    const double mm = units.lengthFactor();
    auto scaled = [&](std::vector<double> v) {
        for (double& x : v) x *= mm;
        return v;
    };
    if (const auto v = rd.numbers(*m, at, "axis_accel", true)) spec.axisAccel = scaled(*v);
    if (const auto v = rd.numbers(*m, at, "axis_vmax", false)) spec.axisVmax = scaled(*v);
    if (const auto v = rd.number(*m, at, "feed_max", true)) spec.feedMax = *v * mm;
    if (const auto v = rd.number(*m, at, "tool_radius", false)) spec.toolRadius = *v * mm;
    if (const auto v = rd.number(*m, at, "step", false)) spec.step = *v * mm;
    p.machining = spec;
}

void readDynamics(Reader& rd, const Json& root, Project& p) {
    const Json* d = rd.field(root, "", "dynamics", false);
    if (!d || !rd.object(*d, "dynamics")) return;
    DynamicsSpec spec;
    // The keys the file may have at the top of `dynamics`, and the objects inside it.
    std::set<std::string> top;
    std::set<std::string> groups;
    for (const DynamicsKeyInfo& info : dynamicsKeys()) {
        const std::string group(dynamicsKeyGroup(info.key));
        (group.empty() ? top : groups)
            .insert(group.empty() ? std::string(dynamicsKeyName(info.key)) : group);
    }
    for (const auto& [key, value] : d->items()) {
        if (!top.contains(key) && !groups.contains(key)) {
            rd.error("dynamics." + key, DiagnosticCode::UnknownKey);
        }
    }
    for (const std::string& group : groups) {
        const std::string at = "dynamics." + group;
        const Json* g = rd.field(*d, "dynamics", group.c_str(), false);
        if (!g || !rd.object(*g, at)) continue;
        // A material is both its values: each is required once the object is there.
        for (const auto& [key, value] : g->items()) {
            bool known = false;
            for (const DynamicsKeyInfo& info : dynamicsKeys()) {
                known = known ||
                        (dynamicsKeyGroup(info.key) == group && dynamicsKeyName(info.key) == key);
            }
            if (!known) rd.error(at + "." + key, DiagnosticCode::UnknownKey);
        }
        for (const DynamicsKeyInfo& info : dynamicsKeys()) {
            if (dynamicsKeyGroup(info.key) != group) continue;
            const std::string name(dynamicsKeyName(info.key));
            if (const auto v = rd.number(*g, at, name.c_str(), true)) spec[info.key] = *v;
        }
    }
    for (const DynamicsKeyInfo& info : dynamicsKeys()) {
        if (!dynamicsKeyGroup(info.key).empty()) continue;
        const std::string name(dynamicsKeyName(info.key));
        if (const auto v = rd.number(*d, "dynamics", name.c_str(), false)) spec[info.key] = *v;
    }
    p.dynamics = spec;
}

/// "\"dwell\", \"harmonic\", …" for messages.
std::string knownLawNames() {
    std::string out;
    for (const MotionLawKind& law : motionLaws()) {
        if (!out.empty()) out += ", ";
        out += '"';
        out += law.name;
        out += '"';
    }
    return out;
}

void readDesign(Reader& rd, const Json& root, const UnitsSpec& units, Project& p) {
    const Json* d = rd.field(root, "", "design", false);
    if (!d || !rd.object(*d, "design")) return;
    rd.onlyKeys(*d, "design", {"base_radius", "segments", "tolerance", "strict_pressure_angle"});
    DesignSpec spec;
    const double mm = units.lengthFactor();
    // Lifts are lengths on a translating follower, degrees swung on an arm.
    const bool swinging = p.follower && p.follower->motion == FollowerMotion::Oscillating;
    const double liftUnit = swinging ? 1.0 : mm;
    if (const auto v = rd.number(*d, "design", "base_radius", true)) spec.baseRadius = *v * mm;
    if (const auto v = rd.number(*d, "design", "tolerance", false)) spec.tolerance = *v * mm;
    if (const auto v = rd.boolean(*d, "design", "strict_pressure_angle", false)) {
        spec.strictPressureAngle = *v;
    }
    if (const Json* list = rd.field(*d, "design", "segments", true)) {
        if (!list->is_array()) {
            rd.wrongType("design.segments",
                         CAM_TRANSLATE_NOOP("Diagnostic", "an array of segments"), typeName(*list));
        } else {
            for (std::size_t k = 0; k < list->size(); ++k) {
                const Json& j = (*list)[k];
                const std::string at = "design.segments[" + std::to_string(k) + "]";
                if (!rd.object(j, at)) continue;
                DesignSegmentSpec s;
                if (const auto name = rd.string(j, at, "law", true)) {
                    if (const auto law = lawFromName(*name)) {
                        s.law = *law;
                    } else {
                        rd.error(at + ".law", DiagnosticCode::UnknownLaw, {*name, knownLawNames()});
                    }
                }
                // The keys a law takes are its row's (design/motion_law.cpp).
                std::vector<std::string> keys = {"law", "to_deg", "lift"};
                for (DesignPart part : kLawParameterParts) {
                    if (lawUses(s.law, part)) keys.emplace_back(designPartKey(part));
                }
                rd.onlyKeys(j, at, keys);
                if (const auto v = rd.number(j, at, "to_deg", true)) s.toDeg = *v;
                if (const auto v =
                        rd.number(j, at, "lift", motionLaw(s.law).shape != LawShape::Dwell)) {
                    s.lift = *v * liftUnit;
                } else if (motionLaw(s.law).shape == LawShape::Dwell) {
                    s.lift = spec.segments.empty() ? 0.0 : spec.segments.back().lift;
                }
                for (auto [key, value] :
                     {std::pair{"v0", &s.v0}, std::pair{"a0", &s.a0}, std::pair{"v1", &s.v1},
                      std::pair{"a1", &s.a1}, std::pair{"j0", &s.j0}, std::pair{"j1", &s.j1}}) {
                    if (const auto v = rd.number(j, at, key, false)) *value = *v * liftUnit;
                }
                for (auto [key, value] : {std::pair{"lambda", &s.lambda}, std::pair{"b", &s.sccaB},
                                          std::pair{"d", &s.sccaD}}) {
                    if (const auto v = rd.number(j, at, key, false)) *value = *v;
                }
                if (lawUses(s.law, DesignPart::Points)) {
                    if (const Json* list = rd.field(j, at, "points", true)) {
                        const std::string loc = at + ".points";
                        if (!list->is_array()) {
                            rd.wrongType(loc,
                                         CAM_TRANSLATE_NOOP("Diagnostic",
                                                            "an array of points [x, y] or "
                                                            "[x, y, dy/dx]"),
                                         typeName(*list));
                        } else {
                            for (std::size_t i = 0; i < list->size(); ++i) {
                                const Json& p = (*list)[i];
                                const std::string pat = loc + "[" + std::to_string(i) + "]";
                                if (!p.is_array() || (p.size() != 2 && p.size() != 3)) {
                                    rd.error(pat, DiagnosticCode::MotionTableColumns,
                                             {static_cast<double>(p.is_array() ? p.size() : 1)});
                                    continue;
                                }
                                const auto x = rd.number(p[0], pat + "[0]");
                                const auto y = rd.number(p[1], pat + "[1]");
                                std::optional<double> v;
                                if (p.size() == 3) v = rd.number(p[2], pat + "[2]");
                                if (x && y && (p.size() == 2 || v)) s.table.push_back({*x, *y, v});
                            }
                        }
                    }
                }
                spec.segments.push_back(s);
            }
        }
    }
    p.design = spec;
}

}  // namespace

Result<Project> readProject(const Json& root) {
    Reader rd;
    if (!root.is_object()) {
        rd.wrongType("(top level)", CAM_TRANSLATE_NOOP("Diagnostic", "an object"), typeName(root));
        return rd.errors;
    }
    const auto format = rd.string(root, "", "format", true);
    if (format && *format != "camwright") {
        rd.notOneOf("format", {"camwright"}, *format);
    }
    if (const Json* v = rd.field(root, "", "version", true)) {
        if (!v->is_number_integer()) {
            rd.wrongType("version", CAM_TRANSLATE_NOOP("Diagnostic", "a whole number"),
                         v->is_number() ? v->dump() : typeName(*v));
        } else if (v->get<std::int64_t>() > kProjectFormatVersion) {
            rd.error("version", DiagnosticCode::NewerFormatVersion, {v->dump()});
        } else if (v->get<std::int64_t>() < 1) {
            rd.error("version", DiagnosticCode::NotFormatVersion1, {v->dump()});
        }
    }
    if (hasErrors(rd.errors)) return rd.errors;  // not a Camwright v1 file: say only that

    Project p;
    if (const auto name = rd.string(root, "", "name", false)) p.name = *name;

    UnitsSpec& units = p.units;
    if (const Json* u = rd.field(root, "", "units", false); u && rd.object(*u, "units")) {
        rd.onlyKeys(*u, "units", {"length", "angle"});
        if (const auto length = rd.string(*u, "units", "length", false)) {
            if (*length == "m") {
                units.length = LengthUnit::M;
            } else if (*length != "mm") {
                rd.notOneOf("units.length", {"mm", "m"}, *length);
            }
        }
        if (const auto angle = rd.string(*u, "units", "angle", false)) {
            if (*angle == "rad") {
                units.angle = AngleUnit::Rad;
            } else if (*angle != "deg") {
                rd.notOneOf("units.angle", {"deg", "rad"}, *angle);
            }
        }
    }

    readMotion(rd, root, p);

    if (const Json* c = rd.field(root, "", "contour", true)) {
        if (!c->is_array()) {
            rd.wrongType("contour", CAM_TRANSLATE_NOOP("Diagnostic", "an array of segments"),
                         typeName(*c));
        } else {
            std::optional<double> previousEnd;
            for (std::size_t k = 0; k < c->size(); ++k) {
                SegmentSpec s;
                readSegment(rd, (*c)[k], segmentLocation(k), units, previousEnd, s);
                previousEnd = s.phiEndDeg;
                p.contour.push_back(s);
            }
        }
    }
    readFollower(rd, root, units, p);
    readSampling(rd, root, p);
    readMachining(rd, root, units, p);
    readDesign(rd, root, units, p);
    readDynamics(rd, root, p);

    static const std::set<std::string> known{"format",    "version", "name",     "units",
                                             "motion",    "contour", "follower", "sampling",
                                             "machining", "design",  "dynamics"};
    for (const auto& [key, value] : root.items()) {
        if (!known.contains(key)) p.extraKeys.emplace_back(key, value.dump());
    }

    if (hasErrors(rd.errors)) return rd.errors;
    return p;
}

}  // namespace cam
