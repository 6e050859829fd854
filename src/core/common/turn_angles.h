#pragma once
/// @file
/// @brief cos and sin of the sample angles φ_k = ω·(k·dt) of one turn, by blocks: the
/// angle-sum rule on cos/sin(b·B·dφ) and cos/sin(j·dφ), both from std::cos/sin. Unlike a
/// running recurrence this has no loop-carried dependency (loops over it vectorise) and no
/// error growth (a few ulp, always). Shared by the kinematics and the follower's turn sampling.

#include <cmath>
#include <cstddef>
#include <vector>

namespace cam {

/// @brief The block table for samples [first, first + count) of a turn sampled every dt.
struct TurnAngles {
    static constexpr std::size_t kBlockBits = 10;
    static constexpr std::size_t kBlock = std::size_t{1} << kBlockBits;

    std::vector<double> ct, st;  ///< cos/sin(j·dφ), j < kBlock
    std::vector<double> cb, sb;  ///< cos/sin of each block's first angle, from firstBlock on
    std::size_t firstBlock = 0;

    TurnAngles(double omega, double dt, std::size_t first, std::size_t count)
        : ct(kBlock), st(kBlock), firstBlock(first >> kBlockBits) {
        const double dphi = omega * dt;
        const std::size_t blocks =
            count == 0 ? 0 : ((first + count - 1) >> kBlockBits) - firstBlock + 1;
        cb.resize(blocks);
        sb.resize(blocks);
        for (std::size_t j = 0; j < kBlock; ++j) {
            ct[j] = std::cos(static_cast<double>(j) * dphi);
            st[j] = std::sin(static_cast<double>(j) * dphi);
        }
        for (std::size_t b = 0; b < blocks; ++b) {
            const double angle = omega * (static_cast<double>((firstBlock + b) * kBlock) * dt);
            cb[b] = std::cos(angle);
            sb[b] = std::sin(angle);
        }
    }

    /// The block of sample k and its first index.
    [[nodiscard]] static std::size_t blockOf(std::size_t k) { return k >> kBlockBits; }
    [[nodiscard]] static std::size_t blockEnd(std::size_t k) {
        return (blockOf(k) + 1) << kBlockBits;
    }
    [[nodiscard]] double blockCos(std::size_t k) const { return cb[blockOf(k) - firstBlock]; }
    [[nodiscard]] double blockSin(std::size_t k) const { return sb[blockOf(k) - firstBlock]; }
};

}  // namespace cam
