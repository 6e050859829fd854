// The plotted envelopes against the samples themselves: every bucket of the finest envelope
// level holds exactly its samples' smallest and largest value, at those samples' x, found here
// by brute force over sampleTurn() (not through the envelope code).

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <set>
#include <utility>

#include "app_test_support.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "engine/plot_levels.h"
#include "kinematics/kinematics.h"

namespace cam {
namespace {

TEST(PlotLevels, EveryBucketHoldsItsSamplesSmallestAndLargestValue) {
    const Project project = test::loadExample();
    const Contour contour = Contour::build(project).value();
    const double omega = project.motion.omegaRadS();
    const std::size_t n = 100'000;  // above kMaxLevelPoints: buckets of 4 samples
    std::atomic<bool> cancel{false};
    PlotCurves curves;
    ASSERT_TRUE(buildPlotCurves(contour, omega, n, PlotAxis::Angle, curves, cancel));
    ASSERT_EQ(curves.levels.front().samplesPerBucket, 4u);
    SampledTurn samples;
    ASSERT_TRUE(sampleTurn(contour, omega, n, samples));
    const std::vector<double>* values[] = {&samples.vR, &samples.vPhi, &samples.v,
                                           &samples.aR, &samples.aPhi, &samples.a,
                                           &samples.jR, &samples.jPhi, &samples.j};
    for (std::size_t c = 0; c < kCurveCount; ++c) {
        std::set<std::pair<double, double>> points;
        for (const PlotPoint& p : curves.levels.front().curves[c]) points.insert({p.x, p.y});
        const std::vector<double>& y = *values[c];
        std::size_t checked = 0;
        for (std::size_t b = 0; b + 4 <= n; b += 4) {
            // Buckets inside one segment (a joint splits the others, with exact points).
            if (samples.segment[b] != samples.segment[b + 3]) continue;
            const auto first = y.begin() + static_cast<std::ptrdiff_t>(b);
            const auto [lo, hi] = std::minmax_element(first, first + 4);
            // minmax_element gives the last of equal maxima; the envelope keeps the first.
            const auto hiFirst = std::find(first, first + 4, *hi);
            for (auto it : {lo, hiFirst}) {
                const std::size_t k = static_cast<std::size_t>(it - y.begin());
                ASSERT_TRUE(points.count({radToDeg(samples.phi[k]), *it}))
                    << "curve " << c << ", bucket " << b / 4 << ", sample " << k;
            }
            ++checked;
        }
        EXPECT_GT(checked, n / 4 - 100);
        // No more than two points a bucket, and at a joint its three and two more for the
        // bucket it splits.
        EXPECT_LE(curves.levels.front().curves[c].size(), n / 2 + 5 * contour.size() + 8);
    }
}

}  // namespace
}  // namespace cam
