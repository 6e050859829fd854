#pragma once
/// @file
/// @brief The follower over one whole turn, sampled at the instants of sampleTurn() into flat
/// arrays: the batch path for plots, CSV columns and benchmarks. Same numbers as
/// FollowerModel::at() to rounding; on arcs and lines (translating knife, roller and flat face)
/// the pieces that can hold the contact are evaluated for a run of angles at once in vectorised
/// loops, the winner's closed form after; splines and swinging arms go through at() per angle.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "follower/follower.h"

namespace cam {

/// @brief Sample k is at t_k = k·T/n, φ_k = ω·t_k (as SampledTurn's). Units as FollowerState.
struct FollowerTurn {
    std::vector<double> s, v, a, j, pressureAngle, rhoProfile, rhoPitch;
    std::vector<std::int32_t> segment;

    [[nodiscard]] std::size_t size() const { return s.size(); }
    void resize(std::size_t n);
};

/// @brief Samples one turn of `model` at ω (≠ 0) into `out`, reusing its storage; n ≥ 1. If
/// `cancel` is given it is polled every few thousand samples; when it reads true the function
/// returns false at once and `out` holds a partial turn.
bool sampleFollowerTurn(const FollowerModel& model, double omega, std::size_t n, FollowerTurn& out,
                        const std::atomic<bool>* cancel = nullptr);

}  // namespace cam
