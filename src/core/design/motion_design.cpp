#include "design/motion_design.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/angles.h"
#include "common/translate_marker.h"
#include "design/boundary_classes.h"
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
Result<MotionDesign> MotionDesign::build(const DesignSpec& spec) { return assemble(spec, true); }

Result<MotionDesign> MotionDesign::buildIgnoringJoints(const DesignSpec& spec) {
    return assemble(spec, false);
}

Result<MotionDesign> MotionDesign::assemble(const DesignSpec& spec, bool jointsMustFit) {
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
              std::pair{DesignPart::V1, s.v1}, std::pair{DesignPart::A1, s.a1},
              std::pair{DesignPart::J0, s.j0}, std::pair{DesignPart::J1, s.j1},
              std::pair{DesignPart::Lambda, s.lambda}, std::pair{DesignPart::SccaB, s.sccaB},
              std::pair{DesignPart::SccaD, s.sccaD}}) {
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
        const LawShape shape = motionLaw(s.law).shape;
        if (shape == LawShape::Dwell && s.lift != startLift) {
            error(at(DesignPart::Lift), DiagnosticCode::DwellLiftChanges, {startLift, s.lift});
        } else if ((shape == LawShape::Normalised || shape == LawShape::Table) &&
                   s.lift == startLift) {
            error(at(DesignPart::Lift), DiagnosticCode::LiftUnchanged,
                  {startLift, std::string(lawName(s.law))});
        }
        if (lawUses(s.law, DesignPart::Lambda) &&
            !(s.lambda >= kMinLawLambda && s.lambda <= 1.0 - kMinLawLambda)) {
            error(at(DesignPart::Lambda), DiagnosticCode::OutOfRange,
                  {kMinLawLambda, 1.0 - kMinLawLambda, std::string{}, s.lambda});
        }
        if (lawUses(s.law, DesignPart::SccaB)) {
            bool inRange = true;
            for (auto [part, v] :
                 {std::pair{DesignPart::SccaB, s.sccaB}, std::pair{DesignPart::SccaD, s.sccaD}}) {
                if (!(v >= 0.0 && v <= 1.0)) {
                    error(at(part), DiagnosticCode::OutOfRange, {0.0, 1.0, std::string{}, v});
                    inRange = false;
                }
            }
            if (inRange && s.sccaB + s.sccaD > 1.0 + 1e-12) {
                error(at(DesignPart::SccaD), DiagnosticCode::SccaSharesExceedOne,
                      {s.sccaB, s.sccaD});
            }
        }
        design.m_startRad.push_back(degToRad(startDeg));
        design.m_endRad.push_back(degToRad(s.toDeg));
        design.m_startLift.push_back(startLift);
        // The law, prepared (its parameters are checked above, its table here).
        SegmentLaw law;
        const double h = degToRad(s.toDeg) - degToRad(startDeg);
        const double perRad = 180.0 / kPi;
        switch (shape) {
            case LawShape::Dwell:
                break;
            case LawShape::Normalised:
                if (s.law == MotionLawType::Scca) {
                    law = SccaLaw(s.sccaB, s.sccaD);
                } else {
                    law = lawParameters(s, s.toDeg - startDeg, s.lift - startLift);
                }
                break;
            case LawShape::BoundaryValues:
                // The file's slopes are per degree; the polynomial works per radian.
                if (s.law == MotionLawType::Poly7) {
                    law = Poly7Law(
                        h, startLift, s.lift,
                        {s.v0 * perRad, s.a0 * perRad * perRad, s.j0 * perRad * perRad * perRad},
                        {s.v1 * perRad, s.a1 * perRad * perRad, s.j1 * perRad * perRad * perRad});
                } else {
                    law = Poly5Law(h, startLift, s.lift, s.v0 * perRad, s.a0 * perRad * perRad,
                                   s.v1 * perRad, s.a1 * perRad * perRad);
                }
                break;
            case LawShape::Table: {
                auto spline = MotionTableSpline::build(s.table, at(DesignPart::Points));
                if (!spline.ok()) {
                    for (const Diagnostic& d : spline.errors()) errors.push_back(d);
                } else {
                    law = std::make_shared<const MotionTableSpline>(std::move(spline.value()));
                }
                break;
            }
        }
        design.m_laws.push_back(std::move(law));
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
    double stroke = 1.0;
    for (const DesignSegmentSpec& s : spec.segments) stroke = std::max(stroke, std::abs(s.lift));
    design.m_zero = 1e-9 * stroke;
    // Where velocity or acceleration jump, the turn's end joining its start. A velocity jump
    // is a law that cannot meet its boundary: refused at the law that must change.
    const std::size_t n = spec.segments.size();
    const double perDeg = kPi / 180.0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t next = (k + 1) % n;
        const std::array<double, 4> left = design.endOf(k);
        const std::array<double, 4> right = design.startOf(next);
        const bool velocity = std::abs(left[1] - right[1]) > design.m_zero;
        const bool acceleration = std::abs(left[2] - right[2]) > design.m_zero;
        if (velocity && jointsMustFit) {
            // The side that must change: a dwell never can, a line only where the other side
            // is a dwell; between equals, the later segment.
            const auto rank = [&](std::size_t s) {
                const MotionLawType law = spec.segments[s].law;
                return law == MotionLawType::Dwell ? 2 : law == MotionLawType::ConstantVelocity;
            };
            const bool atStart = rank(next) <= rank(k);
            const std::size_t changes = atStart ? next : k;
            const double own = (atStart ? right[1] : left[1]) * perDeg;
            const double other = (atStart ? left[1] : right[1]) * perDeg;
            const double otherA = atStart ? left[2] : right[2];
            const BoundaryClass required = classifyBoundary(other / perDeg, otherA, design.m_zero);
            errors.push_back(
                Diagnostic::make(DesignSegmentPlace{changes, DesignPart::Law},
                                 DiagnosticCode::DesignBoundaryMismatch,
                                 {std::string(lawName(spec.segments[changes].law)),
                                  std::string(boundaryClassTerm(required)),
                                  std::string(atStart ? CAM_TRANSLATE_NOOP("Diagnostic", "start")
                                                      : CAM_TRANSLATE_NOOP("Diagnostic", "end")),
                                  own, other}));
            continue;
        }
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
    if (!errors.empty()) return errors;
    return design;
}

std::array<double, 4> MotionDesign::inSegment(std::size_t k, double phi) const {
    const DesignSegmentSpec& s = m_spec.segments[k];
    const double h = m_endRad[k] - m_startRad[k], y0 = m_startLift[k], d = s.lift - y0;
    const double x = std::clamp((phi - m_startRad[k]) / h, 0.0, 1.0);
    const SegmentLaw& law = m_laws[k];
    const auto scaled = [&](const LawPoint& p) -> std::array<double, 4> {
        return {y0 + d * p.y, d * p.v / h, d * p.a / (h * h), d * p.j / (h * h * h)};
    };
    if (const auto* params = std::get_if<LawParameters>(&law)) {
        return scaled(normalisedLaw(s.law, x, *params));
    }
    if (const auto* scca = std::get_if<SccaLaw>(&law)) return scaled(scca->at(x));
    if (const auto* table = std::get_if<std::shared_ptr<const MotionTableSpline>>(&law)) {
        return scaled((*table)->at(x));
    }
    if (const auto* poly5 = std::get_if<Poly5Law>(&law)) {
        const LawPoint p = poly5->at(x);
        return {p.y, p.v, p.a, p.j};
    }
    if (const auto* poly7 = std::get_if<Poly7Law>(&law)) {
        const LawPoint p = poly7->at(x);
        return {p.y, p.v, p.a, p.j};
    }
    return {y0, 0.0, 0.0, 0.0};
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
    if (const auto* params = std::get_if<LawParameters>(&m_laws[k])) {
        return lawCoefficients(s.law, *params);
    }
    if (const auto* scca = std::get_if<SccaLaw>(&m_laws[k])) return scca->coefficients();
    if (std::holds_alternative<std::monostate>(m_laws[k])) return {};
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
