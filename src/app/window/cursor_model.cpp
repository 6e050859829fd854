#include "window/cursor_model.h"

#include <cmath>
#include <limits>

#include "common/angles.h"
#include "engine/compute_engine.h"
#include "window/result_hub.h"

namespace cam {
namespace {

/// Any instant read within the turn of period T: 0 <= t < T.
double timeInTurn(double t, double T) {
    t = std::fmod(t, T);
    if (t < 0.0) t += T;
    return t >= T ? 0.0 : t;
}

}  // namespace

CursorModel::CursorModel(const ResultHub* results, const ComputeEngine* engine, QObject* parent)
    : QObject(parent), m_results(results), m_engine(engine) {}

void CursorModel::setAtAngle(double phi) {
    const ComputeResultPtr& r = m_results->shown();
    if (r) setTime(phi / r->omega);  // the instant the ray points there
}

void CursorModel::setAtPlotX(double x) {
    const ComputeResultPtr& r = m_results->shown();
    if (r) setTime(r->axis == PlotAxis::Angle ? degToRad(x) / r->omega : x);
}

void CursorModel::stepSamples(int count) {
    const ComputeResultPtr& r = m_results->shown();
    if (!r || r->sampleCount == 0 || !(r->period > 0.0)) return;
    const double dt = r->period / static_cast<double>(r->sampleCount);
    setTime((std::round(m_t / dt) + count) * dt);
}

void CursorModel::stepJoints(int direction) {
    const ComputeResultPtr& r = m_results->shown();
    if (!r || r->joints.empty() || !(r->period > 0.0)) return;
    // The joints' instants within the turn, and the nearest one ahead (or behind) by more
    // than a rounding: the one the cursor stands on is not a step.
    const double T = r->period;
    const double eps = 1e-9 * T;
    double best = std::numeric_limits<double>::infinity();
    double target = m_t;
    for (const JointAnalysis& j : r->joints) {
        const double tj = timeInTurn(j.phi / r->omega, T);
        double ahead = direction > 0 ? tj - m_t : m_t - tj;  // how far, in the step's sense
        if (ahead <= eps) ahead += T;
        if (ahead < best) {
            best = ahead;
            target = tj;
        }
    }
    setTime(target);
}

void CursorModel::toTurnStart() { setTime(0.0); }

void CursorModel::toTurnEnd() {
    const ComputeResultPtr& r = m_results->shown();
    if (!r || r->sampleCount == 0) return;
    setTime(r->period * (1.0 - 1.0 / static_cast<double>(r->sampleCount)));
}

void CursorModel::setTime(double t) {
    const ComputeResultPtr& r = m_results->shown();
    const ComputeResultPtr& latest = m_engine->latestResult();
    if (!r || !latest || !latest->valid()) {
        // Nothing computed for the project as it is (a contour with open joints is drawn, but
        // its follower's state is not the cam's): no state to read out.
        m_t = t;
        emit cleared();
        return;
    }
    // Any instant, the mouse's or a joint's, is read within the turn: 0 <= t < T.
    t = timeInTurn(t, r->period);
    m_t = t;
    // One state from the shared, immutable contour of the result: a few hundred nanoseconds.
    const KinematicState s = stateAt(*r->contour, r->omega, t);
    emit moved(s, r->axis == PlotAxis::Angle ? radToDeg(s.phi) : t);
}

}  // namespace cam
