// The plotted envelopes against the samples themselves: every bucket of the finest envelope
// level holds exactly its samples' smallest and largest value, at those samples' x, found here
// by brute force over sampleTurn() (not through the envelope code).

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <set>
#include <utility>

#include "app_test_support.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "engine/plot_levels.h"
#include "kinematics/kinematics.h"

namespace cam {
namespace {

/// Checks that every bucket of `level` inside one segment holds its samples' smallest and
/// largest value at their x, found by brute force over sampleTurn().
void expectBucketsHoldTheirExtremes(const Contour& contour, double omega, std::size_t n,
                                    const PlotLevel& level) {
    const std::size_t size = level.samplesPerBucket;
    SampledTurn samples;
    ASSERT_TRUE(sampleTurn(contour, omega, n, samples));
    const std::vector<double>* values[] = {&samples.vR,   &samples.vPhi, &samples.v,  &samples.aR,
                                           &samples.aPhi, &samples.a,    &samples.jR, &samples.jPhi,
                                           &samples.j,    &samples.r};
    static_assert(std::size(values) == kCurveCount);
    for (std::size_t c = 0; c < kCurveCount; ++c) {
        std::set<std::pair<double, double>> points;
        for (const PlotPoint& p : level.curves[c]) points.insert({p.x, p.y});
        const std::vector<double>& y = *values[c];
        std::size_t checked = 0;
        for (std::size_t b = 0; b + size <= n; b += size) {
            // Buckets inside one segment (a joint splits the others, with exact points).
            if (samples.segment[b] != samples.segment[b + size - 1]) continue;
            const auto first = y.begin() + static_cast<std::ptrdiff_t>(b);
            const auto last = first + static_cast<std::ptrdiff_t>(size);
            const auto [lo, hi] = std::minmax_element(first, last);
            // minmax_element gives the last of equal maxima; the envelope keeps the first.
            const auto hiFirst = std::find(first, last, *hi);
            for (auto it : {lo, hiFirst}) {
                const std::size_t k = static_cast<std::size_t>(it - y.begin());
                ASSERT_TRUE(points.count({radToDeg(samples.phi[k]), *it}))
                    << "curve " << c << ", bucket " << b / size << ", sample " << k;
            }
            ++checked;
        }
        EXPECT_GT(checked, n / size - 2 * contour.size() - 2);
        // No more than two points a bucket, and at a joint its three and two more for the
        // bucket it splits.
        EXPECT_LE(level.curves[c].size(), 2 * (n / size + 1) + 5 * contour.size() + 8);
    }
}

TEST(PlotLevels, EveryBucketHoldsItsSamplesSmallestAndLargestValue) {
    const Project project = test::loadExample();
    const Contour contour = Contour::build(project).value();
    const double omega = project.motion.omegaRadS();
    const std::size_t n = 100'000;  // above kMaxLevelPoints: buckets of 4 samples
    std::atomic<bool> cancel{false};
    PlotCurves curves;
    ASSERT_TRUE(buildPlotCurves(contour, omega, n, PlotAxis::Angle, curves, cancel));
    ASSERT_EQ(curves.levels.front().samplesPerBucket, 4u);
    EXPECT_FALSE(curves.partial);
    expectBucketsHoldTheirExtremes(contour, omega, n, curves.levels.front());
}

/// Two points of a level are the same when both coordinates are, NaN breaks included.
bool samePoint(const PlotPoint& a, const PlotPoint& b) {
    const auto same = [](double u, double v) { return u == v || (std::isnan(u) && std::isnan(v)); };
    return same(a.x, b.x) && same(a.y, b.y);
}

TEST(PlotLevels, AFirstPictureHoldsTheWholeSetsCoarserLevelsPointForPoint) {
    const Project project = test::loadExample();
    const Contour contour = Contour::build(project).value();
    std::atomic<bool> cancel{false};
    // Both senses of rotation, both axes; sample counts with and without a first picture.
    for (const double omega : {project.motion.omegaRadS(), -project.motion.omegaRadS()}) {
        for (const PlotAxis axis : {PlotAxis::Angle, PlotAxis::Time}) {
            for (const std::size_t n :
                 {std::size_t{3'600}, std::size_t{100'000}, std::size_t{1'000'003}}) {
                SCOPED_TRACE(testing::Message() << "omega " << omega << ", n " << n << ", axis "
                                                << static_cast<int>(axis));
                PlotCurves whole, first;
                ASSERT_TRUE(buildPlotCurves(contour, omega, n, axis, whole, cancel));
                ASSERT_TRUE(buildPlotCurves(contour, omega, n, axis, first, cancel,
                                            PlotCurves::kFirstPictureBuckets));
                const std::size_t finest = first.levels.front().samplesPerBucket;
                // The finest level it holds has at most that many buckets, and the next finer
                // one of the whole set more.
                EXPECT_LE((n + finest - 1) / finest, PlotCurves::kFirstPictureBuckets);
                EXPECT_EQ(first.partial, whole.levels.front().samplesPerBucket != finest);
                std::size_t skipped = 0;
                while (whole.levels[skipped].samplesPerBucket != finest) ++skipped;
                if (skipped > 0) {
                    const std::size_t finer = whole.levels[skipped - 1].samplesPerBucket;
                    EXPECT_GT((n + finer - 1) / finer, PlotCurves::kFirstPictureBuckets);
                }
                ASSERT_EQ(first.levels.size() + skipped, whole.levels.size());
                for (std::size_t i = 0; i < first.levels.size(); ++i) {
                    const PlotLevel& a = first.levels[i];
                    const PlotLevel& b = whole.levels[i + skipped];
                    ASSERT_EQ(a.samplesPerBucket, b.samplesPerBucket);
                    for (std::size_t c = 0; c < kCurveCount; ++c) {
                        ASSERT_EQ(a.curves[c].size(), b.curves[c].size()) << "level " << i;
                        for (std::size_t k = 0; k < a.curves[c].size(); ++k) {
                            ASSERT_TRUE(samePoint(a.curves[c][k], b.curves[c][k]))
                                << "level " << i << ", curve " << c << ", point " << k;
                        }
                    }
                }
                for (std::size_t p = 0; p < first.yRanges.size(); ++p) {
                    EXPECT_EQ(first.yRanges[p].lower, whole.yRanges[p].lower);
                    EXPECT_EQ(first.yRanges[p].upper, whole.yRanges[p].upper);
                }
            }
        }
    }
    // And its finest level against the samples themselves.
    const double omega = project.motion.omegaRadS();
    PlotCurves first;
    ASSERT_TRUE(buildPlotCurves(contour, omega, 100'000, PlotAxis::Angle, first, cancel,
                                PlotCurves::kFirstPictureBuckets));
    EXPECT_TRUE(first.partial);
    EXPECT_EQ(first.levels.front().samplesPerBucket, 64u);
    expectBucketsHoldTheirExtremes(contour, omega, 100'000, first.levels.front());
}

}  // namespace
}  // namespace cam
