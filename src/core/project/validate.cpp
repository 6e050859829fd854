#include "project/validate.h"

#include <cmath>

#include "common/angles.h"
#include "geometry/line.h"

namespace cam {
namespace {

std::string deg(double value) { return formatNumber(value) + "°"; }

class Validator {
public:
    Validator(const Project& project, ValidationOptions options)
        : m_project(project), m_options(options) {}

    Diagnostics run() {
        checkMotion();
        checkContour();
        checkFollower();
        checkSampling();
        checkMachining();
        return std::move(m_out);
    }

private:
    void error(std::string location, std::string message) {
        m_out.push_back({std::move(location), std::move(message), Severity::Error});
    }

    /// Finite with |value| <= 1e6 mm; returns false (and reports) otherwise.
    bool checkLength(const std::string& location, double value) {
        if (!std::isfinite(value)) {
            error(location, "must be a finite number (got " + formatNumber(value) + ")");
            return false;
        }
        if (std::abs(value) > kMaxLengthMm) {
            error(location, "magnitude must be at most 1e6 mm (got " + formatNumber(value) + ")");
            return false;
        }
        return true;
    }

    bool checkPoint(const std::string& location, const Eigen::Vector2d& p) {
        const bool x = checkLength(location + "[0]", p.x());
        const bool y = checkLength(location + "[1]", p.y());
        return x && y;
    }

    bool checkPositive(const std::string& location, double value, bool isLength) {
        if (isLength && !checkLength(location, value)) return false;
        if (!std::isfinite(value)) {
            error(location, "must be a finite number (got " + formatNumber(value) + ")");
            return false;
        }
        if (!(value > 0.0)) {
            error(location, "must be > 0 (got " + formatNumber(value) + ")");
            return false;
        }
        return true;
    }

    void checkMotion() {
        const MotionSpec& m = m_project.motion;
        const char* key = m.unit == SpeedUnit::OmegaRadS ? "motion.omega_rad_s"
                          : m.unit == SpeedUnit::Rpm     ? "motion.rpm"
                                                         : "motion.period_s";
        if (!std::isfinite(m.value)) {
            error(key, "must be a finite number (got " + formatNumber(m.value) + ")");
        } else if (m.unit == SpeedUnit::PeriodS && !(m.value > 0.0)) {
            error(key, "must be > 0 (got " + formatNumber(m.value) + ")");
        } else if (m.value == 0.0) {
            error(key, "must not be 0 (its sign gives the turning direction)");
        }
    }

    void checkContour() {
        const auto& segments = m_project.contour;
        if (segments.empty()) {
            error("contour", "must have at least one segment");
            return;
        }
        bool allShapesValid = true;
        bool windowsValid = true;
        for (std::size_t k = 0; k < segments.size(); ++k) {
            const bool window = checkWindow(k);
            windowsValid = windowsValid && window;
            allShapesValid = checkShape(k, window) && allShapesValid;
        }
        if (!windowsValid) return;
        const bool chainValid = checkContiguity();
        if (allShapesValid && chainValid && m_options.checkJoints) checkJoints();
    }

    bool checkWindow(std::size_t k) {
        const SegmentSpec& s = m_project.contour[k];
        const std::string at = segmentLocation(k);
        bool ok = true;
        for (auto [name, value] :
             {std::pair{".phi_start", s.phiStartDeg}, std::pair{".phi_end", s.phiEndDeg}}) {
            if (!std::isfinite(value) || std::abs(value) > 1e6) {
                error(at + name, "must be a finite angle of magnitude at most 1e6° (got " +
                                     formatNumber(value) + ")");
                ok = false;
            }
        }
        if (ok && !(s.phiEndDeg > s.phiStartDeg)) {
            error(at + ".phi_end", "must be greater than phi_start " + deg(s.phiStartDeg) +
                                       " (got " + deg(s.phiEndDeg) + ")");
            ok = false;
        }
        return ok;
    }

    bool checkShape(std::size_t k, bool windowValid) {
        const SegmentSpec& s = m_project.contour[k];
        const std::string at = segmentLocation(k);
        if (isSpline(s.type)) return checkSpline(k, windowValid);
        if (s.type == SegmentType::Arc) {
            const bool center = checkPoint(at + ".center", s.center);
            const bool radius = checkPositive(at + ".radius", s.radius, true);
            if (!(center && radius)) return false;
            return !windowValid || checkArcWindow(k);
        }
        const bool from = checkPoint(at + ".from", s.from);
        const bool to = checkPoint(at + ".to", s.to);
        if (!(from && to)) return false;
        if ((s.to - s.from).norm() <= kJointToleranceMm) {
            error(at + ".to", "must differ from `from` (the line has no length)");
            return false;
        }
        const double cross = s.from.x() * s.to.y() - s.from.y() * s.to.x();
        const Line line{s.from, s.to};
        if (line.distance() <= kJointToleranceMm) {
            error(at,
                  "the line passes through the rotation centre, so the follower ray meets "
                  "it at no angle or at every point");
            return false;
        }
        if (cross <= 0.0) {
            error(at, "the line runs clockwise around the rotation centre (from " +
                          deg(radToDeg(std::atan2(s.from.y(), s.from.x()))) + " to " +
                          deg(radToDeg(std::atan2(s.to.y(), s.to.x()))) +
                          "); swap `from` and `to`");
            return false;
        }
        if (!windowValid) return false;
        const auto [start, end] = lineWindowDeg(s, s.phiStartDeg);
        if (std::abs(wrapDeg(s.phiStartDeg - start)) > kLineWindowToleranceDeg ||
            std::abs(wrapDeg(s.phiEndDeg - end)) > kLineWindowToleranceDeg ||
            std::abs((s.phiEndDeg - s.phiStartDeg) - (end - start)) > kLineWindowToleranceDeg) {
            error(at, "window " + deg(s.phiStartDeg) + " .. " + deg(s.phiEndDeg) +
                          " disagrees with the polar angles of from/to (" + deg(start) + " .. " +
                          deg(end) + ")");
            return false;
        }
        return true;
    }

    /// Bézier and Hermite: finite points, the window on the polar angles of the end points, and
    /// the ray meeting the curve exactly once at every angle inside the window.
    bool checkSpline(std::size_t k, bool windowValid) {
        const SegmentSpec& s = m_project.contour[k];
        const std::string at = segmentLocation(k);
        const bool bezier = s.type == SegmentType::Bezier;
        const char* names[] = {".p0", ".t0", ".p3", ".t1"};
        bool ok = true;
        for (std::size_t i = 0; i < 4; ++i) {
            const std::string where =
                bezier ? at + ".points[" + std::to_string(i) + "]" : at + names[i];
            ok = checkPoint(where, s.controls[i]) && ok;
        }
        if (!ok || !windowValid) return false;
        const auto [from, to] = endPointsOf(s);
        if (from.norm() <= kJointToleranceMm || to.norm() <= kJointToleranceMm) {
            error(at, "an end point lies on the rotation centre");
            return false;
        }
        const auto [start, end] = lineWindowDeg(s, s.phiStartDeg);
        if (!(end > start)) {
            error(at, "the curve runs clockwise around the rotation centre (from " + deg(start) +
                          " to " + deg(end) + "); reverse its points");
            return false;
        }
        if (std::abs(wrapDeg(s.phiStartDeg - start)) > kLineWindowToleranceDeg ||
            std::abs(wrapDeg(s.phiEndDeg - end)) > kLineWindowToleranceDeg ||
            std::abs((s.phiEndDeg - s.phiStartDeg) - (end - start)) > kLineWindowToleranceDeg) {
            error(at, "window " + deg(s.phiStartDeg) + " .. " + deg(s.phiEndDeg) +
                          " disagrees with the polar angles of its end points (" + deg(start) +
                          " .. " + deg(end) + ")");
            return false;
        }
        const CubicBezier curve = bezierOf(s);
        constexpr int kChecks = 256;
        for (int i = 1; i < kChecks; ++i) {
            const double phiDeg = s.phiStartDeg + (s.phiEndDeg - s.phiStartDeg) * i / kChecks;
            const double phi = degToRad(phiDeg);
            const std::size_t hits = curve.rayParameters(std::cos(phi), std::sin(phi)).size();
            if (hits != 1) {
                error(at, "the follower ray meets the curve " + std::to_string(hits) +
                              " times at " + deg(phiDeg) +
                              "; inside its window it must meet it exactly once");
                return false;
            }
        }
        return true;
    }

    /// The ray meets the circle with r > 0 across the whole window (math.md §1).
    bool checkArcWindow(std::size_t k) {
        const SegmentSpec& s = m_project.contour[k];
        const std::string at = segmentLocation(k);
        const double dist = s.center.norm();
        const double rel = (dist - s.radius) / s.radius;
        if (s.branch == Branch::Inner && rel <= 1e-12) {
            error(at + ".branch",
                  "the rotation centre lies inside this circle, so the inner "
                  "intersection is behind the follower (r <= 0); use \"outer\"");
            return false;
        }
        if (rel < -1e-12) return true;  // centre inside the circle: the outer branch is total
        // Centre outside (or on) the circle: the ray meets it within alpha of the centre's angle.
        const double alphaDeg = rel <= 1e-12 ? 90.0 : radToDeg(std::asin(s.radius / dist));
        const double centerDeg = radToDeg(std::atan2(s.center.y(), s.center.x()));
        const double lo = wrapDeg(s.phiStartDeg - centerDeg);
        const double hi = lo + (s.phiEndDeg - s.phiStartDeg);
        constexpr double kTangentTolDeg = 1e-7;
        if (lo < -alphaDeg - kTangentTolDeg || hi > alphaDeg + kTangentTolDeg) {
            error(at, "the follower ray misses the circle inside the window " + deg(s.phiStartDeg) +
                          " .. " + deg(s.phiEndDeg) + "; it meets it only for phi in " +
                          deg(centerDeg - alphaDeg) + " .. " + deg(centerDeg + alphaDeg));
            return false;
        }
        return true;
    }

    bool checkContiguity() {
        const auto& c = m_project.contour;
        bool ok = true;
        for (std::size_t k = 0; k + 1 < c.size(); ++k) {
            const double end = c[k].phiEndDeg;
            const double next = c[k + 1].phiStartDeg;
            const double diff = next - end;
            if (std::abs(diff) > kWindowToleranceDeg) {
                error(segmentLocation(k) + "/" + segmentLocation(k + 1),
                      std::string(diff > 0 ? "gap" : "overlap") + " of " + deg(std::abs(diff)) +
                          " between phi_end " + formatNumber(end) + " and phi_start " +
                          formatNumber(next));
                ok = false;
            }
        }
        const double span = c.back().phiEndDeg - c.front().phiStartDeg;
        if (std::abs(span - 360.0) > kWindowToleranceDeg) {
            error("contour", "the windows cover " + deg(span) + " (from " +
                                 deg(c.front().phiStartDeg) + " to " + deg(c.back().phiEndDeg) +
                                 "); they must cover exactly one turn, 360°");
            ok = false;
        }
        return ok;
    }

    void checkJoints() {
        const auto& c = m_project.contour;
        for (std::size_t k = 0; k < c.size(); ++k) {
            const std::size_t next = (k + 1) % c.size();
            const double angle = c[k].phiEndDeg;
            const Eigen::Vector2d left = pointOnSegment(c[k], angle);
            const Eigen::Vector2d right = pointOnSegment(c[next], c[next].phiStartDeg);
            const double gap = (left - right).norm();
            if (!(gap <= kJointToleranceMm)) {
                error(segmentLocation(k) + "/" + segmentLocation(next),
                      "the segments do not meet at " + deg(angle) + ": gap of " +
                          formatNumber(gap) + " mm (at most 1e-06 mm allowed)");
            }
        }
    }

    void checkFollower() {
        if (!m_project.follower) return;
        const FollowerSpec& f = *m_project.follower;
        checkLength("follower.offset", f.offset);
        if (f.type == FollowerType::Roller) checkPositive("follower.radius", f.radius, true);
    }

    void checkSampling() {
        if (!m_project.samplesPerTurn) return;
        const auto n = *m_project.samplesPerTurn;
        if (n < kMinSamplesPerTurn || n > kMaxSamplesPerTurn) {
            error("sampling.samples_per_turn",
                  "must be between 16 and 10000000 (got " + std::to_string(n) + ")");
        }
    }

    void checkMachining() {
        if (!m_project.machining) return;
        const MachiningSpec& m = *m_project.machining;
        auto checkAxes = [&](const std::string& key, const std::vector<double>& values) {
            if (values.size() < 2 || values.size() > 3) {
                error(key, "must list 2 or 3 axes (got " + std::to_string(values.size()) + ")");
            }
            for (std::size_t i = 0; i < values.size(); ++i) {
                checkPositive(key + "[" + std::to_string(i) + "]", values[i], false);
            }
        };
        checkAxes("machining.axis_accel", m.axisAccel);
        if (!m.axisVmax.empty()) checkAxes("machining.axis_vmax", m.axisVmax);
        checkPositive("machining.feed_max", m.feedMax, false);
        if (checkLength("machining.tool_radius", m.toolRadius) && m.toolRadius < 0.0) {
            error("machining.tool_radius", "must be >= 0 (got " + formatNumber(m.toolRadius) + ")");
        }
        checkPositive("machining.step", m.step, true);
    }

    const Project& m_project;
    ValidationOptions m_options;
    Diagnostics m_out;
};

}  // namespace

std::string segmentLocation(std::size_t index) { return "contour[" + std::to_string(index) + "]"; }

std::pair<double, double> lineWindowDeg(const SegmentSpec& segment, double nearDeg) {
    const auto [from, to] = endPointsOf(segment);
    double start = radToDeg(std::atan2(from.y(), from.x()));
    start = nearDeg + wrapDeg(start - nearDeg);
    const double cross = from.x() * to.y() - from.y() * to.x();
    const double dot = from.dot(to);
    const double sweep = radToDeg(std::atan2(cross, dot));
    return {start, start + sweep};
}

Diagnostics validateProject(const Project& project, ValidationOptions options) {
    return Validator(project, options).run();
}

}  // namespace cam
