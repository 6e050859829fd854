#include "design/motion_design.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/angles.h"
#include "project/validate.h"

namespace cam {

Diagnostics designProblems(const Project& project) {
    if (!project.design) return {};
    const DesignSpec& d = *project.design;
    Diagnostics out;
    // Not finite or not positive: MotionDesign says so; here only the upper bound.
    for (const auto& [field, value] : {std::pair{Field::DesignBaseRadius, d.baseRadius},
                                       std::pair{Field::DesignTolerance, d.tolerance}}) {
        if (!std::isfinite(value)) continue;
        if (auto problem = lengthProblem(FieldPlace{field}, value)) {
            out.push_back(std::move(*problem));
        }
    }
    const Result<MotionDesign> motion = MotionDesign::build(d);
    for (const Diagnostic& problem : motion.errors()) out.push_back(problem);
    return out;
}
Result<MotionDesign> MotionDesign::build(const DesignSpec& spec) {
    Diagnostics errors;
    const auto error = [&](Place place, DiagnosticCode code, std::vector<DiagnosticArg> args) {
        errors.push_back(Diagnostic::make(std::move(place), code, std::move(args)));
    };
    const auto positive = [&](Field field, double value) {
        if (!std::isfinite(value) || !(value > 0.0)) {
            error(FieldPlace{field}, DiagnosticCode::NotPositive, {value});
        }
    };
    positive(Field::DesignBaseRadius, spec.baseRadius);
    positive(Field::DesignTolerance, spec.tolerance);
    if (spec.segments.empty()) {
        error(FieldPlace{Field::DesignSegments}, DiagnosticCode::NoSegments, {});
    }
    double startDeg = 0.0, startLift = 0.0;
    MotionDesign design(spec);
    for (std::size_t k = 0; k < spec.segments.size(); ++k) {
        const DesignSegmentSpec& s = spec.segments[k];
        const auto at = [k](DesignPart part) { return DesignSegmentPlace{k, part}; };
        bool finite = true;
        for (auto [part, v] :
             {std::pair{DesignPart::ToDeg, s.toDeg}, std::pair{DesignPart::Lift, s.lift},
              std::pair{DesignPart::V0, s.v0}, std::pair{DesignPart::A0, s.a0},
              std::pair{DesignPart::V1, s.v1}, std::pair{DesignPart::A1, s.a1}}) {
            if (!std::isfinite(v)) {
                error(at(part), DiagnosticCode::NotFinite, {v});
                finite = false;
            }
        }
        if (!finite) continue;
        if (!(s.toDeg > startDeg)) {
            error(at(DesignPart::ToDeg), DiagnosticCode::DesignEndNotAfterStart,
                  {startDeg, s.toDeg});
        } else if (s.toDeg > 360.0) {
            error(at(DesignPart::ToDeg), DiagnosticCode::DesignEndBeyondTurn, {s.toDeg});
        }
        if (motionLaw(s.law).shape == LawShape::Dwell && s.lift != startLift) {
            error(at(DesignPart::Lift), DiagnosticCode::DwellLiftChanges, {startLift, s.lift});
        } else if (motionLaw(s.law).shape == LawShape::Normalised && s.lift == startLift) {
            error(at(DesignPart::Lift), DiagnosticCode::LiftUnchanged,
                  {startLift, std::string(lawName(s.law))});
        }
        design.m_startRad.push_back(degToRad(startDeg));
        design.m_endRad.push_back(degToRad(s.toDeg));
        design.m_startLift.push_back(startLift);
        startDeg = s.toDeg;
        startLift = s.lift;
    }
    if (!spec.segments.empty()) {
        const std::size_t last = spec.segments.size() - 1;
        if (std::isfinite(spec.segments.back().toDeg) && spec.segments.back().toDeg != 360.0) {
            error(DesignSegmentPlace{last, DesignPart::ToDeg}, DiagnosticCode::DesignLastNot360,
                  {spec.segments.back().toDeg});
        }
        if (std::isfinite(startLift) && startLift != 0.0) {
            error(DesignSegmentPlace{last, DesignPart::Lift}, DiagnosticCode::DesignNotReturning,
                  {startLift});
        }
    }
    if (!errors.empty()) return errors;
    // Where velocity or acceleration jump, the turn's end joining its start.
    const std::size_t n = spec.segments.size();
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t next = (k + 1) % n;
        const std::array<double, 4> left = design.inSegment(k, design.m_endRad[k]);
        const std::array<double, 4> right = design.inSegment(next, design.m_startRad[next]);
        const double stroke = std::max({std::abs(left[0]), 1.0});
        const double perDeg = kPi / 180.0;
        const bool velocity = std::abs(left[1] - right[1]) > 1e-9 * stroke;
        const bool acceleration = std::abs(left[2] - right[2]) > 1e-9 * stroke;
        std::vector<DiagnosticArg> args;
        if (velocity) args = {left[1] * perDeg, right[1] * perDeg};
        if (acceleration) {
            args.insert(args.end(), {left[2] * perDeg * perDeg, right[2] * perDeg * perDeg});
        }
        if (velocity || acceleration) {
            const DiagnosticCode code = velocity && acceleration
                                            ? DiagnosticCode::DesignVelocityAndAccelerationJump
                                        : velocity ? DiagnosticCode::DesignVelocityJump
                                                   : DiagnosticCode::DesignAccelerationJump;
            design.m_jumps.push_back(
                Diagnostic::make(DesignJointPlace{k, next}, code, std::move(args), Severity::Info));
        }
    }
    return design;
}

std::array<double, 4> MotionDesign::inSegment(std::size_t k, double phi) const {
    const DesignSegmentSpec& s = m_spec.segments[k];
    const double h = m_endRad[k] - m_startRad[k], y0 = m_startLift[k], d = s.lift - y0;
    const double x = (phi - m_startRad[k]) / h;
    if (motionLaw(s.law).shape == LawShape::Dwell) return {y0, 0.0, 0.0, 0.0};
    if (motionLaw(s.law).shape == LawShape::BoundaryValues) {
        // The file's slopes are per degree; the polynomial works per radian.
        const double perRad = 180.0 / kPi;
        const Poly5Law law(h, y0, s.lift, s.v0 * perRad, s.a0 * perRad * perRad, s.v1 * perRad,
                           s.a1 * perRad * perRad);
        const LawPoint p = law.at(std::clamp(x, 0.0, 1.0));
        return {p.y, p.v, p.a, p.j};
    }
    const LawPoint p = normalisedLaw(s.law, x);
    return {y0 + d * p.y, d * p.v / h, d * p.a / (h * h), d * p.j / (h * h * h)};
}

std::size_t MotionDesign::segmentAt(double phi) const {
    double into = std::fmod(phi, kTwoPi);
    if (into < 0.0) into += kTwoPi;
    const auto it = std::upper_bound(m_endRad.begin(), m_endRad.end(), into);
    return std::min<std::size_t>(static_cast<std::size_t>(it - m_endRad.begin()),
                                 m_endRad.size() - 1);
}

std::array<double, 4> MotionDesign::liftAt(double phi) const {
    double into = std::fmod(phi, kTwoPi);
    if (into < 0.0) into += kTwoPi;
    return inSegment(segmentAt(into), into);
}

LawCoefficients MotionDesign::coefficients(std::size_t k) const {
    const DesignSegmentSpec& s = m_spec.segments[k];
    if (motionLaw(s.law).shape != LawShape::BoundaryValues) return lawCoefficients(s.law);
    // Sampled finely, normalised by the stretch: y' · h/Δ, y'' · h²/Δ, y''' · h³/Δ.
    const double h = m_endRad[k] - m_startRad[k], d = s.lift - m_startLift[k];
    const double scale = d != 0.0 ? 1.0 / std::abs(d) : 1.0;
    LawCoefficients c;
    constexpr int kSamples = 20000;
    for (int i = 0; i <= kSamples; ++i) {
        const std::array<double, 4> l =
            inSegment(k, m_startRad[k] + h * static_cast<double>(i) / kSamples);
        c.cv = std::max(c.cv, std::abs(l[1]) * h * scale);
        c.ca = std::max(c.ca, std::abs(l[2]) * h * h * scale);
        c.cj = std::max(c.cj, std::abs(l[3]) * h * h * h * scale);
    }
    return c;
}

}  // namespace cam
