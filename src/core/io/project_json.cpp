#include "io/project_json.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "common/angles.h"
#include "project/validate.h"

namespace cam {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kMaxDepth = 64;

/// Thrown from the parser callback; carries the location of the offending key or value.
struct StructureError {
    std::string location;
    std::string message;
};

/// Tracks the JSON path during parsing, to name duplicated keys and excessive nesting.
class PathTracker {
public:
    bool operator()(int depth, Json::parse_event_t event, Json& parsed) {
        using E = Json::parse_event_t;
        switch (event) {
            case E::object_start:
            case E::array_start:
                if (depth >= kMaxDepth) {
                    throw StructureError{
                        path(), "nesting deeper than " + std::to_string(kMaxDepth) + " levels"};
                }
                m_frames.push_back({event == E::array_start, 0, {}, {}});
                break;
            case E::key: {
                Frame& f = m_frames.back();
                f.key = parsed.get<std::string>();
                if (!f.keys.insert(f.key).second) {
                    throw StructureError{path(), "duplicated key"};
                }
                break;
            }
            case E::value:
                advance();
                break;
            case E::object_end:
            case E::array_end:
                m_frames.pop_back();
                advance();
                break;
        }
        return true;
    }

private:
    struct Frame {
        bool isArray;
        std::size_t index;
        std::string key;
        std::set<std::string> keys;
    };

    void advance() {
        if (!m_frames.empty() && m_frames.back().isArray) ++m_frames.back().index;
    }

    std::string path() const {
        // Deep paths are named by their first levels only: "key[0][0][0]…".
        constexpr std::size_t kShownLevels = 4;
        std::string p;
        for (std::size_t i = 0; i < m_frames.size(); ++i) {
            const Frame& f = m_frames[i];
            if (i == kShownLevels) {
                p += "…";
                break;
            }
            if (f.isArray) {
                p += "[" + std::to_string(f.index) + "]";
            } else if (!f.key.empty()) {
                if (!p.empty()) p += '.';
                p += f.key;
            }
        }
        return p;
    }

    std::vector<Frame> m_frames;
};

std::string lineColumnOf(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// Turns nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 7: msg"
/// into {"line 3, column 7", "msg"}.
Diagnostic syntaxDiagnostic(const Json::exception& e, std::string_view text) {
    const std::string what = e.what();
    static const std::regex located(
        R"(^\[json\.exception\.[a-z_]+\.\d+\] (?:parse error )?at (line \d+, column \d+): (.*)$)");
    std::smatch m;
    if (std::regex_match(what, m, located)) return {m[1], m[2].str()};
    const std::string message = what.substr(what.find(']') + 2);
    // A number too large for a double (out_of_range.406) names the literal but not its place.
    static const std::regex overflow(R"(number overflow parsing '([^']*)')");
    if (std::regex_search(what, m, overflow)) {
        const std::size_t at = text.find(m[1].str());
        if (at != std::string_view::npos) {
            return {lineColumnOf(text, at), "number " + m[1].str() + " is too large for a double"};
        }
    }
    return {"line ?", message};
}

const char* typeName(const Json& j) {
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    if (j.is_number()) return "a number";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    return "null";
}

/// Reads typed fields out of the DOM, recording located errors instead of throwing.
class Reader {
public:
    Diagnostics errors;

    void error(const std::string& location, const std::string& message) {
        errors.push_back({location, message, Severity::Error});
    }

    const Json* field(const Json& obj, const std::string& at, const char* key, bool required) {
        const auto it = obj.find(key);
        if (it == obj.end()) {
            if (required) error(join(at, key), "missing");
            return nullptr;
        }
        return &*it;
    }

    static std::string join(const std::string& at, const char* key) {
        return at.empty() ? std::string(key) : at + "." + key;
    }

    std::optional<double> number(const Json& j, const std::string& at) {
        if (!j.is_number()) {
            error(at, std::string("must be a number (got ") + typeName(j) + ")");
            return std::nullopt;
        }
        return j.get<double>();
    }

    std::optional<double> number(const Json& obj, const std::string& at, const char* key,
                                 bool required) {
        const Json* j = field(obj, at, key, required);
        return j ? number(*j, join(at, key)) : std::nullopt;
    }

    std::optional<std::string> string(const Json& obj, const std::string& at, const char* key,
                                      bool required) {
        const Json* j = field(obj, at, key, required);
        if (!j) return std::nullopt;
        if (!j->is_string()) {
            error(join(at, key), std::string("must be a string (got ") + typeName(*j) + ")");
            return std::nullopt;
        }
        return j->get<std::string>();
    }

    std::optional<Eigen::Vector2d> point(const Json& obj, const std::string& at, const char* key,
                                         bool required) {
        const Json* j = field(obj, at, key, required);
        if (!j) return std::nullopt;
        const std::string loc = join(at, key);
        if (!j->is_array() || j->size() != 2) {
            error(loc,
                  std::string("must be an array [x, y] of two numbers (got ") +
                      (j->is_array() ? std::to_string(j->size()) + " elements" : typeName(*j)) +
                      ")");
            return std::nullopt;
        }
        const auto x = number((*j)[0], loc + "[0]");
        const auto y = number((*j)[1], loc + "[1]");
        if (!x || !y) return std::nullopt;
        return Eigen::Vector2d(*x, *y);
    }

    std::optional<std::vector<double>> numbers(const Json& obj, const std::string& at,
                                               const char* key, bool required) {
        const Json* j = field(obj, at, key, required);
        if (!j) return std::nullopt;
        const std::string loc = join(at, key);
        if (!j->is_array()) {
            error(loc, std::string("must be an array of numbers (got ") + typeName(*j) + ")");
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
            error(at, std::string("must be an object (got ") + typeName(j) + ")");
            return false;
        }
        return true;
    }

    /// Keys inside known objects must be known: a typo must not be silently ignored.
    void onlyKeys(const Json& obj, const std::string& at, std::initializer_list<const char*> keys) {
        for (const auto& [key, value] : obj.items()) {
            bool known = false;
            for (const char* k : keys) known = known || key == k;
            if (!known) error(join(at, key.c_str()), "unknown key");
        }
    }
};

struct Units {
    double length = 1.0;  // to mm
    double angle = 1.0;   // to degrees
};

void readSegment(Reader& rd, const Json& j, const std::string& at, const Units& units,
                 std::optional<double> previousEndDeg, SegmentSpec& s) {
    if (!rd.object(j, at)) return;
    const auto type = rd.string(j, at, "type", true);
    if (!type) return;
    auto window = [&](bool required) {
        const auto start = rd.number(j, at, "phi_start", required);
        const auto end = rd.number(j, at, "phi_end", required);
        if (start) s.phiStartDeg = *start * units.angle;
        if (end) s.phiEndDeg = *end * units.angle;
        return start.has_value() && end.has_value();
    };
    if (*type == "arc") {
        s.type = SegmentType::Arc;
        rd.onlyKeys(j, at, {"type", "center", "radius", "branch", "phi_start", "phi_end"});
        if (const auto c = rd.point(j, at, "center", true)) s.center = *c * units.length;
        if (const auto r = rd.number(j, at, "radius", true)) s.radius = *r * units.length;
        if (const auto b = rd.string(j, at, "branch", true)) {
            if (*b == "outer") {
                s.branch = Branch::Outer;
            } else if (*b == "inner") {
                s.branch = Branch::Inner;
            } else {
                rd.error(at + ".branch", "must be \"outer\" or \"inner\" (got \"" + *b + "\")");
            }
        }
        window(true);
    } else if (*type == "line") {
        s.type = SegmentType::Line;
        rd.onlyKeys(j, at, {"type", "from", "to", "phi_start", "phi_end"});
        const auto from = rd.point(j, at, "from", true);
        const auto to = rd.point(j, at, "to", true);
        if (from) s.from = *from * units.length;
        if (to) s.to = *to * units.length;
        const bool hasStart = j.contains("phi_start"), hasEnd = j.contains("phi_end");
        if (hasStart || hasEnd) {
            window(true);
        } else if (from && to) {
            std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, previousEndDeg.value_or(0.0));
        }
    } else if (*type == "bezier" || *type == "hermite") {
        const bool bezier = *type == "bezier";
        s.type = bezier ? SegmentType::Bezier : SegmentType::Hermite;
        bool complete = true;
        if (bezier) {
            rd.onlyKeys(j, at, {"type", "points", "phi_start", "phi_end"});
            if (const Json* pts = rd.field(j, at, "points", true)) {
                if (!pts->is_array() || pts->size() != 4) {
                    rd.error(at + ".points", "must be an array of four points [x, y]");
                    complete = false;
                } else {
                    for (std::size_t i = 0; i < 4; ++i) {
                        Json holder = Json::object();
                        holder["p"] = (*pts)[i];
                        const auto p =
                            rd.point(holder, at + ".points[" + std::to_string(i) + "]", "p", true);
                        // rd.point names "…points[i].p"; the located message is clear enough.
                        if (p) {
                            s.controls[i] = *p * units.length;
                        } else {
                            complete = false;
                        }
                    }
                }
            } else {
                complete = false;
            }
        } else {
            rd.onlyKeys(j, at, {"type", "p0", "t0", "p3", "t1", "phi_start", "phi_end"});
            const char* keys[] = {"p0", "t0", "p3", "t1"};
            for (std::size_t i = 0; i < 4; ++i) {
                if (const auto p = rd.point(j, at, keys[i], true)) {
                    s.controls[i] = *p * units.length;
                } else {
                    complete = false;
                }
            }
        }
        const bool hasWindow = j.contains("phi_start") || j.contains("phi_end");
        if (hasWindow) {
            window(true);
        } else if (complete) {
            std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, previousEndDeg.value_or(0.0));
        }
    } else {
        rd.error(at + ".type", "unknown segment type \"" + *type +
                                   "\" (expected \"arc\", \"line\", \"bezier\" or \"hermite\")");
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
        rd.error("motion", "must give exactly one of omega_rad_s, rpm, period_s (got " +
                               std::to_string(given) + ")");
    }
}

void readFollower(Reader& rd, const Json& root, const Units& units, Project& p) {
    const Json* f = rd.field(root, "", "follower", false);
    if (!f || !rd.object(*f, "follower")) return;
    rd.onlyKeys(*f, "follower", {"type", "offset", "radius"});
    FollowerSpec spec;
    if (const auto type = rd.string(*f, "follower", "type", false)) {
        if (*type == "knife") {
            spec.type = FollowerType::Knife;
        } else if (*type == "roller") {
            spec.type = FollowerType::Roller;
        } else if (*type == "flat") {
            spec.type = FollowerType::Flat;
        } else {
            rd.error("follower.type",
                     "must be \"knife\", \"roller\" or \"flat\" (got \"" + *type + "\")");
        }
    }
    if (const auto v = rd.number(*f, "follower", "offset", false)) spec.offset = *v * units.length;
    const bool needsRadius = spec.type == FollowerType::Roller;
    if (const auto v = rd.number(*f, "follower", "radius", needsRadius)) {
        spec.radius = *v * units.length;
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
        rd.error("sampling.samples_per_turn",
                 "must be a whole number between 16 and 10000000 (got " + formatNumber(*n) + ")");
        return;
    }
    p.samplesPerTurn = static_cast<std::int64_t>(*n);
}

void readMachining(Reader& rd, const Json& root, const Units& units, Project& p) {
    const Json* m = rd.field(root, "", "machining", false);
    if (!m || !rd.object(*m, "machining")) return;
    const std::string at = "machining";
    rd.onlyKeys(*m, at, {"axis_accel", "axis_vmax", "feed_max", "tool_radius", "step"});
    MachiningSpec spec;
    auto scaled = [&](std::vector<double> v) {
        for (double& x : v) x *= units.length;
        return v;
    };
    if (const auto v = rd.numbers(*m, at, "axis_accel", true)) spec.axisAccel = scaled(*v);
    if (const auto v = rd.numbers(*m, at, "axis_vmax", false)) spec.axisVmax = scaled(*v);
    if (const auto v = rd.number(*m, at, "feed_max", true)) spec.feedMax = *v * units.length;
    if (const auto v = rd.number(*m, at, "tool_radius", false)) spec.toolRadius = *v * units.length;
    if (const auto v = rd.number(*m, at, "step", false)) spec.step = *v * units.length;
    p.machining = spec;
}

Result<Project> readProject(const Json& root) {
    Reader rd;
    if (!root.is_object()) {
        rd.error("(top level)", std::string("must be an object (got ") + typeName(root) + ")");
        return rd.errors;
    }
    const auto format = rd.string(root, "", "format", true);
    if (format && *format != "camwright") {
        rd.error("format", "must be \"camwright\" (got \"" + *format + "\")");
    }
    if (const Json* v = rd.field(root, "", "version", true)) {
        if (!v->is_number_integer()) {
            rd.error("version", std::string("must be a whole number (got ") +
                                    (v->is_number() ? v->dump() : typeName(*v)) + ")");
        } else if (v->get<std::int64_t>() > kProjectFormatVersion) {
            rd.error("version", "this file has format version " + v->dump() +
                                    "; this Camwright reads version 1 only — open it with a "
                                    "newer Camwright");
        } else if (v->get<std::int64_t>() < 1) {
            rd.error("version", "must be 1 (got " + v->dump() + ")");
        }
    }
    if (hasErrors(rd.errors)) return rd.errors;  // not a Camwright v1 file: say only that

    Project p;
    if (const auto name = rd.string(root, "", "name", false)) p.name = *name;

    Units units;
    if (const Json* u = rd.field(root, "", "units", false); u && rd.object(*u, "units")) {
        rd.onlyKeys(*u, "units", {"length", "angle"});
        if (const auto length = rd.string(*u, "units", "length", false)) {
            if (*length == "m") {
                units.length = 1000.0;
            } else if (*length != "mm") {
                rd.error("units.length", "must be \"mm\" or \"m\" (got \"" + *length + "\")");
            }
        }
        if (const auto angle = rd.string(*u, "units", "angle", false)) {
            if (*angle == "rad") {
                units.angle = 180.0 / kPi;
            } else if (*angle != "deg") {
                rd.error("units.angle", "must be \"deg\" or \"rad\" (got \"" + *angle + "\")");
            }
        }
    }

    readMotion(rd, root, p);

    if (const Json* c = rd.field(root, "", "contour", true)) {
        if (!c->is_array()) {
            rd.error("contour",
                     std::string("must be an array of segments (got ") + typeName(*c) + ")");
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

    static const std::set<std::string> known{"format",   "version",  "name",
                                             "units",    "motion",   "contour",
                                             "follower", "sampling", "machining"};
    for (const auto& [key, value] : root.items()) {
        if (!known.contains(key)) p.extraKeys.emplace_back(key, value.dump());
    }

    if (hasErrors(rd.errors)) return rd.errors;
    Diagnostics semantic = validateProject(p);
    if (hasErrors(semantic)) return semantic;
    return p;
}

Json point(const Eigen::Vector2d& p) { return Json::array({p.x(), p.y()}); }

}  // namespace

Result<Project> parseProject(std::string_view text) {
    Json root;
    try {
        root = Json::parse(text.begin(), text.end(), PathTracker{});
    } catch (const StructureError& e) {
        return Diagnostics{{e.location.empty() ? "(top level)" : e.location, e.message}};
    } catch (const Json::exception& e) {
        return Diagnostics{syntaxDiagnostic(e, text)};
    }
    return readProject(root);
}

Result<std::string> readTextFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return Diagnostics{{path, "is a folder, not a file"}};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Diagnostics{{path, std::string("cannot open: ") + std::strerror(errno)}};
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return Diagnostics{{path, "read error"}};
    return buffer.str();
}

Result<Project> loadProjectFile(const std::string& path) {
    auto text = readTextFile(path);
    if (!text.ok()) return text.errors();
    return parseProject(text.value());
}

std::string serializeProject(const Project& p) {
    Json root;
    root["format"] = "camwright";
    root["version"] = kProjectFormatVersion;
    root["name"] = p.name;
    root["units"] = {{"length", "mm"}, {"angle", "deg"}};
    const char* speedKey = p.motion.unit == SpeedUnit::OmegaRadS ? "omega_rad_s"
                           : p.motion.unit == SpeedUnit::Rpm     ? "rpm"
                                                                 : "period_s";
    root["motion"] = {{speedKey, p.motion.value}};
    Json contour = Json::array();
    for (const SegmentSpec& s : p.contour) {
        Json j;
        if (s.type == SegmentType::Arc) {
            j["type"] = "arc";
            j["center"] = point(s.center);
            j["radius"] = s.radius;
            j["branch"] = s.branch == Branch::Outer ? "outer" : "inner";
        } else if (s.type == SegmentType::Line) {
            j["type"] = "line";
            j["from"] = point(s.from);
            j["to"] = point(s.to);
        } else if (s.type == SegmentType::Bezier) {
            j["type"] = "bezier";
            j["points"] = Json::array({point(s.controls[0]), point(s.controls[1]),
                                       point(s.controls[2]), point(s.controls[3])});
        } else {
            j["type"] = "hermite";
            j["p0"] = point(s.controls[0]);
            j["t0"] = point(s.controls[1]);
            j["p3"] = point(s.controls[2]);
            j["t1"] = point(s.controls[3]);
        }
        j["phi_start"] = s.phiStartDeg;
        j["phi_end"] = s.phiEndDeg;
        contour.push_back(std::move(j));
    }
    root["contour"] = std::move(contour);
    if (p.follower) {
        const FollowerSpec& f = *p.follower;
        Json j;
        j["type"] = f.type == FollowerType::Knife    ? "knife"
                    : f.type == FollowerType::Roller ? "roller"
                                                     : "flat";
        j["offset"] = f.offset;
        if (f.type == FollowerType::Roller) j["radius"] = f.radius;
        root["follower"] = std::move(j);
    }
    if (p.samplesPerTurn) root["sampling"] = {{"samples_per_turn", *p.samplesPerTurn}};
    if (p.machining) {
        const MachiningSpec& m = *p.machining;
        Json j;
        j["axis_accel"] = m.axisAccel;
        if (!m.axisVmax.empty()) j["axis_vmax"] = m.axisVmax;
        j["feed_max"] = m.feedMax;
        j["tool_radius"] = m.toolRadius;
        j["step"] = m.step;
        root["machining"] = std::move(j);
    }
    for (const auto& [key, text] : p.extraKeys) root[key] = Json::parse(text);
    return root.dump(2) + "\n";
}

}  // namespace cam
