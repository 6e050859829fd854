#include "contour/contour.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "project/validate.h"

namespace cam {

PolarDerivatives ContourSegment::evaluate(double phi) const {
    return evaluate(std::cos(phi), std::sin(phi));
}

Result<Contour> Contour::build(const Project& project, ValidationOptions options) {
    Diagnostics errors = validateProject(project, options);
    if (hasErrors(errors)) return errors;
    return buildValidated(project);
}

Diagnostic contourNeverSynthesised() {
    return Diagnostic::make(FieldPlace{Field::Contour}, DiagnosticCode::ContourNeverSynthesised);
}

Result<Contour> Contour::buildValidated(const Project& project) {
    // Valid only as a design waiting for its synthesis: nothing to compute yet.
    if (project.contour.empty()) return Diagnostics{contourNeverSynthesised()};
    Contour contour;
    contour.m_segments.reserve(project.contour.size());
    for (const SegmentSpec& spec : project.contour) {
        ContourSegment seg;
        seg.type = spec.type();
        if (const auto* arc = spec.as<Arc>()) {
            seg.arc = *arc;
            seg.arcKernel = arc->kernel();
        } else if (const auto* line = spec.as<Line>()) {
            seg.line = *line;
            seg.lineKernel = line->kernel();
        } else {
            seg.bezierKernel = bezierOf(spec).kernel();
        }
        seg.phiStart = degToRad(spec.phiStartDeg);
        seg.phiEnd = degToRad(spec.phiEndDeg);
        contour.m_segments.push_back(seg);
    }
    // Degrees → radians may round the shared boundaries differently; make them identical and
    // make the last window end exactly one turn after the first begins.
    for (std::size_t k = 0; k + 1 < contour.m_segments.size(); ++k) {
        contour.m_segments[k].phiEnd = contour.m_segments[k + 1].phiStart;
    }
    contour.m_segments.back().phiEnd = contour.phiBegin() + kTwoPi;
    return contour;
}

double Contour::normalize(double phi) const {
    const double begin = phiBegin();
    double x = std::fmod(phi - begin, kTwoPi);
    if (x < 0.0) x += kTwoPi;
    double normalized = begin + x;
    if (normalized >= begin + kTwoPi) normalized = begin;
    return normalized;
}

std::size_t Contour::segmentAtNormalized(double phiNormalized) const {
    // First window whose end lies beyond phi: windows are [start, end).
    const auto it = std::upper_bound(
        m_segments.begin(), m_segments.end(), phiNormalized,
        [](double value, const ContourSegment& seg) { return value < seg.phiEnd; });
    if (it == m_segments.end()) return m_segments.size() - 1;
    return static_cast<std::size_t>(it - m_segments.begin());
}

std::size_t Contour::segmentAt(double phi) const { return segmentAtNormalized(normalize(phi)); }

}  // namespace cam
