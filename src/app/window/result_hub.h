#pragma once
/// @file
/// @brief Where the engine's results reach the views. Each result is handed out in an order
/// that keeps editing smooth: the plots first (arrived), the views beside them once the plots
/// are drawn (settled), a refined first picture to the plots alone (refined). Views subscribe
/// to the signal they need; nobody calls a view by name for a result.

#include <QObject>

#include "engine/compute_result.h"

namespace cam {

class ComputeEngine;

class ResultHub : public QObject {
    Q_OBJECT
public:
    explicit ResultHub(ComputeEngine* engine, QObject* parent = nullptr);

    /// @brief The last result that could be computed: what the views draw (null before one,
    /// and while a design awaits its contour).
    [[nodiscard]] const ComputeResultPtr& shown() const { return m_shown; }

    /// @brief Runs the event loop until the plots show the result of the newest request, with
    /// every plot level.
    bool waitForCurrent(int timeoutMs);

signals:
    /// A result of a newer request, computable or not: the plots and what shares their axis
    /// take it first.
    void arrived(const cam::ComputeResultPtr& result);
    /// The shown result again with its finer plot levels; `checks`: with the follower's design
    /// checks, which the first picture left out.
    void refined(const cam::ComputeResultPtr& result, bool checks);
    /// A result that could not be computed: the views beside the plots mark what they show as
    /// out of date.
    void uncomputed(const cam::ComputeResultPtr& result);
    /// A computable result, once the plots have drawn it: the views beside them take it.
    void settled(const cam::ComputeResultPtr& result);
    /// After each of the above has been handed out.
    void handed(const cam::ComputeResultPtr& result);

private:
    void take(const ComputeResultPtr& result);

    ComputeEngine* m_engine;
    ComputeResultPtr m_shown;
    /// The request of the last result handed out (computable or not; its refinement has the
    /// same).
    std::uint64_t m_handedGeneration = 0;
};

}  // namespace cam
