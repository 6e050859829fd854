#include "engine/plot_levels.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>

#include "common/angles.h"
#include "common/tolerances.h"

namespace cam {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
using Tag = std::int32_t;  ///< a sample's index in the turn (kMaxSamplesPerTurn fits)
static_assert(kMaxSamplesPerTurn < std::numeric_limits<Tag>::max());
/// Tags of points that are no sample: never merged into a bucket when coarsening.
constexpr Tag kExact = -1;
constexpr Tag kBreakCandidate = -2;  ///< NaN between two one-sided values: kept if they differ

using Values = std::array<double, kCurveCount>;

Values valuesOf(const PolarDerivatives& d, double omega) {
    const PolarMotion m = polarMotion(d, omega);
    return {m.vR, m.vPhi, m.v, m.aR, m.aPhi, m.a, m.jR, m.jPhi, m.j, d.r};
}

const double* samplesOf(const SampledTurn& t, std::size_t c) {
    const std::vector<double>* sources[] = {&t.vR, &t.vPhi, &t.v,    &t.aR, &t.aPhi,
                                            &t.a,  &t.jR,   &t.jPhi, &t.j,  &t.r};
    static_assert(std::size(sources) == kCurveCount);
    return sources[c]->data();
}

/// A joint the turn passes: both segments' one-sided values at its exact place.
struct Crossing {
    double x = 0.0;
    Values left{}, right{};
};

class Turn {
public:
    Turn(const Contour& contour, double omega, PlotAxis axis)
        : m_contour(contour), m_omega(omega), m_axis(axis) {}

    [[nodiscard]] double xOf(double phi) const {
        return m_axis == PlotAxis::Angle ? radToDeg(phi) : phi / m_omega;
    }
    [[nodiscard]] Values valuesAt(std::size_t segment, double phi) const {
        return valuesOf(m_contour.segment(segment).evaluate(phi), m_omega);
    }

    /// Walks from segment `from` in the direction of turning, starting at turn angle `phi`,
    /// across every joint up to segment `to` (or, with `stop`, up to the turn angle `stop`),
    /// appending each crossing. Windows narrower than a sample step are crossed too. Returns
    /// the segment reached.
    std::size_t cross(std::size_t from, std::size_t to, double phi, std::optional<double> stop,
                      std::vector<Crossing>& out) const {
        const std::size_t m = m_contour.size();
        const bool forward = m_omega > 0.0;
        const double eps = degToRad(kWindowToleranceDeg);
        std::size_t u = from;
        for (std::size_t steps = 0; u != to && steps < m; ++steps) {
            const std::size_t next = forward ? (u + 1) % m : (u + m - 1) % m;
            // The boundary between u and next, in the windows' frame, then in the turn's.
            const double j = m_contour.segment(forward ? next : u).phiStart;
            const double phiJ = j + kTwoPi * std::round((phi - j) / kTwoPi);
            if (stop && (forward ? phiJ >= *stop - eps : phiJ <= *stop + eps)) break;
            out.push_back({xOf(phiJ), valuesAt(u, phiJ), valuesAt(next, phiJ)});
            u = next;
            phi = phiJ;
        }
        return u;
    }

private:
    const Contour& m_contour;
    double m_omega;
    PlotAxis m_axis;
};

/// One curve of one level while it is built: points in the order of the turn, each tagged with
/// its sample index (or kExact / kBreakCandidate).
struct CurveBuilder {
    std::vector<PlotPoint> points;
    std::vector<Tag> tags;
    double lo = kInf, hi = -kInf;

    // The bucket being filled.
    Tag bucket = -1;
    PlotPoint minP, maxP;
    Tag minK = 0, maxK = 0;

    void push(PlotPoint p, Tag tag) {
        points.push_back(p);
        tags.push_back(tag);
    }
    void flush() {
        if (bucket < 0) return;
        // In the order of the turn: the earlier of the two first.
        if (minK == maxK) {
            push(minP, minK);
        } else if (minK < maxK) {
            push(minP, minK);
            push(maxP, maxK);
        } else {
            push(maxP, maxK);
            push(minP, minK);
        }
        bucket = -1;
    }
    void add(Tag k, Tag b, double x, double y) {
        if (!std::isfinite(y)) {  // nothing to draw: a break, never part of an extreme
            flush();
            push({x, kNaN}, kExact);
            return;
        }
        lo = std::min(lo, y);
        hi = std::max(hi, y);
        if (b != bucket) {
            flush();
            bucket = b;
            minP = maxP = {x, y};
            minK = maxK = k;
        } else if (y < minP.y) {
            minP = {x, y};
            minK = k;
        } else if (y > maxP.y) {
            maxP = {x, y};
            maxK = k;
        }
    }
    /// Samples k0 … k0 + count − 1 of one segment, into buckets of 2^shift samples.
    void addRun(const double* xs, const double* ys, std::size_t count, Tag k0, int shift) {
        double l = lo, h = hi;
        if (shift == 0) {
            // Every sample is a point (NaN included: the line breaks there and coarsening
            // treats it as a break).
            for (std::size_t i = 0; i < count; ++i) {  // into reserved room: written once
                points.push_back({xs[i], ys[i]});
                tags.push_back(k0 + static_cast<Tag>(i));
                l = ys[i] < l ? ys[i] : l;  // NaN compares false: ignored
                h = ys[i] > h ? ys[i] : h;
            }
            lo = l;
            hi = h;
            return;
        }
        // Bucket by bucket: each bucket's part in this run is scanned in a tight loop (its
        // smallest and largest value and where they are), then merged into the open bucket.
        // The loop runs over millions of samples; a part holding an infinity or NaN (rare)
        // goes sample by sample through add().
        std::size_t i = 0;
        while (i < count) {
            const Tag k = k0 + static_cast<Tag>(i);
            const Tag bk = k >> shift;
            const std::size_t bucketEnd = (static_cast<std::size_t>(bk) + 1) << shift;
            const std::size_t end = std::min(count, i + (bucketEnd - static_cast<std::size_t>(k)));
            double mnY = ys[i], mxY = ys[i];
            std::size_t mnI = i, mxI = i;
            bool finite = std::isfinite(ys[i]);
            for (std::size_t j = i + 1; j < end; ++j) {
                const double y = ys[j];
                finite = finite && std::isfinite(y);
                if (y < mnY) mnY = y, mnI = j;
                if (y > mxY) mxY = y, mxI = j;
            }
            if (!finite) {
                lo = l, hi = h;
                for (std::size_t j = i; j < end; ++j) {
                    add(k0 + static_cast<Tag>(j), (k0 + static_cast<Tag>(j)) >> shift, xs[j],
                        ys[j]);
                }
                l = lo, h = hi;
                i = end;
                continue;
            }
            l = std::min(l, mnY);
            h = std::max(h, mxY);
            const PlotPoint mn{xs[mnI], mnY}, mx{xs[mxI], mxY};
            const Tag mnK = k0 + static_cast<Tag>(mnI), mxK = k0 + static_cast<Tag>(mxI);
            if (bk != bucket) {
                flush();
                bucket = bk;
                minP = mn, minK = mnK;
                maxP = mx, maxK = mxK;
            } else {  // the open bucket goes on: the earlier sample wins a tie, as in add()
                if (mnY < minP.y) minP = mn, minK = mnK;
                if (mxY > maxP.y) maxP = mx, maxK = mxK;
            }
            i = end;
        }
        lo = l, hi = h;
    }
    void exact(double x, double y) {
        flush();
        if (std::isfinite(y)) {
            lo = std::min(lo, y);
            hi = std::max(hi, y);
        }
        push({x, y}, kExact);
    }
    void joint(const Crossing& c, std::size_t curve) {
        exact(c.x, c.left[curve]);
        push({c.x, kNaN}, kBreakCandidate);
        exact(c.x, c.right[curve]);
    }
};

/// The next coarser level: merges the points of buckets `shift` apart that no exact point
/// separates, keeping each merged bucket's smallest and largest value.
CurveBuilder coarsen(const CurveBuilder& fine, int shift) {
    CurveBuilder out;
    out.points.reserve(fine.points.size() / 2 + 16);
    out.tags.reserve(fine.points.size() / 2 + 16);
    for (std::size_t i = 0; i < fine.points.size(); ++i) {
        const Tag tag = fine.tags[i];
        if (tag < 0) {
            out.flush();
            out.push(fine.points[i], tag);
        } else {
            out.add(tag, tag >> shift, fine.points[i].x, fine.points[i].y);
        }
    }
    out.flush();
    return out;
}

/// Keeps a NaN between two one-sided values only where they differ visibly.
void settleBreaks(CurveBuilder& b, double tolerance) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < b.points.size(); ++i) {
        if (b.tags[i] == kBreakCandidate) {
            const double left = b.points[i - 1].y, right = b.points[i + 1].y;
            const bool continuous = std::abs(right - left) <= tolerance;  // false for NaN
            if (continuous) continue;
            b.tags[i] = kExact;
        }
        b.points[w] = b.points[i];
        b.tags[w] = b.tags[i];
        ++w;
    }
    b.points.resize(w);
    b.tags.resize(w);
}

std::size_t ceilDiv(std::size_t a, std::size_t b) { return (a + b - 1) / b; }

}  // namespace

std::size_t PlotCurves::pointCount() const {
    std::size_t count = 0;
    for (const PlotLevel& level : levels) {
        for (const auto& curve : level.curves) count += curve.size();
    }
    return count;
}

std::size_t PlotCurves::levelFor(double visibleFraction, double pixels) const {
    if (levels.empty() || !(pixels > 0.0)) return 0;
    const double samplesPerPixel =
        std::clamp(visibleFraction, 0.0, 1.0) * static_cast<double>(sampleCount) / pixels;
    std::size_t chosen = 0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        if (static_cast<double>(levels[i].samplesPerBucket) <= samplesPerPixel) chosen = i;
    }
    return chosen;
}

bool buildPlotCurves(const Contour& contour, double omega, std::size_t n, PlotAxis axis,
                     PlotCurves& out, const std::atomic<bool>& cancel, std::size_t maxBuckets) {
    out = PlotCurves{};
    out.sampleCount = n;
    const Turn turn(contour, omega, axis);
    const double dt = kTwoPi / std::abs(omega) / static_cast<double>(n);
    const double phiEnd = omega * (static_cast<double>(n) * dt);
    const double xEnd = turn.xOf(phiEnd);
    out.xRange = {std::min(0.0, xEnd), std::max(0.0, xEnd)};

    // The finest level: every sample when they fit, else the finest envelope that fits.
    int shift = 0;
    if (n > PlotCurves::kMaxLevelPoints) {
        shift = 2;
        while (2 * ceilDiv(n, std::size_t{1} << shift) > PlotCurves::kMaxLevelPoints) ++shift;
    }
    // A first picture starts at a coarser level of the same sequence (below: 3 after 0, then
    // steps of 2), one that still has enough buckets to be coarsened.
    if (maxBuckets > 0) {
        while (ceilDiv(n, std::size_t{1} << shift) > maxBuckets) {
            const int next = shift == 0 ? 3 : shift + 2;
            if (ceilDiv(n, std::size_t{1} << next) < PlotCurves::kMinLevelBuckets) break;
            shift = next;
            out.partial = true;
        }
    }
    std::array<CurveBuilder, kCurveCount> builders;
    for (CurveBuilder& b : builders) {
        const std::size_t expected = shift == 0 ? n : 2 * ceilDiv(n, std::size_t{1} << shift);
        b.points.reserve(expected + 3 * contour.size() + 8);  // and the joints
        b.tags.reserve(expected + 3 * contour.size() + 8);
    }

    // One chunk of samples at a time, in a buffer the worker thread keeps: no big turn is ever
    // held, and no fresh memory is touched for it on every edit.
    thread_local SampledTurn samples;
    const std::size_t chunk = PlotCurves::kChunkSamples;
    std::vector<double> xs;
    std::vector<Crossing> crossings;
    struct Boundary {
        std::size_t index, begin, end;  // sample in the chunk; its crossings
    };
    std::vector<Boundary> boundaries;
    std::size_t lastSegment = 0;
    double lastPhi = 0.0;
    for (std::size_t first = 0; first < n; first += chunk) {
        const std::size_t count = std::min(chunk, n - first);
        if (!sampleTurnRange(contour, omega, n, first, count, samples, &cancel)) return false;
        xs.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            xs[i] = axis == PlotAxis::Angle ? radToDeg(samples.phi[i]) : samples.t[i];
        }
        crossings.clear();
        boundaries.clear();
        for (std::size_t i = 0; i < count; ++i) {
            const auto segment = static_cast<std::size_t>(samples.segment[i]);
            if ((first > 0 || i > 0) && segment != lastSegment) {
                const std::size_t begin = crossings.size();
                turn.cross(lastSegment, segment, lastPhi, std::nullopt, crossings);
                boundaries.push_back({i, begin, crossings.size()});
            }
            lastSegment = segment;
            lastPhi = samples.phi[i];
        }
        for (std::size_t c = 0; c < kCurveCount; ++c) {
            const double* y = samplesOf(samples, c);
            CurveBuilder& b = builders[c];
            // Runs of one segment, with the joints between them.
            std::size_t runStart = 0;
            for (std::size_t r = 0; r <= boundaries.size(); ++r) {
                const std::size_t runEnd = r < boundaries.size() ? boundaries[r].index : count;
                b.addRun(xs.data() + runStart, y + runStart, runEnd - runStart,
                         static_cast<Tag>(first + runStart), shift);
                if (r == boundaries.size()) break;
                for (std::size_t j = boundaries[r].begin; j < boundaries[r].end; ++j) {
                    b.joint(crossings[j], c);
                }
                runStart = runEnd;
            }
        }
        if (cancel.load(std::memory_order_relaxed)) return false;
    }
    // The joints between the last sample and the end of the turn, then the value at the end.
    crossings.clear();
    const std::size_t endSegment =
        turn.cross(lastSegment, contour.size(), lastPhi, phiEnd, crossings);
    const Values closing = turn.valuesAt(endSegment, phiEnd);
    for (std::size_t c = 0; c < kCurveCount; ++c) {
        for (const Crossing& crossing : crossings) builders[c].joint(crossing, c);
        builders[c].exact(xEnd, closing[c]);
    }

    // Per plot, its curves: three each for velocity, acceleration and jerk, then r alone.
    constexpr std::array<std::pair<std::size_t, std::size_t>, 4> plotCurves{
        {{0, 3}, {3, 6}, {6, 9}, {9, 10}}};
    for (std::size_t p = 0; p < plotCurves.size(); ++p) {
        const auto [begin, end] = plotCurves[p];
        double lo = kInf, hi = -kInf;
        for (std::size_t c = begin; c < end; ++c) {
            lo = std::min(lo, builders[c].lo);
            hi = std::max(hi, builders[c].hi);
        }
        if (!(lo <= hi)) lo = hi = 0.0;  // nothing finite to show
        out.yRanges[p] = {lo, hi};
        const double tolerance = PlotCurves::kJumpRelative * std::max(hi - lo, 1e-300);
        for (std::size_t c = begin; c < end; ++c) settleBreaks(builders[c], tolerance);
    }

    // Coarser levels, each with buckets four times as wide as the one before (a quarter of its
    // points), until a level would have too few buckets.
    const bool descending = xEnd < 0.0;  // ω < 0 over angle: x runs 0 → −360°
    std::size_t samplesPerBucket = std::size_t{1} << shift;
    for (int s = shift == 0 ? 3 : shift + 2;; s += 2) {
        if (cancel.load(std::memory_order_relaxed)) return false;
        const bool coarser = ceilDiv(n, std::size_t{1} << s) >= PlotCurves::kMinLevelBuckets;
        PlotLevel& level = out.levels.emplace_back();
        level.samplesPerBucket = samplesPerBucket;
        for (std::size_t c = 0; c < kCurveCount; ++c) {
            CurveBuilder next = coarser ? coarsen(builders[c], s) : CurveBuilder{};
            level.curves[c] = std::move(builders[c].points);
            if (descending) std::reverse(level.curves[c].begin(), level.curves[c].end());
            builders[c] = std::move(next);
        }
        if (!coarser) break;
        samplesPerBucket = std::size_t{1} << s;
    }
    return true;
}

}  // namespace cam
