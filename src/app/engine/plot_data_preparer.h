#pragma once
/// @file
/// @brief How the views get their own drawing data made in the worker thread: the engine knows
/// only this interface; the views implement it (views/plot_data.h) and the main window installs
/// it. The engine's results stay plain data, and the GUI thread only swaps pointers and draws.

#include <atomic>

#include "engine/compute_result.h"

namespace cam {

class PlotDataPreparer {
public:
    virtual ~PlotDataPreparer() = default;
    /// @brief Called in the worker thread on a complete result before anyone else sees it.
    /// Must be thread-safe (const, no GUI objects); may poll `cancel`; may throw (the worker
    /// reports the failure instead of showing the result).
    [[nodiscard]] virtual PreparedPlotDataPtr prepare(const ComputeResult& result,
                                                      const std::atomic<bool>& cancel) const = 0;
    /// @brief The same for the machining times.
    [[nodiscard]] virtual PreparedPlotDataPtr prepareTiming(const TimingOutcome& outcome) const = 0;
};

}  // namespace cam
