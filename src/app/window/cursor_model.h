#pragma once
/// @file
/// @brief The cursor: one instant of the turn that every view marks (the readout's state, the
/// contour's follower ray, the plots' dashed line). Views subscribe to moved() and cleared();
/// whoever moves the cursor (a plot, the contour, a joint, Play) calls one setter.

#include <QObject>

#include "engine/compute_result.h"
#include "kinematics/kinematics.h"

namespace cam {

class ComputeEngine;
class ResultHub;

class CursorModel : public QObject {
    Q_OBJECT
public:
    /// @brief The cursor reads its state in the result the views draw (ResultHub::shown()).
    CursorModel(const ResultHub* results, const ComputeEngine* engine, QObject* parent = nullptr);
    /// @brief The cursor's instant (s, within the turn).
    [[nodiscard]] double time() const { return m_t; }

    /// @brief Puts the cursor at time t (s; any instant, read within the turn).
    void setTime(double t);
    /// @brief At the instant the follower ray points at angle phi (rad).
    void setAtAngle(double phi);
    /// @brief At x of the plots' shared axis (degrees or seconds).
    void setAtPlotX(double x);
    /// @brief Once more where it is (a new result: its state there).
    void refresh() { setTime(m_t); }
    /// @brief By `count` samples of the turn (the result's samples per turn), from the sample
    /// nearest the cursor; the turn wraps round.
    void stepSamples(int count);
    /// @brief To the next joint of the contour in time (`direction` > 0) or the previous one;
    /// the turn wraps round. No joint (one closed segment): the cursor stays.
    void stepJoints(int direction);
    /// @brief To the first sample of the turn (t = 0) or its last (one sample before T).
    void toTurnStart();
    void toTurnEnd();

signals:
    /// The state at the cursor, and where it is on the plots' x axis (degrees or seconds).
    void moved(const KinematicState& state, double plotX);
    /// Nothing is computed for the project as it is: no state to show.
    void cleared();

private:
    const ResultHub* m_results;
    const ComputeEngine* m_engine;
    double m_t = 0.0;
};

}  // namespace cam
