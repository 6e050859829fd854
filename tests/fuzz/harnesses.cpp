#include "harnesses.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/analysis.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "fillet/fillet.h"
#include "io/number_rows.h"
#include "io/path_csv.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"
#include "project/validate.h"
#include "spline/teach_in.h"
#include "timing/machining_time.h"
#include "timing/timing_job.h"
#include "toolpath/tool_path.h"

namespace cam::fuzz {
namespace {

[[noreturn]] void broken(const std::string& what) {
    std::fprintf(stderr, "fuzz: invariant broken: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

// A macro so that the message is built only when the check fails: the harnesses run millions
// of times, and some messages read values that exist only then.
#define FUZZ_CHECK(condition, what)     \
    do {                                \
        if (!(condition)) broken(what); \
    } while (false)

/// A refusal must say why: at least one diagnostic, and none with an empty message.
void checkRefusal(const Diagnostics& errors, const std::string& who) {
    FUZZ_CHECK(!errors.empty(), who + " refused without a diagnostic");
    for (const Diagnostic& d : errors) {
        FUZZ_CHECK(!d.message.empty(),
                   who + " refused with an empty message at \"" + d.location + "\"");
    }
}

/// Reads the fuzzer's bytes as the inputs of a computation. Past the end it reads zeros, so
/// every byte string is a complete input.
class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

    std::uint8_t byte() { return m_pos < m_size ? m_data[m_pos++] : 0; }
    [[nodiscard]] bool empty() const { return m_pos >= m_size; }

    std::int16_t i16() {
        const auto lo = static_cast<unsigned>(byte());
        const auto hi = static_cast<unsigned>(byte());
        return static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | hi << 8));
    }

    /// Any bit pattern: NaN, infinities, subnormals.
    double raw() {
        std::uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(byte()) << (8 * i);
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }

    /// A number: mostly one a person might type (multiples of scale/256 up to ±128·scale), else
    /// an extreme one, a scaled one over 2^±64, or any bit pattern.
    double real(double scale) {
        static constexpr double kSpecial[] = {0.0,
                                              -0.0,
                                              1.0,
                                              -1.0,
                                              1e-300,
                                              -1e-300,
                                              1e-9,
                                              1e9,
                                              1e6,
                                              -1e6,
                                              1e300,
                                              std::numeric_limits<double>::infinity(),
                                              -std::numeric_limits<double>::infinity(),
                                              std::numeric_limits<double>::quiet_NaN(),
                                              std::numeric_limits<double>::denorm_min(),
                                              std::numeric_limits<double>::max()};
        const std::uint8_t kind = byte() % 8;
        if (kind < 5) return scale * i16() / 256.0;
        if (kind == 5) return kSpecial[byte() % std::size(kSpecial)];
        if (kind == 6) return scale * std::ldexp(i16() / 256.0, static_cast<std::int8_t>(byte()));
        return raw();
    }

    /// The bytes not read yet.
    std::string_view rest() const {
        if (empty()) return {};
        return {reinterpret_cast<const char*>(m_data + m_pos), m_size - m_pos};
    }

private:
    const std::uint8_t* m_data;
    std::size_t m_size;
    std::size_t m_pos = 0;
};

/// With CAMWRIGHT_FUZZ_VERBOSE set, the harnesses print the inputs they decoded (to triage a
/// saved crash input: run the fuzzer binary or the regression test on it).
bool verbose() {
    static const bool on = std::getenv("CAMWRIGHT_FUZZ_VERBOSE") != nullptr;
    return on;
}

void describe(const std::vector<SegmentSpec>& contour, std::size_t joint, double rho) {
    Project project;
    project.contour = contour;
    std::fprintf(stderr, "fillet at joint %zu, radius %.17g, of\n%s\n", joint, rho,
                 serializeProject(project).c_str());
}

void describe(const TimingJob& job, const std::vector<PathPoint>& points) {
    const MachineLimits& l = job.limits;
    std::fprintf(stderr,
                 "accel %.17g %.17g %.17g, vmax %.17g %.17g %.17g, feed %.17g, step %.17g, "
                 "profile %d on %zu points\n",
                 l.accel[0], l.accel[1], l.accel[2], l.vmax[0], l.vmax[1], l.vmax[2], l.feedMax,
                 l.seedStep, job.profileMethod ? static_cast<int>(*job.profileMethod) : -1,
                 job.profilePoints);
    for (const PathPoint& p : points) {
        std::fprintf(stderr, "%.17g,%.17g,%.17g,%.17g\n", p.position.x(), p.position.y(),
                     p.position.z(), p.bulge);
    }
}

bool allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// ---------------------------------------------------------------------------------------------
// Point lists

std::string format17(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

/// The rows read as the reader promises, and written back with 17 digits they read the same.
void checkRows(std::string_view text, const RowShape& shape, const std::string& who) {
    const auto rows = parseNumberRows(text, shape);
    if (!rows.ok()) {
        checkRefusal(rows.errors(), who);
        FUZZ_CHECK(rows.errors().size() <= 20, who + " listed more than 20 problems");
        const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
        for (const Diagnostic& d : rows.errors()) {
            FUZZ_CHECK(d.location.rfind("line ", 0) == 0,
                       who + " located a problem as \"" + d.location + "\", not as a line");
            const std::size_t line = std::stoul(d.location.substr(5));
            FUZZ_CHECK(line >= 1 && line <= lines + 1, who + " named " + d.location + " of " +
                                                           std::to_string(lines + 1) + " lines");
        }
        return;
    }
    std::string written;
    for (const std::vector<double>& row : rows.value()) {
        FUZZ_CHECK(row.size() >= shape.required && row.size() <= shape.names.size(),
                   who + " accepted a row of " + std::to_string(row.size()) + " values");
        FUZZ_CHECK(allFinite(row), who + " accepted a non-finite number");
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (i > 0) written += ',';  // appends: GCC 12 warns falsely on "," + string
            written += format17(row[i]);
        }
        written += "\n";
    }
    const auto again = parseNumberRows(written, shape);
    FUZZ_CHECK(again.ok(), who + " refused its own rows written back: " +
                               (again.ok() ? "" : again.errors().front().text()));
    FUZZ_CHECK(again.value() == rows.value(), who + " read its rows written back differently");
}

/// A tool path from accepted points: made, or refused with a reason; made, it is finite.
void checkToolPath(const std::vector<PathPoint>& points, const char* who) {
    const auto path = toolPathFromPoints(points);
    if (!path.ok()) {
        checkRefusal(path.errors(), who);
        return;
    }
    FUZZ_CHECK(path.value().segments.size() + 1 == points.size(),
               std::string(who) + ": segment count");
    for (const PathSegment& s : path.value().segments) {
        const double len = s.length();
        FUZZ_CHECK(std::isfinite(len) && len > 0.0,
                   std::string(who) + " made a segment of length " + formatNumber(len));
    }
}

// ---------------------------------------------------------------------------------------------
// Fillets

SegmentSpec arcThrough(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double bend) {
    const Eigen::Vector2d mid = 0.5 * (a + b);
    const Eigen::Vector2d chord = b - a;
    const Eigen::Vector2d center = mid + bend * Eigen::Vector2d(-chord.y(), chord.x());
    Arc arc{center, (a - center).norm(), Branch::Outer};
    // The branch that passes through a (the other one would not meet the window's start).
    const double phi = std::atan2(a.y(), a.x());
    const double outer = arc.evaluate(phi).r;
    arc.branch = Branch::Inner;
    const double inner = arc.evaluate(phi).r;
    arc.branch =
        std::abs(outer - a.norm()) <= std::abs(inner - a.norm()) ? Branch::Outer : Branch::Inner;
    return SegmentSpec{arc};
}

/// A closed contour of lines and arcs through points around the rotation centre, their polar
/// angles increasing (so lines run counter-clockwise); windows on the points' angles.
std::vector<SegmentSpec> polygon(Bytes& in) {
    const std::size_t n = 1 + in.byte() % 12;
    std::vector<double> weights(n);
    double total = 0.0;
    for (double& w : weights) total += w = 1.0 + in.byte();
    const double startDeg = in.byte() % 4 == 0 ? in.real(1.0) : 0.0;
    std::vector<double> deg(n + 1);
    deg[0] = startDeg;
    for (std::size_t i = 0; i < n; ++i) deg[i + 1] = deg[i] + 360.0 * weights[i] / total;
    deg[n] = startDeg + 360.0;
    std::vector<Eigen::Vector2d> points(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
        const double r = in.byte() % 8 == 0 ? in.real(1.0) : 1.0 + in.i16() / 256.0 + 128.0;
        const double phi = degToRad(deg[i]);
        points[i] = {r * std::cos(phi), r * std::sin(phi)};
    }
    points[n] = points[0];
    std::vector<SegmentSpec> contour;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t kind = in.byte();
        SegmentSpec s = kind % 2 == 0 ? SegmentSpec{Line{points[i], points[i + 1]}}
                                      : arcThrough(points[i], points[i + 1], in.real(1.0 / 64));
        s.phiStartDeg = deg[i];
        s.phiEndDeg = deg[i + 1];
        contour.push_back(s);
    }
    return contour;
}

void checkFilleted(const std::vector<SegmentSpec>& contour, std::size_t joint, double rho,
                   const FilletResult& f) {
    const std::string at =
        "fillet at joint " + std::to_string(joint) + ", radius " + formatNumber(rho) + ": ";
    FUZZ_CHECK(f.contour.size() == contour.size() + 1,
               at + "the contour did not grow by one segment");
    FUZZ_CHECK(f.radius == rho, at + "the radius is " + formatNumber(f.radius));
    FUZZ_CHECK(f.center.allFinite() && f.tangentPoint1.allFinite() && f.tangentPoint2.allFinite(),
               at + "a non-finite centre or tangent point");
    const double tol = 1e-6 * std::max({rho, f.center.norm(), 1.0});
    FUZZ_CHECK(std::abs((f.tangentPoint1 - f.center).norm() - rho) <= tol &&
                   std::abs((f.tangentPoint2 - f.center).norm() - rho) <= tol,
               at + "a tangent point is not on the fillet circle");
    Project project;
    project.contour = f.contour;
    const Diagnostics problems = validateProject(project);
    FUZZ_CHECK(!hasErrors(problems),
               at + "the result does not validate: " + problems.front().text());
    FUZZ_CHECK(Contour::build(project).ok(), at + "the result does not compile");
    const auto again = parseProject(serializeProject(project));
    FUZZ_CHECK(again.ok(), at + "the result saved does not load: " +
                               (again.ok() ? "" : again.errors().front().text()));
}

// ---------------------------------------------------------------------------------------------
// Timing

void checkTiming(const TimingResult& r, const ToolPath& path, const std::string& who) {
    FUZZ_CHECK(std::isfinite(r.timeS) && r.timeS >= 0.0, who + " time " + formatNumber(r.timeS));
    FUZZ_CHECK(std::isfinite(r.lengthMm) && r.lengthMm > 0.0,
               who + " length " + formatNumber(r.lengthMm));
    // Moving takes time (issue 27: a plunge along an axis without an acceleration limit took
    // 0 s). Only below 2e-12 mm may a path be too short for the seed to take a step.
    FUZZ_CHECK(
        !(r.lengthMm > 1e-9) || r.timeS > 0.0,
        who + " takes " + formatNumber(r.timeS) + " s for " + formatNumber(r.lengthMm) + " mm");
    FUZZ_CHECK(r.segments.size() == path.segments.size(), who + ": one timing per segment");
    for (const SegmentTiming& s : r.segments) {
        FUZZ_CHECK(std::isfinite(s.timeS) && s.timeS >= 0.0,
                   who + " segment time " + formatNumber(s.timeS));
        FUZZ_CHECK(std::isfinite(s.entrySpeed) && std::isfinite(s.exitSpeed) &&
                       s.entrySpeed >= 0.0 && s.exitSpeed >= 0.0,
                   who + " segment entry/exit speed not finite");
    }
}

}  // namespace

void fuzzProject(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto project = parseProject(text);
    if (!project.ok()) {
        checkRefusal(project.errors(), "parseProject");
        return;
    }
    const auto contour = Contour::build(project.value());
    if (project.value().contour.empty()) {
        // A design never synthesised loads (project-format.md) and says it has no contour yet.
        FUZZ_CHECK(project.value().design.has_value(), "an empty contour loaded without a design");
        FUZZ_CHECK(!contour.ok() && contour.errors().front().location == "contour",
                   "a design without a contour does not say so");
        return;
    }
    FUZZ_CHECK(contour.ok(), "a loaded project does not compile");
    const double omega = project.value().motion.omegaRadS();
    FUZZ_CHECK(std::isfinite(omega) && omega != 0.0,
               "a loaded project turns at " + formatNumber(omega));
    for (double t : {0.0, 0.123, -7.5, 1e6}) (void)stateAt(contour.value(), omega, t);
    SampledTurn turn;
    sampleTurn(contour.value(), omega, 97, turn);
    (void)analyzeContour(contour.value(), omega);
    const std::string saved = serializeProject(project.value());
    const auto again = parseProject(saved);
    FUZZ_CHECK(again.ok() && again.value() == project.value(), "save → load changed the project");
    FUZZ_CHECK(serializeProject(again.value()) == saved, "save → load → save is not byte-stable");
}

void fuzzPointList(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    checkRows(text, {{"x", "y", "z", "bulge"}, 3}, "the point-list reader");
    checkRows(text, {{"x", "y"}, 2}, "the teach-in reader");

    const auto points = parsePathCsv(text);
    if (!points.ok()) {
        checkRefusal(points.errors(), "parsePathCsv");
    } else {
        FUZZ_CHECK(points.value().size() >= 2, "parsePathCsv accepted fewer than two points");
        for (const PathPoint& p : points.value()) {
            FUZZ_CHECK(p.position.allFinite() && std::isfinite(p.bulge),
                       "parsePathCsv accepted a non-finite point");
        }
        checkToolPath(points.value(), "toolPathFromPoints");
    }

    // The teach-in import: knots through a closed Bézier contour (kept small: each segment's
    // validation casts 256 rays).
    const auto rows = parseNumberRows(text, {{"x", "y"}, 2});
    if (!rows.ok() || rows.value().size() > 64) return;
    std::vector<Eigen::Vector2d> knots;
    for (const auto& row : rows.value()) knots.emplace_back(row[0], row[1]);
    const auto rule = static_cast<HandleRule>(size % 3);
    const auto contour = contourThroughPoints(knots, rule);
    if (!contour.ok()) {
        checkRefusal(contour.errors(), "contourThroughPoints");
        return;
    }
    Project project;
    project.contour = contour.value();
    const Diagnostics problems = validateProject(project);
    FUZZ_CHECK(!hasErrors(problems), "a teach-in contour does not validate: " +
                                         (problems.empty() ? "" : problems.front().text()));
}

void fuzzFillet(const std::uint8_t* data, std::size_t size) {
    Bytes in(data, size);
    const std::uint8_t mode = in.byte();
    const std::uint8_t jointByte = in.byte();
    const std::uint8_t radiusKind = in.byte();
    std::vector<SegmentSpec> contour;
    double rhoGiven = 0.0;
    if (mode % 4 == 0) {
        // The rest is a project file (the examples and the test data are seeds).
        rhoGiven = in.real(1.0);
        const auto project = parseProject(in.rest());
        if (!project.ok()) return;  // fuzzProject covers the refusals
        contour = project.value().contour;
    } else {
        contour = polygon(in);
        rhoGiven = in.real(1.0);
    }
    const std::size_t n = contour.size();
    // Now and then a joint that does not exist.
    const std::size_t joint = jointByte == 255 ? n : jointByte % std::max<std::size_t>(n, 1);

    if (verbose()) describe(contour, joint, rhoGiven);
    const auto range = filletRange(contour, joint);
    if (range.ok()) {
        const FilletRange& r = range.value();
        FUZZ_CHECK(
            r.minRadius == kMinLengthMm && std::isfinite(r.maxRadius) &&
                r.maxRadius > r.minRadius && r.maxRadius <= kMaxLengthMm,
            "filletRange gave " + formatNumber(r.minRadius) + " .. " + formatNumber(r.maxRadius));
    } else {
        checkRefusal(range.errors(), "filletRange");
    }

    // A radius as typed, or a fraction of the largest that fits (or just beyond it).
    double rho = rhoGiven;
    if (range.ok() && radiusKind % 2 == 0) {
        rho = range.value().maxRadius * (radiusKind / 2 + 1) / 120.0;
    }
    if (verbose()) describe(contour, joint, rho);
    const auto result = filletJoint(contour, joint, rho);
    if (!result.ok()) {
        checkRefusal(result.errors(), "filletJoint");
        return;
    }
    checkFilleted(contour, joint, rho, result.value());
}

void fuzzTiming(const std::uint8_t* data, std::size_t size) {
    Bytes in(data, size);
    TimingJob job;
    const std::uint8_t flags = in.byte();
    for (int i = 0; i < 3; ++i) job.limits.accel[i] = in.real(4.0);
    for (int i = 0; i < 3; ++i) {
        if (flags & (1 << i)) job.limits.vmax[i] = in.real(4.0);
    }
    if (flags & 8) job.limits.feedMax = in.real(4.0);
    job.limits.seedStep = flags & 16 ? in.real(1.0 / 16) : 1.0;
    job.methods = {TimingMethod::Seed, TimingMethod::ExactStop, TimingMethod::Optimal};
    const std::uint8_t profile = in.byte();
    if (profile % 4 != 3) {
        job.profileMethod = static_cast<TimingMethod>(profile % 4);
        job.profilePoints = 2 + in.byte() * 8u;
    }

    std::vector<PathPoint> points(2 + in.byte() % 15);
    for (PathPoint& p : points) {
        const std::uint8_t kind = in.byte();
        p.position = {in.real(1.0), in.real(1.0), kind & 1 ? in.real(1.0) : 0.0};
        if (kind & 2) p.bulge = in.real(1.0 / 256);
    }
    if (verbose()) describe(job, points);
    const auto built = toolPathFromPoints(points);
    if (!built.ok()) {
        checkRefusal(built.errors(), "toolPathFromPoints");
        return;
    }
    const ToolPath path = built.value();
    FUZZ_CHECK(path.segments.size() + 1 == points.size(), "toolPathFromPoints: segment count");
    const double length = path.length();
    FUZZ_CHECK(std::isfinite(length) && length > 0.0,
               "toolPathFromPoints made a path of length " + formatNumber(length));

    const auto timed = timePath(path, job);
    if (!timed.ok()) {
        checkRefusal(timed.errors(), "timePath");
        return;
    }
    const TimedPath& t = timed.value();
    FUZZ_CHECK(t.results.size() == job.methods.size(), "timePath: one result per method");
    for (std::size_t i = 0; i < t.results.size(); ++i) {
        FUZZ_CHECK(t.results[i].method == job.methods[i], "timePath: results out of order");
        checkTiming(t.results[i], path,
                    std::string("timing (") + timingMethodName(job.methods[i]) + ")");
    }
    // Stopping only at corners is never slower than stopping at every joint. Each segment's
    // time is converged to 1e-6 of itself (1e-5 leaves room for the grids' own error), or the
    // result says how far it may be off (convergence).
    const TimingResult& exactStop = t.results[1];
    const TimingResult& optimal = t.results[2];
    const double tolerance = 1e-5 + exactStop.convergence + optimal.convergence;
    FUZZ_CHECK(optimal.timeS <= exactStop.timeS * (1.0 + tolerance) + 1e-12,
               "optimal " + formatNumber(optimal.timeS) + " s is slower than exact stop " +
                   formatNumber(exactStop.timeS) + " s (tolerance " + formatNumber(tolerance) +
                   ")");
    FUZZ_CHECK(std::isfinite(optimal.convergence) && optimal.convergence >= 0.0 &&
                   std::isfinite(exactStop.convergence) && exactStop.convergence >= 0.0,
               "timing: a convergence estimate is not a finite number >= 0");
    FUZZ_CHECK(t.profile.has_value() == job.profileMethod.has_value(), "timePath: profile missing");
    if (t.profile) {
        const TimingProfile& p = *t.profile;
        FUZZ_CHECK(p.s.size() == p.speed.size() && p.s.size() == p.accel.size() && !p.s.empty(),
                   "timing profile: columns of different lengths");
        FUZZ_CHECK(allFinite(p.s) && allFinite(p.speed), "timing profile: non-finite s or speed");
        for (const Eigen::Vector3d& a : p.accel) {
            FUZZ_CHECK(a.allFinite(), "timing profile: non-finite acceleration");
        }
        for (std::size_t k = 0; k < p.s.size(); ++k) {
            FUZZ_CHECK(p.speed[k] >= 0.0, "timing profile: negative speed");
            FUZZ_CHECK(k == 0 || p.s[k] >= p.s[k - 1] - 1e-9 * length,
                       "timing profile: s goes back");
        }
    }
}

}  // namespace cam::fuzz
