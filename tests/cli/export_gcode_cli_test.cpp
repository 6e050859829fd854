// camwright-cli export --format gcode, checked by LinuxCNC's own interpreter: rs274 runs every
// program, and the path it would cut (its canonical STRAIGHT_FEED / ARC_FEED, 4 decimals) is
// compared with the exact profile, computed here from the project file's segments: arcs and
// lines in closed form, Bézier and Hermite curves by a refined search. Nothing of the core's
// geometry is used to judge the result.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "contour/contour.h"
#include "export/gcode.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

namespace fs = std::filesystem;
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;
/// rs274 prints 4 decimals: the precision to which the cut path is known.
constexpr double kTolMm = 1e-4;
/// Cut moves and the profile are checked at points this far apart, mm (arcs and lines: their
/// distance from the profile varies smoothly between them).
constexpr double kSampleStepMm = 0.05;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
Vec2 perp(const Vec2& v) { return {-v.y(), v.x()}; }
Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
/// The angle from `from` to `to` turning the way `sign` says, in [0, 2π).
double turnFrom(double from, double to, double sign) {
    double a = std::fmod(sign >= 0 ? to - from : from - to, 2 * kPi);
    return a < 0 ? a + 2 * kPi : a;
}

double distanceToSegment(const Vec2& q, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double u = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (q - (a + u * d)).norm();
}

// ---- The exact profile, from the project file ------------------------------------------------

/// One segment of the profile as the part has it, traversed with increasing polar angle.
struct Piece {
    enum Kind { Line, Arc, Bezier } kind = Line;
    Vec2 a{0, 0}, b{0, 0};  // start and end
    // Arc: centre, radius, polar angle of `a` about the centre, signed sweep.
    Vec2 c{0, 0};
    double r = 0, a0 = 0, sweep = 0;
    std::array<Vec2, 4> p{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};  // Bézier

    [[nodiscard]] Vec2 bezier(double t) const {
        const double s = 1 - t;
        return s * s * s * p[0] + 3 * s * s * t * p[1] + 3 * s * t * t * p[2] + t * t * t * p[3];
    }
    [[nodiscard]] Vec2 bezierDerivative(double t) const {
        const double s = 1 - t;
        return 3 * s * s * (p[1] - p[0]) + 6 * s * t * (p[2] - p[1]) + 3 * t * t * (p[3] - p[2]);
    }
    /// The point at u in [0, 1] along the piece.
    [[nodiscard]] Vec2 at(double u) const {
        if (kind == Line) return a + u * (b - a);
        if (kind == Arc) return c + r * unit(a0 + u * sweep);
        return bezier(u);
    }
    /// The unit tangent (direction of travel) at u.
    [[nodiscard]] Vec2 tangent(double u) const {
        if (kind == Line) return (b - a).normalized();
        if (kind == Arc) return (sweep > 0 ? 1.0 : -1.0) * perp(unit(a0 + u * sweep));
        return bezierDerivative(u).normalized();
    }
    [[nodiscard]] double length() const {
        if (kind == Line) return (b - a).norm();
        if (kind == Arc) return r * std::abs(sweep);
        double total = 0;
        for (int i = 0; i < 1000; ++i)
            total += (bezier((i + 1) / 1000.0) - bezier(i / 1000.0)).norm();
        return total;
    }
    // A Bézier's points at 256 equal parameter steps, and the box of its control points (which
    // holds the curve).
    std::vector<Vec2> coarse;
    Vec2 boxLo{0, 0}, boxHi{0, 0};

    /// The distance from q: closed forms for lines and arcs; on a Bézier the nearest of its
    /// coarse points, refined by a golden-section search between its neighbours. A Bézier whose
    /// box is `bound` or farther away returns `bound`.
    [[nodiscard]] double distance(const Vec2& q,
                                  double bound = std::numeric_limits<double>::infinity()) const {
        if (kind == Line) return distanceToSegment(q, a, b);
        if (kind == Arc) {
            const Vec2 w = q - c;
            const double along = turnFrom(a0, std::atan2(w.y(), w.x()), sweep);
            if (along <= std::abs(sweep)) return std::abs(w.norm() - r);
            return std::min((q - a).norm(), (q - b).norm());
        }
        if ((q.cwiseMax(boxLo).cwiseMin(boxHi) - q).norm() >= bound) return bound;
        const int n = static_cast<int>(coarse.size()) - 1;
        int best = 0;
        double bestD = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= n; ++i) {
            const double dx = coarse[i].x() - q.x(), dy = coarse[i].y() - q.y();
            if (dx * dx + dy * dy < bestD) bestD = dx * dx + dy * dy, best = i;
        }
        double lo = std::max(0, best - 1) / double(n), hi = std::min(n, best + 1) / double(n);
        const double g = (std::sqrt(5.0) - 1) / 2;
        for (int it = 0; it < 50; ++it) {
            const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
            if ((bezier(m1) - q).squaredNorm() < (bezier(m2) - q).squaredNorm()) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        return std::min(std::sqrt(bestD), (bezier((lo + hi) / 2) - q).norm());
    }
};

struct Profile {
    std::vector<Piece> pieces;
    std::vector<Vec2> polygon;  // dense, for inside/outside
    struct Corner {
        Vec2 point;
        double turn;  // rad, < 0: concave
    };
    std::vector<Corner> concave;

    [[nodiscard]] double distance(const Vec2& q) const {
        double d = std::numeric_limits<double>::infinity();
        for (const Piece& p : pieces) {
            if (p.kind != Piece::Bezier) d = std::min(d, p.distance(q));
        }
        for (const Piece& p : pieces) {
            if (p.kind == Piece::Bezier) d = std::min(d, p.distance(q, d));
        }
        return d;
    }
    /// Winding number of the profile round q: 0 outside the part.
    [[nodiscard]] int winding(const Vec2& q) const {
        int w = 0;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const Vec2& a = polygon[i];
            const Vec2& b = polygon[(i + 1) % polygon.size()];
            if (a.y() <= q.y()) {
                if (b.y() > q.y() && cross(b - a, q - a) > 0) ++w;
            } else if (b.y() <= q.y() && cross(b - a, q - a) < 0) {
                --w;
            }
        }
        return w;
    }
};

/// The profile of a project file (mm or m, degrees or radians).
Profile profileOf(const nlohmann::json& project) {
    const nlohmann::json units = project.value("units", nlohmann::json::object());
    const double mm = units.value("length", "mm") == "m" ? 1000.0 : 1.0;
    const double rad = units.value("angle", "deg") == "rad" ? 1.0 : kPi / 180.0;
    auto point = [&](const nlohmann::json& j) -> Vec2 {
        return Vec2(j[0].get<double>(), j[1].get<double>()) * mm;
    };
    Profile profile;
    for (const auto& s : project.at("contour")) {
        Piece piece;
        const std::string type = s.at("type");
        if (type == "line") {
            piece.a = point(s.at("from"));
            piece.b = point(s.at("to"));
        } else if (type == "arc") {
            piece.kind = Piece::Arc;
            piece.c = point(s.at("center"));
            piece.r = s.at("radius").get<double>() * mm;
            const double sign = s.at("branch") == "outer" ? 1.0 : -1.0;
            // Where the ray at phi meets the circle: |t·u − c| = R, the far or near root.
            auto hit = [&](double phi) {
                const Vec2 u = unit(phi);
                const double mu = u.dot(piece.c);
                const double disc = mu * mu - piece.c.squaredNorm() + piece.r * piece.r;
                return Vec2((mu + sign * std::sqrt(std::max(disc, 0.0))) * u);
            };
            const double p0 = s.at("phi_start").get<double>() * rad;
            const double p1 = s.at("phi_end").get<double>() * rad;
            piece.a = hit(p0);
            piece.b = hit(p1);
            auto angle = [&](const Vec2& q) {
                return std::atan2(q.y() - piece.c.y(), q.x() - piece.c.x());
            };
            piece.a0 = angle(piece.a);
            // The way round that passes the window's middle.
            double ccw = turnFrom(piece.a0, angle(piece.b), 1.0);
            if (ccw < 1e-12) ccw = 2 * kPi;  // a full circle
            const double mid = turnFrom(piece.a0, angle(hit((p0 + p1) / 2)), 1.0);
            piece.sweep = mid < ccw ? ccw : ccw - 2 * kPi;
        } else {
            piece.kind = Piece::Bezier;
            if (type == "bezier") {
                for (int i = 0; i < 4; ++i) piece.p[i] = point(s.at("points")[i]);
            } else {  // hermite
                piece.p[0] = point(s.at("p0"));
                piece.p[3] = point(s.at("p3"));
                piece.p[1] = piece.p[0] + point(s.at("t0")) / 3.0;
                piece.p[2] = piece.p[3] - point(s.at("t1")) / 3.0;
            }
            piece.a = piece.p[0];
            piece.b = piece.p[3];
            for (int i = 0; i <= 256; ++i) piece.coarse.push_back(piece.bezier(i / 256.0));
            piece.boxLo = piece.boxHi = piece.p[0];
            for (const Vec2& c : piece.p) {
                piece.boxLo = piece.boxLo.cwiseMin(c);
                piece.boxHi = piece.boxHi.cwiseMax(c);
            }
        }
        profile.pieces.push_back(piece);
    }
    const std::size_t n = profile.pieces.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Piece& left = profile.pieces[k];
        const Piece& right = profile.pieces[(k + 1) % n];
        // The test's own model closes: each piece ends where the next begins.
        EXPECT_LT((left.b - right.a).norm(), 1e-6) << "profile model: gap after piece " << k;
        const Vec2 t0 = left.tangent(1.0), t1 = right.tangent(0.0);
        const double turn = std::atan2(cross(t0, t1), t0.dot(t1));
        if (turn < -1e-6) profile.concave.push_back({left.b, turn});
        const int samples = left.kind == Piece::Line ? 1 : 256;
        for (int i = 0; i < samples; ++i) profile.polygon.push_back(left.at(double(i) / samples));
    }
    return profile;
}

// ---- rs274's canonical path ------------------------------------------------------------------

/// One move of the canonical output, from the previous position.
struct CanonMove {
    bool feed = false;
    bool arc = false;
    Vec3 start{0, 0, 0}, end{0, 0, 0};
    Vec2 centre{0, 0};
    int rotation = 0;  // +1 counter-clockwise, -1 clockwise

    [[nodiscard]] bool planar() const { return start.z() == end.z(); }
    [[nodiscard]] double sweep() const {
        const Vec2 s = start.head<2>() - centre, e = end.head<2>() - centre;
        double a = turnFrom(std::atan2(s.y(), s.x()), std::atan2(e.y(), e.x()), rotation);
        if (a < 1e-9) a = 2 * kPi;
        return rotation * a;
    }
    /// The point at u in [0, 1]; an arc's radius goes linearly from start to end, as the
    /// interpreter moves when the two differ by the rounding.
    [[nodiscard]] Vec2 at(double u) const {
        if (!arc) return (start + u * (end - start)).head<2>();
        const Vec2 s = start.head<2>() - centre, e = end.head<2>() - centre;
        const double r = s.norm() + u * (e.norm() - s.norm());
        return centre + r * unit(std::atan2(s.y(), s.x()) + u * sweep());
    }
    [[nodiscard]] Vec2 tangent(double u) const {
        if (!arc) return (end - start).head<2>().normalized();
        const Vec2 s = start.head<2>() - centre;
        return rotation * perp(unit(std::atan2(s.y(), s.x()) + u * sweep()));
    }
    [[nodiscard]] double length() const {
        if (!arc) return (end - start).head<2>().norm();
        return (start.head<2>() - centre).norm() * std::abs(sweep());
    }
    [[nodiscard]] double distance(const Vec2& q) const {
        if (!arc) return distanceToSegment(q, start.head<2>(), end.head<2>());
        const Vec2 s = start.head<2>() - centre, w = q - centre;
        const double along = turnFrom(std::atan2(s.y(), s.x()), std::atan2(w.y(), w.x()), rotation);
        const double total = std::abs(sweep());
        if (along <= total) return std::abs(w.norm() - (at(along / total) - centre).norm());
        return std::min((q - start.head<2>()).norm(), (q - end.head<2>()).norm());
    }
    /// Points every `step` mm along the move, both ends included.
    [[nodiscard]] std::vector<Vec2> samples(double step) const {
        const int n = std::max(16, static_cast<int>(std::ceil(length() / step)));
        std::vector<Vec2> out;
        for (int i = 0; i <= n; ++i) out.push_back(at(double(i) / n));
        return out;
    }
};

std::vector<double> argumentsOf(const std::string& line, const std::string& name) {
    std::vector<double> values;
    std::istringstream in(line.substr(line.find(name + "(") + name.size() + 1));
    std::string cell;
    while (std::getline(in, cell, ',')) values.push_back(std::stod(cell));
    return values;
}

std::vector<CanonMove> parseCanon(const std::string& text) {
    std::vector<CanonMove> moves;
    Vec3 at(0, 0, 0);  // rs274 starts at the origin
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        CanonMove m;
        m.start = at;
        if (line.find("STRAIGHT_TRAVERSE(") != std::string::npos ||
            line.find("STRAIGHT_FEED(") != std::string::npos) {
            const bool feed = line.find("STRAIGHT_FEED(") != std::string::npos;
            const auto v = argumentsOf(line, feed ? "STRAIGHT_FEED" : "STRAIGHT_TRAVERSE");
            m.feed = feed;
            m.end = Vec3(v[0], v[1], v[2]);
        } else if (line.find("ARC_FEED(") != std::string::npos) {
            // ARC_FEED(x end, y end, x centre, y centre, rotation, z end, a, b, c)
            const auto v = argumentsOf(line, "ARC_FEED");
            m.feed = m.arc = true;
            m.end = Vec3(v[0], v[1], v[5]);
            m.centre = Vec2(v[2], v[3]);
            m.rotation = static_cast<int>(v[4]);
            EXPECT_TRUE(m.rotation == 1 || m.rotation == -1) << line;
        } else {
            continue;
        }
        moves.push_back(m);
        at = m.end;
    }
    return moves;
}

// ---- Running the export and the interpreter --------------------------------------------------

struct Milled {
    std::string program;
    std::vector<CanonMove> moves;
};

/// Runs rs274 on a program; failures are test failures. `toolTable`: the radius of tool 1 in
/// the machine's tool table, for cutter compensation. The wrapper's table gives tool 1 "D6.0",
/// which rs274 reads in inches (a 76.2 mm radius); a `G10 L1 P1 R…` after the program's units
/// line stands in for the operator's table.
Milled interpret(const test::TempDir& dir, const std::string& program,
                 std::optional<double> toolTable = std::nullopt) {
    const std::string ngc = dir.file("interpreted.ngc"), canon = dir.file("canon.txt");
    Milled m;
    m.program = program;
    std::string interpreted = ngc;
    std::ofstream(ngc) << program;
    if (toolTable) {
        const auto units = m.program.find("\nG21 ");
        EXPECT_NE(units, std::string::npos);
        const auto lineEnd = m.program.find('\n', units + 1);
        interpreted = dir.file("cam-with-tool-table.ngc");
        std::ofstream(interpreted)
            << m.program.substr(0, lineEnd + 1) << "G10 L1 P1 R" << *toolTable << "\n"
            << m.program.substr(lineEnd + 1);
    }
    fs::remove(canon);
    const auto r = test::run(test::kRs274, {interpreted, canon}, 120);
    EXPECT_EQ(r.exitCode, 0) << "rs274 refused the program: " << r.err << "\n" << m.program;
    m.moves = parseCanon(test::readFile(canon));
    return m;
}

/// Exports `project` with the options and runs rs274 on the program.
Milled exportAndInterpret(const test::TempDir& dir, const std::string& project,
                          const std::vector<std::string>& options,
                          std::optional<double> toolTable = std::nullopt) {
    const std::string ngc = dir.file("cam.ngc");
    fs::remove(ngc);
    std::vector<std::string> args{"export", project, "--format", "gcode", "--out", ngc};
    args.insert(args.end(), options.begin(), options.end());
    const auto exported = test::runCli(args);
    EXPECT_EQ(exported.exitCode, 0) << exported.err;
    return interpret(dir, test::readFile(ngc), toolTable);
}

/// The cutting moves of each pass: runs of feed moves in the plane at one height below Z0.
struct Pass {
    double z = 0;
    std::vector<CanonMove> moves;
    std::optional<CanonMove> plunge;
};

std::vector<Pass> passesOf(const std::vector<CanonMove>& moves) {
    std::vector<Pass> passes;
    std::optional<CanonMove> plunge;
    bool inPass = false;
    for (const CanonMove& m : moves) {
        if (m.feed && !m.planar()) {
            EXPECT_EQ(m.start.head<2>(), m.end.head<2>()) << "a feed move that is not a plunge";
            plunge = m;
            inPass = false;
            continue;
        }
        if (!m.feed) {
            inPass = false;
            continue;
        }
        if (!inPass) {
            passes.push_back({m.end.z(), {}, plunge});
            inPass = true;
        }
        passes.back().moves.push_back(m);
    }
    return passes;
}

struct Expect {
    double toolRadius = 0;
    /// Moves of a pass before the loop (lead-in arc; under compensation also the entry line) and
    /// after it.
    int leadMoves = 1;
    bool clockwise = true;  // climb milling
    /// How far the loop may be from the tool radius off the profile: rs274's print precision,
    /// plus the spline tolerance where that is coarser than the default.
    double within = kTolMm;
};

/// The checks of exports.md on one pass: (a) every cutting point is outside the part and at
/// least the tool radius from the profile, every point of the loop exactly that (to 1e-4 mm);
/// (b) every profile point is within the tool radius of the loop (but in the shadow of a concave
/// corner, which a round tool cannot reach); (c) the loop closes; the leads are tangent arcs.
void checkPass(const Pass& pass, const Profile& profile, const Expect& e, const std::string& what) {
    SCOPED_TRACE(what + ", pass at Z" + std::to_string(pass.z));
    ASSERT_GT(static_cast<int>(pass.moves.size()), 2 * e.leadMoves);
    const double rho = e.toolRadius;
    double worstGouge = 0, worstLoop = 0;
    int inside = 0;
    std::vector<Vec2> loopPoints;
    for (std::size_t i = 0; i < pass.moves.size(); ++i) {
        const bool loop = static_cast<int>(i) >= e.leadMoves &&
                          static_cast<int>(i) < static_cast<int>(pass.moves.size()) - e.leadMoves;
        for (const Vec2& q : pass.moves[i].samples(kSampleStepMm)) {
            const double d = profile.distance(q);
            worstGouge = std::max(worstGouge, rho - d);
            if (profile.winding(q) != 0) ++inside;
            if (loop) {
                worstLoop = std::max(worstLoop, std::abs(d - rho));
                loopPoints.push_back(q);
            }
        }
    }
    EXPECT_LE(worstGouge, e.within) << "the tool cuts into the profile";
    EXPECT_EQ(inside, 0) << "cutting points inside the part";
    EXPECT_LE(worstLoop, e.within) << "the loop is not the tool radius from the profile";
    if (pass.plunge) {
        EXPECT_GE(profile.distance(pass.plunge->end.head<2>()), rho) << "plunge too close";
        EXPECT_EQ(profile.winding(pass.plunge->end.head<2>()), 0) << "plunge inside the part";
    }

    // (c) The loop closes, and the lead arcs join it tangentially.
    const CanonMove& leadIn = pass.moves[e.leadMoves - 1];
    const CanonMove& first = pass.moves[e.leadMoves];
    const CanonMove& last = pass.moves[pass.moves.size() - e.leadMoves - 1];
    const CanonMove& leadOut = pass.moves[pass.moves.size() - e.leadMoves];
    EXPECT_LE((first.start - last.end).norm(), kTolMm) << "the loop does not close";
    EXPECT_TRUE(leadIn.arc && leadOut.arc) << "lead-in and lead-out are arcs";
    EXPECT_LT((leadIn.tangent(1) - first.tangent(0)).norm(), 1e-3) << "lead-in not tangent";
    EXPECT_LT((last.tangent(1) - leadOut.tangent(0)).norm(), 1e-3) << "lead-out not tangent";

    // Direction: the signed area of the loop.
    double area = 0;
    for (std::size_t i = 0; i < loopPoints.size(); ++i) {
        area += cross(loopPoints[i], loopPoints[(i + 1) % loopPoints.size()]) / 2;
    }
    EXPECT_EQ(area < 0, e.clockwise) << "signed area " << area;

    // (b) Every profile point is reached: within the tool radius of some loop move.
    std::vector<const CanonMove*> loopMoves;
    for (std::size_t i = e.leadMoves; i + e.leadMoves < pass.moves.size(); ++i) {
        loopMoves.push_back(&pass.moves[i]);
    }
    int unreached = 0;
    double worstReach = 0;
    for (const Piece& piece : profile.pieces) {
        const int n = std::max(50, static_cast<int>(piece.length() / kSampleStepMm));
        for (int i = 0; i <= n; ++i) {
            const Vec2 q = piece.at(double(i) / n);
            double d = std::numeric_limits<double>::infinity();
            for (const CanonMove* m : loopMoves) d = std::min(d, m->distance(q));
            // A round tool touching both sides of a concave corner (turn β) touches straight
            // sides ρ·tan(β/2) from it; twice that, and at least ρ, allows for curved sides.
            bool shadow = false;
            for (const auto& c : profile.concave) {
                shadow |= (q - c.point).norm() <= rho * std::max(1.0, 2 * std::tan(-c.turn / 2));
            }
            if (shadow) continue;
            worstReach = std::max(worstReach, d - rho);
            if (d > rho + e.within) ++unreached;
        }
    }
    EXPECT_EQ(unreached, 0) << "profile points the tool does not reach; worst by " << worstReach;
    ::testing::Test::RecordProperty("worst_" + what,
                                    std::to_string(std::max({worstGouge, worstLoop, worstReach})));
}

/// Every pass of a program checked against the profile; the Z levels are returned.
std::vector<double> checkProgram(const Milled& milled, const Profile& profile, const Expect& e,
                                 const std::string& what) {
    std::istringstream lines(milled.program);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '(') continue;
        EXPECT_EQ(line.find('R'), std::string::npos) << "an R-format arc: " << line;
    }
    const std::vector<Pass> passes = passesOf(milled.moves);
    EXPECT_FALSE(passes.empty());
    std::vector<double> levels;
    for (const Pass& p : passes) {
        checkPass(p, profile, e, what);
        levels.push_back(p.z);
    }
    return levels;
}

Profile profileOfFile(const std::string& path) {
    return profileOf(nlohmann::json::parse(test::readFile(path)));
}

std::string writeProject(const test::TempDir& dir, const std::string& name,
                         const std::string& json) {
    const std::string path = dir.file(name);
    std::ofstream(path) << json;
    return path;
}

// Hand-made cams. A convex cam of three outer arcs meeting at corners (the intersection of three
// discs of radius 30 whose centres lie 10 mm from the rotation centre).
constexpr const char* kThreeArcs =
    R"json({"format": "camwright", "version": 1, "name": "Three arcs",
  "motion": {"period_s": 1}, "contour": [
  {"type": "arc", "center": [-10, 0], "radius": 30, "branch": "outer",
   "phi_start": -60, "phi_end": 60},
  {"type": "arc", "center": [5, -8.660254037844386], "radius": 30, "branch": "outer",
   "phi_start": 60, "phi_end": 180},
  {"type": "arc", "center": [5, 8.660254037844386], "radius": 30, "branch": "outer",
   "phi_start": 180, "phi_end": 300}]})json";

// One eccentric circle: the whole contour is one arc.
constexpr const char* kCircle =
    R"json({"format": "camwright", "version": 1, "name": "Circle (one arc)",
  "motion": {"period_s": 1}, "machining": {"axis_accel": [500, 500, 200], "tool_radius": 4, "feed_max": 20},
  "contour": [{"type": "arc", "center": [3, -2], "radius": 20, "branch": "outer",
               "phi_start": 0, "phi_end": 360}]})json";

// Lines and concave (inner-branch) arcs: a diamond whose upper-left and lower-right sides are
// dented arcs of radius sqrt(650) round centres outside the part.
constexpr const char* kDentedDiamond = R"json({"format": "camwright", "version": 1,
  "name": "Dented diamond (lines, inner arcs)", "motion": {"period_s": 1}, "contour": [
  {"type": "line", "from": [20, 0], "to": [0, 20]},
  {"type": "arc", "center": [-25, 25], "radius": 25.495097567963924, "branch": "inner",
   "phi_start": 90, "phi_end": 180},
  {"type": "line", "from": [-20, 0], "to": [0, -20]},
  {"type": "arc", "center": [25, -25], "radius": 25.495097567963924, "branch": "inner",
   "phi_start": 270, "phi_end": 360}]})json";

// Concave corners: a four-pointed star of lines (points 30 mm out, inner corners 15 mm).
constexpr const char* kStar = R"json({"format": "camwright", "version": 1, "name": "Star",
  "motion": {"period_s": 1}, "contour": [
  {"type": "line", "from": [30, 0], "to": [10.606601717798213, 10.606601717798213]},
  {"type": "line", "from": [10.606601717798213, 10.606601717798213], "to": [0, 30]},
  {"type": "line", "from": [0, 30], "to": [-10.606601717798213, 10.606601717798213]},
  {"type": "line", "from": [-10.606601717798213, 10.606601717798213], "to": [-30, 0]},
  {"type": "line", "from": [-30, 0], "to": [-10.606601717798213, -10.606601717798213]},
  {"type": "line", "from": [-10.606601717798213, -10.606601717798213], "to": [0, -30]},
  {"type": "line", "from": [0, -30], "to": [10.606601717798213, -10.606601717798213]},
  {"type": "line", "from": [10.606601717798213, -10.606601717798213], "to": [30, 0]}]})json";

TEST(CliExportGcode, SixLobeExampleIsMilledAtTheToolRadius) {
    const test::TempDir dir;
    const std::string project = test::examplePath("six-lobe-arc-cam.cam.json");
    const Milled m = exportAndInterpret(dir, project, {"--tool-radius", "3", "--depth", "4"});
    const auto levels = checkProgram(m, profileOfFile(project), {3.0}, "six-lobe");
    EXPECT_EQ(levels, std::vector<double>{-4.0});
}

TEST(CliExportGcode, ConvexArcCamRollsRoundItsCorners) {
    const test::TempDir dir;
    const std::string project = writeProject(dir, "three.cam.json", kThreeArcs);
    const Milled m = exportAndInterpret(dir, project, {"--tool-radius", "2.5"});
    checkProgram(m, profileOfFile(project), {2.5}, "three arcs");
}

TEST(CliExportGcode, OneArcCircleIsMilledInHalves) {
    const test::TempDir dir;
    const std::string project = writeProject(dir, "circle.cam.json", kCircle);
    // The tool radius and feed come from the project's machining section.
    const Milled m = exportAndInterpret(dir, project, {});
    checkProgram(m, profileOfFile(project), {4.0}, "circle");
    EXPECT_NE(m.program.find("F1200.000"), std::string::npos) << "feed_max 20 mm/s";
    const auto passes = passesOf(m.moves);
    ASSERT_EQ(passes.size(), 1u);
    // lead-in, two halves of the circle (its top is where the loop starts), lead-out.
    EXPECT_EQ(passes[0].moves.size(), 4u);
}

TEST(CliExportGcode, LinesAndConcaveArcs) {
    const test::TempDir dir;
    const std::string project = writeProject(dir, "diamond.cam.json", kDentedDiamond);
    const Milled m = exportAndInterpret(dir, project, {"--tool-radius", "3"});
    checkProgram(m, profileOfFile(project), {3.0}, "dented diamond");
    // A notch (a concave arc of radius 9 mm between convex corners) and a flat, in metres.
    const std::string notch = test::dataPath("reference/notch-flat.cam.json");
    checkProgram(exportAndInterpret(dir, notch, {"--tool-radius", "4"}), profileOfFile(notch),
                 {4.0}, "notch-flat");
}

TEST(CliExportGcode, ConcaveCornersKeepTheToolOutOfBothSides) {
    const test::TempDir dir;
    const std::string project = writeProject(dir, "star.cam.json", kStar);
    const Profile profile = profileOfFile(project);
    EXPECT_EQ(profile.concave.size(), 4u);
    checkProgram(exportAndInterpret(dir, project, {"--tool-radius", "3"}), profile, {3.0}, "star");
}

TEST(CliExportGcode, SplineCamsWithinTheDefaultTolerance) {
    const test::TempDir dir;
    for (const char* name : {"reference/spline-mix.cam.json", "reference/spline-offset.cam.json"}) {
        const std::string project = test::dataPath(name);
        const Profile profile = profileOfFile(project);
        // Concave corners next to splines: the offset arcs are cut pieces away from the corner.
        EXPECT_FALSE(profile.concave.empty()) << name;
        checkProgram(exportAndInterpret(dir, project, {"--tool-radius", "3"}), profile, {3.0},
                     name);
    }
}

TEST(CliExportGcode, StepDownsMakePassesAtEachDepth) {
    const test::TempDir dir;
    const std::string project = test::examplePath("six-lobe-arc-cam.cam.json");
    const Profile profile = profileOfFile(project);
    const Milled m = exportAndInterpret(dir, project,
                                        {"--tool-radius", "2", "--depth", "5", "--step-down", "2"});
    EXPECT_EQ(checkProgram(m, profile, {2.0}, "step-down 2"),
              (std::vector<double>{-2.0, -4.0, -5.0}));
    // A step-down that divides the depth: no extra pass; one larger than it: one pass.
    EXPECT_EQ(checkProgram(
                  exportAndInterpret(dir, project,
                                     {"--tool-radius", "2", "--depth", "3", "--step-down", "0.75"}),
                  profile, {2.0}, "step-down 0.75"),
              (std::vector<double>{-0.75, -1.5, -2.25, -3.0}));
    EXPECT_EQ(checkProgram(
                  exportAndInterpret(dir, project,
                                     {"--tool-radius", "2", "--depth", "1.5", "--step-down", "4"}),
                  profile, {2.0}, "step-down 4"),
              (std::vector<double>{-1.5}));
}

TEST(CliExportGcode, CompensationLetsTheControllerOffsetThePartContour) {
    const test::TempDir dir;
    const Expect e{3.0, 2};
    for (const std::string& project : {test::examplePath("six-lobe-arc-cam.cam.json"),
                                       writeProject(dir, "three.cam.json", kThreeArcs),
                                       writeProject(dir, "circle.cam.json", kCircle),
                                       writeProject(dir, "diamond.cam.json", kDentedDiamond),
                                       writeProject(dir, "star.cam.json", kStar),
                                       test::dataPath("reference/notch-flat.cam.json")}) {
        const Milled m = exportAndInterpret(
            dir, project, {"--tool-radius", "3", "--compensation", "--step-down", "2.5"}, 3.0);
        EXPECT_NE(m.program.find("\nG41 D1\n"), std::string::npos);
        EXPECT_NE(m.program.find("\nG40\n"), std::string::npos);
        EXPECT_EQ(checkProgram(m, profileOfFile(project), e, project),
                  (std::vector<double>{-2.5, -5.0}));
    }
    // Splines with concave corners, as arcs within 1e-3 mm: each corner's crossing lies on the
    // next programmed arc, as a controller's compensation needs.
    const std::string splines = test::dataPath("reference/spline-mix.cam.json");
    Expect coarse = e;
    coarse.within = 1e-3 + kTolMm;
    checkProgram(
        exportAndInterpret(dir, splines,
                           {"--tool-radius", "3", "--compensation", "--tolerance", "1e-3"}, 3.0),
        profileOfFile(splines), coarse, "spline-mix, tolerance 1e-3");
}

TEST(CliExportGcode, CompensationIsRefusedWhereTheControllerWouldCutIntoThePart) {
    const test::TempDir dir;
    // With arcs within 1e-5 mm the crossing at the concave corner between the Bézier and the
    // arc (contour[0]/contour[1]) lies several short arcs into the Bézier. LinuxCNC, offsetting
    // move by move, makes one of them an almost full circle through the part: refused (exit 3).
    const std::string project = test::dataPath("reference/spline-mix.cam.json");
    const std::string out = dir.file("never.ngc");
    const auto r = test::runCli({"export", project, "--format", "gcode", "--out", out,
                                 "--tool-radius", "3", "--compensation"});
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find(project + ": contour[0]: with cutter compensation"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out));
    // Without compensation the same cam is milled exactly (CliExportGcode.SplineCams…).
}

TEST(GcodeProgram, ConventionalMillingGoesCounterClockwiseWithG42) {
    const test::TempDir dir;
    for (const std::string& path : {test::examplePath("six-lobe-arc-cam.cam.json"),
                                    test::dataPath("reference/spline-offset.cam.json")}) {
        const auto project = loadProjectFile(path);
        ASSERT_TRUE(project.ok());
        const auto contour = Contour::build(project.value());
        ASSERT_TRUE(contour.ok());
        GcodeOptions options;
        options.toolRadiusMm = 3.0;
        options.direction = MillingDirection::Conventional;
        options.toleranceMm = 1e-3;  // coarse enough for compensation at the spline's corners
        const Expect e{3.0, 1, false, 1e-3 + kTolMm};
        const auto plain = gcodeProgram(contour.value(), options);
        ASSERT_TRUE(plain.ok());
        EXPECT_NE(plain.value().find("(conventional milling: counter-clockwise"),
                  std::string::npos);
        checkProgram(interpret(dir, plain.value()), profileOfFile(path), e, path);
        options.compensation = true;
        const auto compensated = gcodeProgram(contour.value(), options);
        ASSERT_TRUE(compensated.ok());
        EXPECT_NE(compensated.value().find("\nG42 D1\n"), std::string::npos);
        Expect ce = e;
        ce.leadMoves = 2;
        checkProgram(interpret(dir, compensated.value(), 3.0), profileOfFile(path), ce,
                     path + " (G42)");
    }
}

TEST(CliExportGcode, ToolTooWideForAConcaveArcIsRefusedNamingIt) {
    const test::TempDir dir;
    const std::string out = dir.file("never.ngc");
    struct Case {
        std::string project;
        std::string radius;
        std::string location;
    };
    const std::vector<Case> cases{
        {test::examplePath("six-lobe-arc-cam.cam.json"), "5", "contour[0]"},  // inner radius 4.84
        {test::dataPath("reference/notch-flat.cam.json"), "9.5", "contour[1]"},  // notch 9 mm
        {writeProject(dir, "diamond.cam.json", kDentedDiamond), "26", "contour[1]"},
    };
    for (const Case& c : cases) {
        for (const bool compensation : {false, true}) {
            std::vector<std::string> args{"export", c.project, "--format",      "gcode",
                                          "--out",  out,       "--tool-radius", c.radius};
            if (compensation) args.push_back("--compensation");
            const auto r = test::runCli(args);
            EXPECT_EQ(r.exitCode, 3) << c.project << "\n" << r.err;
            EXPECT_NE(r.err.find(c.project + ": " + c.location + ":"), std::string::npos) << r.err;
            EXPECT_FALSE(fs::exists(out));
        }
    }
}

TEST(CliExportGcode, OptionsAreCheckedAndNamed) {
    const test::TempDir dir;
    const std::string out = dir.file("never.ngc");
    const std::string sixLobe = test::examplePath("six-lobe-arc-cam.cam.json");
    const std::string noMachining = writeProject(dir, "three.cam.json", kThreeArcs);
    struct Case {
        std::vector<std::string> options;
        int code;
        std::string location;
    };
    const std::vector<Case> cases{
        {{}, 1, "--tool-radius"},  // neither the option nor machining.tool_radius
        {{"--tool-radius", "0"}, 2, "--tool-radius"},
        {{"--tool-radius", "-1"}, 2, "--tool-radius"},
        {{"--tool-radius", "x"}, 2, "--tool-radius"},
        {{"--tool-radius", "1", "--depth", "0"}, 2, "--depth"},
        {{"--tool-radius", "1", "--depth", "nan"}, 2, "--depth"},
        {{"--tool-radius", "1", "--step-down", "-2"}, 2, "--step-down"},
        {{"--tool-radius", "1", "--depth", "100", "--step-down", "0.001"}, 2, "--step-down"},
        {{"--tool-radius", "1", "--tolerance", "0"}, 2, "--tolerance"},
        {{"--tool-radius", "1", "--points", "10"}, 1, "--points"},
        {{"--tool-radius", "1", "--polyline"}, 1, "--polyline"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"export", noMachining, "--format", "gcode", "--out", out};
        args.insert(args.end(), c.options.begin(), c.options.end());
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, c.code) << r.err;
        EXPECT_EQ(r.err.rfind("camwright-cli: " + c.location + ":", 0), 0u) << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
    // --compensation and --depth belong to gcode only.
    for (const char* option : {"--compensation", "--depth"}) {
        std::vector<std::string> args{"export", sixLobe, "--format", "dxf", "--out", out, option};
        if (std::string(option) == "--depth") args.push_back("1");
        EXPECT_EQ(test::runCli(args).exitCode, 1) << option;
    }
}

TEST(CliExportGcode, ProgramTextIsPlainAndSaysHowItMills) {
    const test::TempDir dir;
    const std::string out = dir.file("cam.ngc");
    const std::string project =
        writeProject(dir, "named.cam.json",
                     R"json({"format": "camwright", "version": 1, "name": "Cam (rev. 2)\nfür Welle",
           "motion": {"period_s": 1},
           "contour": [{"type": "arc", "center": [3, -2], "radius": 20, "branch": "outer",
                        "phi_start": 0, "phi_end": 360}]})json");
    const auto r = test::runCli({"export", project, "--format", "gcode", "--out", out,
                                 "--tool-radius", "3", "--depth", "2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string program = test::readFile(out);
    EXPECT_EQ(program.rfind("%\n(Camwright G-code: Cam [rev. 2]?f?r Welle)\n", 0), 0u) << program;
    EXPECT_NE(program.find("\nG21 G90 G91.1 G17 G94 G40\n"), std::string::npos);
    EXPECT_NE(program.find("(climb milling: clockwise round the part"), std::string::npos);
    EXPECT_NE(program.find("tool radius 3.000000 mm"), std::string::npos);
    EXPECT_EQ(program.substr(program.size() - 6), "M30\n%\n");
    // Every comment closes on its line; no character outside printable ASCII.
    std::istringstream lines(program);
    std::string line;
    while (std::getline(lines, line)) {
        EXPECT_EQ(std::count(line.begin(), line.end(), '('),
                  std::count(line.begin(), line.end(), ')'))
            << line;
        for (const char c : line) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << line;
        // Coordinates with 6 decimals.
        for (const char axis : {'X', 'Y', 'Z', 'I', 'J'}) {
            if (line.empty() || line[0] == '(') break;
            const auto at = line.find(axis);
            if (at == std::string::npos) continue;
            const auto end = line.find(' ', at);
            const std::string number =
                line.substr(at + 1, end == std::string::npos ? end : end - at - 1);
            EXPECT_EQ(number.size() - number.find('.') - 1, 6u) << line;
        }
    }
}

// ---- A grooved cam: the program mills the groove between its flanks -------------------------

/// The outer flank of an arc profile, built here from the profile's own arcs: the same centres
/// and angles, the radius grown by the groove's width w on a convex arc (counter-clockwise
/// about its centre) and shrunk by it on a concave one.
Profile outerFlankOf(const Profile& inner, double w) {
    Profile outer;
    for (Piece p : inner.pieces) {
        EXPECT_EQ(p.kind, Piece::Arc) << "the groove tests use arc profiles";
        p.r += p.sweep > 0 ? w : -w;
        p.a = p.at(0.0);
        p.b = p.at(1.0);
        outer.pieces.push_back(p);
        for (int i = 0; i < 256; ++i) outer.polygon.push_back(p.at(i / 256.0));
    }
    return outer;
}

/// A copy of the bundled six-lobe cam run by a roller of radius ρ in a groove with clearance c.
std::string groovedSixLobe(const test::TempDir& dir, double rho, double clearance) {
    nlohmann::json project =
        nlohmann::json::parse(test::readFile(test::examplePath("six-lobe-arc-cam.cam.json")));
    project["follower"] = {{"type", "roller"},
                           {"radius", rho},
                           {"closure", "groove"},
                           {"groove_clearance_mm", clearance}};
    return writeProject(dir, "grooved.cam.json", project.dump(1));
}

/// The checks of a groove's program at every depth: no cutting point comes nearer either flank
/// than the tool radius r (nothing beyond the groove is cut), every point of both flanks and of
/// the groove between them lies within r of the tool's centre (the groove is cleared), and the
/// plunge lies on the centre line. Returns, per pass, each cutting point's distance from the
/// inner flank.
std::vector<std::vector<double>> checkGroove(const Milled& milled, const Profile& inner, double w,
                                             double r, const std::string& what) {
    SCOPED_TRACE(what);
    const Profile outer = outerFlankOf(inner, w);
    const std::vector<Pass> passes = passesOf(milled.moves);
    std::vector<std::vector<double>> distances;
    for (const Pass& pass : passes) {
        SCOPED_TRACE(std::string("pass at Z").append(std::to_string(pass.z)));
        std::vector<Vec2> centres;
        std::vector<double> fromInner;
        double worstInner = 0, worstOuter = 0;
        int outside = 0;
        for (const CanonMove& m : pass.moves) {
            for (const Vec2& q : m.samples(kSampleStepMm)) {
                const double dIn = inner.distance(q), dOut = outer.distance(q);
                worstInner = std::max(worstInner, r - dIn);
                worstOuter = std::max(worstOuter, r - dOut);
                // In the groove: outside the cam's body, inside the outer flank.
                if (inner.winding(q) != 0 || outer.winding(q) == 0) ++outside;
                fromInner.push_back(dIn);
                centres.push_back(q);
            }
        }
        EXPECT_LE(worstInner, kTolMm) << "the tool cuts into the inner flank";
        EXPECT_LE(worstOuter, kTolMm) << "the tool cuts into the outer flank";
        EXPECT_EQ(outside, 0) << "tool centres outside the groove";
        EXPECT_TRUE(pass.plunge);
        if (pass.plunge) {
            EXPECT_NEAR(inner.distance(pass.plunge->end.head<2>()), w / 2, kTolMm)
                << "the plunge is not on the groove's centre line";
        }
        // Cleared: points across the groove at every 0.05 mm along each arc, at 0, w/8, …, w
        // from the inner flank, each within r of some tool centre.
        int uncleared = 0;
        double worst = 0;
        for (const Piece& p : inner.pieces) {
            const int n = std::max(50, static_cast<int>(p.length() / kSampleStepMm));
            for (int i = 0; i <= n; ++i) {
                const Vec2 onArc = p.at(double(i) / n);
                const Vec2 out = (onArc - p.c).normalized() * (p.sweep > 0 ? 1.0 : -1.0);
                for (int k = 0; k <= 8; ++k) {
                    const Vec2 q = onArc + w * k / 8.0 * out;
                    double d = std::numeric_limits<double>::infinity();
                    for (const Vec2& c : centres) d = std::min(d, (q - c).squaredNorm());
                    worst = std::max(worst, std::sqrt(d) - r);
                    // The centres are samples 0.05 mm apart: between two the tool reaches
                    // at least √(r² − 0.025²) – r further, a little less than r itself.
                    if (std::sqrt(d) > r + kTolMm + kSampleStepMm * kSampleStepMm / r) ++uncleared;
                }
            }
        }
        EXPECT_EQ(uncleared, 0) << "groove points the tool never reaches; worst by " << worst;
        distances.push_back(std::move(fromInner));
    }
    return distances;
}

TEST(CliExportGcodeGroove, OneSlotPassOnTheCentreLineByDefault) {
    const test::TempDir dir;
    const double rho = 2.0, clearance = 0.5, w = 2 * rho + clearance;
    const std::string project = groovedSixLobe(dir, rho, clearance);
    const Milled m = exportAndInterpret(dir, project, {"--depth", "6", "--step-down", "3"});
    const Profile inner = profileOfFile(project);
    const auto passes = checkGroove(m, inner, w, w / 2, "slot");
    ASSERT_EQ(passes.size(), 2u);  // Z −3 and −6
    // Every cutting point runs on the centre line, ρ + c/2 from both flanks.
    for (const auto& pass : passes) {
        for (const double d : pass) EXPECT_NEAR(d, w / 2, kTolMm);
    }
    EXPECT_NE(m.program.find("one slot pass on the groove's centre line"), std::string::npos);
    EXPECT_EQ(m.program.find("G41"), std::string::npos);
    EXPECT_EQ(m.program.find("G42"), std::string::npos);
}

TEST(CliExportGcodeGroove, ANarrowerToolRoughsTheCentreAndFinishesEachFlank) {
    const test::TempDir dir;
    const double rho = 2.0, clearance = 0.5, w = 2 * rho + clearance, tool = 1.2;
    const std::string project = groovedSixLobe(dir, rho, clearance);
    const Milled m = exportAndInterpret(dir, project, {"--tool-radius", "1.2", "--depth", "4"});
    const Profile inner = profileOfFile(project);
    const auto passes = checkGroove(m, inner, w, tool, "rough and finish");
    ASSERT_EQ(passes.size(), 1u);
    // The three loops: on the centre line, the tool radius off the inner flank, and the tool
    // radius off the outer one; only the sideways moves between them lie elsewhere.
    int centre = 0, innerLoop = 0, outerLoop = 0, between = 0;
    for (const double d : passes.front()) {
        if (std::abs(d - w / 2) <= kTolMm) {
            ++centre;
        } else if (std::abs(d - tool) <= kTolMm) {
            ++innerLoop;
        } else if (std::abs(d - (w - tool)) <= kTolMm) {
            ++outerLoop;
        } else {
            ++between;
        }
    }
    // Each loop is about as long as its flank: hundreds of 0.05 mm samples.
    EXPECT_GT(centre, 2000);
    EXPECT_GT(innerLoop, 2000);
    EXPECT_GT(outerLoop, 2000);
    EXPECT_LT(between, 200);
    EXPECT_NE(m.program.find("finishing the inner flank, climbing: clockwise"), std::string::npos);
}

TEST(CliExportGcodeGroove, AToolWiderThanTheGrooveOrTooNarrowIsRefused) {
    const test::TempDir dir;
    const std::string project = groovedSixLobe(dir, 2.0, 0.5);
    const std::string out = dir.file("cam.ngc");
    const auto wide = test::runCli(
        {"export", project, "--format", "gcode", "--out", out, "--tool-radius", "2.3"});
    EXPECT_EQ(wide.exitCode, 2);
    EXPECT_NE(wide.err.find("--tool-radius: the tool radius 2.3 mm is wider than the groove"),
              std::string::npos)
        << wide.err;
    const auto narrow = test::runCli(
        {"export", project, "--format", "gcode", "--out", out, "--tool-radius", "0.7"});
    EXPECT_EQ(narrow.exitCode, 2);
    EXPECT_NE(narrow.err.find("at least 0.75 mm"), std::string::npos) << narrow.err;
    const auto compensated =
        test::runCli({"export", project, "--format", "gcode", "--out", out, "--compensation"});
    EXPECT_EQ(compensated.exitCode, 2);
    EXPECT_NE(compensated.err.find("--compensation: a groove is milled"), std::string::npos)
        << compensated.err;
    EXPECT_FALSE(fs::exists(out));
}

// ---- A conjugate pair: each plate its own program --------------------------------------------

// The yoke on an eccentric disc (a circle of radius 30 about (5, 0)), its line offset by 3 mm:
// the first roller (4 mm) at s = u·c + √(34² − (3 − n·c)²), the second (5 mm) 80 mm behind.
constexpr const char* kConjugateDisc = R"json({"format": "camwright", "version": 1,
  "name": "Conjugate disc", "motion": {"period_s": 2},
  "contour": [{"type": "arc", "center": [5, 0], "radius": 30, "branch": "outer",
               "phi_start": 0, "phi_end": 360}],
  "follower": {"type": "roller", "radius": 4, "offset": 3, "closure": "conjugate",
               "conjugate_distance_mm": 80, "conjugate_radius_mm": 5}})json";

/// The second roller's centre at cam angle φ, in closed form.
Vec2 secondRollerCentre(double phi) {
    const Vec2 u(std::cos(phi), std::sin(phi)), n(-u.y(), u.x()), c(5.0, 0.0);
    const double side = 3.0 - n.dot(c);
    const double s = u.dot(c) + std::sqrt(34.0 * 34.0 - side * side);
    return (s - 80.0) * u + 3.0 * n;
}

TEST(CliExportGcodeConjugate, TheSecondPlateIsMilledSoThatItHoldsTheSecondRoller) {
    // --plate 2: the tool (3 mm) runs round the second plate, between it and the path of the
    // second roller's centre (5 mm out): 2 mm from that closed-form path at every point of the
    // loop, to the plate's fitting tolerance (0.001 mm) and the program's.
    const test::TempDir dir;
    const std::string project = writeProject(dir, "conjugate.cam.json", kConjugateDisc);
    const Milled m =
        exportAndInterpret(dir, project, {"--plate", "2", "--tool-radius", "3", "--depth", "5"});
    EXPECT_NE(m.program.find("Conjugate disc, second plate"), std::string::npos);
    std::vector<Vec2> path;
    for (int k = 0; k < 72000; ++k)
        path.push_back(secondRollerCentre(2 * std::numbers::pi * k / 72000));
    const std::vector<Pass> passes = passesOf(m.moves);
    ASSERT_EQ(passes.size(), 1u);
    const Pass& pass = passes.front();
    ASSERT_GT(pass.moves.size(), 4u);
    double worst = 0;
    std::size_t points = 0;
    for (std::size_t i = 1; i + 1 < pass.moves.size(); ++i) {  // the loop, without its leads
        for (const Vec2& q : pass.moves[i].samples(kSampleStepMm)) {
            double d = std::numeric_limits<double>::infinity();
            for (const Vec2& c : path) d = std::min(d, (q - c).squaredNorm());
            // The path's samples lie 0.005 mm apart: the nearest is off by ≤ 3e-6 mm.
            worst = std::max(worst, std::abs(std::sqrt(d) - 2.0));
            ++points;
        }
    }
    EXPECT_GT(points, 2000u);
    EXPECT_LE(worst, 1e-3 + kTolMm);
    ::testing::Test::RecordProperty("worst_mm", std::to_string(worst));
    // The loop closes.
    EXPECT_LE((pass.moves[1].start - pass.moves[pass.moves.size() - 2].end).norm(), kTolMm);
    // --plate 1 is the contour, as without it.
    const Milled first = exportAndInterpret(dir, project, {"--plate", "1", "--tool-radius", "3"});
    checkProgram(first, profileOfFile(project), {3.0}, "first plate");
}

TEST(CliExportGcodeConjugate, APlateIsOneOrTwoOfAConjugatePair) {
    const test::TempDir dir;
    const std::string out = dir.file("cam.ngc");
    const std::string pair = writeProject(dir, "conjugate.cam.json", kConjugateDisc);
    const auto third = test::runCli(
        {"export", pair, "--format", "gcode", "--out", out, "--tool-radius", "3", "--plate", "3"});
    EXPECT_EQ(third.exitCode, 1);
    EXPECT_NE(third.err.find("--plate: must be 1 or 2 (got '3')"), std::string::npos) << third.err;
    const std::string single = writeProject(dir, "circle.cam.json", kCircle);
    const auto one =
        test::runCli({"export", single, "--format", "gcode", "--out", out, "--plate", "2"});
    EXPECT_EQ(one.exitCode, 1);
    EXPECT_NE(one.err.find("--plate: is for a conjugate pair"), std::string::npos) << one.err;
    const auto dxf =
        test::runCli({"export", pair, "--format", "dxf", "--out", out, "--plate", "2"});
    EXPECT_EQ(dxf.exitCode, 1);
    EXPECT_NE(dxf.err.find("--plate: is not an option of --format dxf"), std::string::npos)
        << dxf.err;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace cam
