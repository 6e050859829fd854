#pragma once
/// @file
/// @brief The cancel flag that long computations poll (null: never cancelled).

#include <atomic>
#include <cstddef>

#include "common/diagnostic.h"

namespace cam {

/// @brief True once the optional flag is set.
[[nodiscard]] inline bool cancelRequested(const std::atomic<bool>* cancel) {
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
}

/// @brief Inner loops (grid points, seed steps, plot samples) read the flag once per this many
/// iterations: some tens of microseconds of work, so a cancel is honoured within a millisecond.
inline constexpr std::size_t kCancelPollInterval = 4096;

/// @brief What a computation stopped by its cancel flag returns.
[[nodiscard]] inline Diagnostics cancelledDiagnostics() {
    return {Diagnostic::make({}, DiagnosticCode::Cancelled)};
}

}  // namespace cam
