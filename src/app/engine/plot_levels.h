#pragma once
/// @file
/// @brief The kinematics curves of one turn as the plots draw them, in plain data: each curve
/// at several resolutions (min/max envelopes of buckets of samples), exact at the joints, with
/// a break only where the quantity jumps. Bounded in size however many samples the turn has.

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <vector>

#include "contour/contour.h"
#include "kinematics/kinematics.h"
#include "project/project.h"

namespace cam {

/// @brief The x axis of the kinematics plots.
enum class PlotAxis { Angle, Time };

/// @brief The curves of the kinematics plots, in this order: three per plot for velocity,
/// acceleration and jerk, then the radius r of the lift plot.
enum class Curve { VR, VPhi, V, AR, APhi, A, JR, JPhi, J, R, Count };
inline constexpr std::size_t kCurveCount = static_cast<std::size_t>(Curve::Count);

/// @brief One point of a plotted curve; y is NaN where the line breaks.
struct PlotPoint {
    double x = 0.0;
    double y = 0.0;
};

struct PlotRange {
    double lower = 0.0;
    double upper = 0.0;
    [[nodiscard]] double size() const { return upper - lower; }
};

/// @brief One resolution of all curves. Each curve holds, in ascending x, the smallest and the
/// largest sample of every bucket of `samplesPerBucket` consecutive samples (1: every sample),
/// at the samples' own x; buckets never span a joint. At each joint both segments' one-sided
/// values at the joint's exact x are added, with a NaN point between them only where the
/// quantity jumps there; the turn ends with its value at T (or ±360°).
struct PlotLevel {
    std::size_t samplesPerBucket = 1;
    std::array<std::vector<PlotPoint>, kCurveCount> curves;
};

struct PlotCurves {
    /// A level holds at most this many points per curve, plus three per joint; the finest level
    /// is the samples themselves up to this count, an envelope above it.
    static constexpr std::size_t kMaxLevelPoints = 65'536;
    /// Coarser levels (the first with buckets of 8 samples after the samples themselves, then
    /// each with buckets four times as wide: a quarter of the points) are made down to this
    /// many buckets, so that even a narrow plot finds one with buckets of about a pixel. All
    /// levels together hold at most 4/3 · kMaxLevelPoints points per curve (plus the joints').
    static constexpr std::size_t kMinLevelBuckets = 256;
    /// A joint breaks a curve's line when the two one-sided values differ by more than this
    /// fraction of the plot's y span (less is far below a pixel, and rounding).
    static constexpr double kJumpRelative = 1e-6;
    /// Samples computed at a time (a multiple of kSampleBlock, so chunks are exact).
    static constexpr std::size_t kChunkSamples = 65'536;

    /// The finest level of a first picture holds at most this many buckets: enough for a
    /// plot 4,096 pixels wide to show the whole turn at its true extremes (see buildPlotCurves).
    static constexpr std::size_t kFirstPictureBuckets = 4'096;

    std::vector<PlotLevel> levels;  ///< finest first
    /// Only the coarser levels were made (a first picture): a second pass adds the finer ones,
    /// for zooming in.
    bool partial = false;
    /// Velocity, acceleration, jerk (each over its three curves), and r.
    std::array<PlotRange, 4> yRanges;
    /// The plotted turn: [0, 360°] or [0, T]; [−360°, 0] over angle at a negative speed.
    PlotRange xRange;
    std::size_t sampleCount = 0;

    /// @brief Points held by all levels and curves together.
    [[nodiscard]] std::size_t pointCount() const;
    /// @brief The level to draw when `visibleFraction` of the turn spans `pixels` columns: the
    /// coarsest whose buckets are at most one pixel wide (so every column shows its samples'
    /// true extremes), or the finest when even those are wider.
    [[nodiscard]] std::size_t levelFor(double visibleFraction, double pixels) const;
};

/// @brief Samples one turn in chunks of PlotCurves::kChunkSamples and builds the plotted
/// curves: memory stays bounded however many samples the turn has. Requires
/// 1 <= n <= kMaxSamplesPerTurn and omega != 0. Returns false if cancelled.
///
/// With `maxBuckets` > 0 only the levels of at most that many buckets are made (`partial` when
/// that leaves out finer ones): every sample is still computed, and those levels are the same
/// as in the whole set, so a plot narrower than `maxBuckets` pixels that shows the whole turn
/// draws exactly what it would with every level. Most of the time of a whole set goes into
/// its finest levels, which only a zoomed-in plot needs.
bool buildPlotCurves(const Contour& contour, double omega, std::size_t n, PlotAxis axis,
                     PlotCurves& out, const std::atomic<bool>& cancel, std::size_t maxBuckets = 0);

}  // namespace cam
