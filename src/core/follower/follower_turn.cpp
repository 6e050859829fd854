#include "follower/follower_turn.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <type_traits>

#include "common/angles.h"
#include "common/simd.h"
#include "common/turn_angles.h"
#include "project/follower_kind.h"

namespace cam {

void FollowerTurn::resize(std::size_t n) {
    for (auto* column : {&s, &v, &a, &j, &pressureAngle, &rhoProfile, &rhoPitch}) {
        column->resize(n);
    }
    segment.resize(n);
}

namespace {

constexpr std::size_t kBlock = TurnAngles::kBlock;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// One run of angles (≤ one block) that share a bin of the model's index: u = (c, s) per angle;
/// for each the outermost contact found so far (its value and its candidate's code, a small
/// integer held in a double so that every array of the loops has one width); then the winner's
/// φ-derivatives of q, d1 … d3 (q itself goes straight into the output). `root`: when the
/// winner is a circle, the square root its crossing took (so that pass 2 need not take it again).
struct Run {
    alignas(64) std::array<double, kBlock> c, s, best, code, root, d1, d2, d3;
};

/// follower_detail::inSpanDirection with the piece's constants hoisted, as a margin: ≥ 0 where
/// w = (x, y) from the circle's centre lies in the span (within the slack). Mode 0: a whole
/// circle; 1: a span up to a half turn (both ends' tests hold); 2: wider (either holds).
struct Wedge {
    double fromX, fromY, toX, toY, sign, tolerance;
    int mode;
    Wedge(const FollowerModel::Piece& piece, double radius)
        : fromX(piece.from.x()),
          fromY(piece.from.y()),
          toX(piece.to.x()),
          toY(piece.to.y()),
          sign(piece.sweep >= 0.0 ? 1.0 : -1.0),
          tolerance(-piece.slack * radius),
          mode(std::abs(piece.sweep) >= kTwoPi ? 0
               : std::abs(piece.sweep) <= kPi  ? 1
                                               : 2) {}
    template <int Mode>
    [[nodiscard]] double margin(double x, double y) const {
        if constexpr (Mode == 0) return 0.0;
        const double afterFrom = sign * (fromX * y - fromY * x) - tolerance;
        const double beforeTo = sign * (x * toY - y * toX) - tolerance;
        if constexpr (Mode == 1) return std::min(afterFrom, beforeTo);
        return std::max(afterFrom, beforeTo);
    }
};

/// Keeps a candidate where it lies farther out (strictly: ties keep the earlier, as
/// FollowerModel::best() does). `margin` ≥ 0 when the candidate exists.
inline void keep(double* __restrict best, double* __restrict code, std::size_t i, double margin,
                 double value, double candidate) {
    const double v = margin >= 0.0 ? value : -kInfinity;
    const bool better = v > best[i];
    best[i] = better ? v : best[i];
    code[i] = better ? candidate : code[i];
}

// ---- Pass 1: every piece of the bin at every angle of the run ----

/// u at samples k0 … k0 + count − 1 (one block: cos/sin of its start cb, sb and of the steps
/// into it ct, st), and no contact yet.
CAMWRIGHT_MULTIVERSION
void startRun(double* __restrict c, double* __restrict s, double* __restrict best,
              double* __restrict code, const double* __restrict ct, const double* __restrict st,
              double cb, double sb, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        c[i] = cb * ct[i] - sb * st[i];
        s[i] = sb * ct[i] + cb * st[i];
        best[i] = -kInfinity;
        code[i] = -1.0;
    }
}

template <int Mode>
void considerCircleCrossings(const double* __restrict cs, const double* __restrict sns,
                             double* __restrict best, double* __restrict code,
                             double* __restrict root, std::size_t count,
                             const FollowerModel::Piece& piece, double e, double candidate) {
    const double cx = piece.center.x(), cy = piece.center.y(), R2 = piece.radius * piece.radius;
    const Wedge wedge(piece, piece.radius);
    for (std::size_t i = 0; i < count; ++i) {
        const double c = cs[i], sn = sns[i];
        const double a = cx * c + cy * sn, b = cy * c - cx * sn;
        const double w = e - b, f = R2 - w * w;
        const double q = std::sqrt(std::max(f, 0.0));
        const double sOut = a + q, sIn = a - q;
        // x = e·n + s·u − centre, n = (−sin φ, cos φ).
        const double out = wedge.margin<Mode>(sOut * c - e * sn - cx, sOut * sn + e * c - cy);
        const double in = wedge.margin<Mode>(sIn * c - e * sn - cx, sIn * sn + e * c - cy);
        keep(best, code, i, std::min(f, out), sOut, candidate);
        keep(best, code, i, std::min(f, in), sIn, candidate + 1.0);
        // This piece holds the contact so far when the code is candidate or candidate + 1.
        root[i] = std::abs(code[i] - (candidate + 0.5)) < 1.0 ? q : root[i];
    }
}

void considerLineCrossings(const double* __restrict cs, const double* __restrict sns,
                           double* __restrict best, double* __restrict code, std::size_t count,
                           const FollowerModel::Piece& piece, double e, double candidate) {
    const double mx = piece.m.x(), my = piece.m.y();
    const double mq = piece.m.dot(piece.q0);
    const double qx = piece.q0.x(), qy = piece.q0.y();
    const Eigen::Vector2d d = piece.q1 - piece.q0;
    const double dx = d.x() / d.squaredNorm(), dy = d.y() / d.squaredNorm();
    const double lo = -piece.slack, hi = 1.0 + piece.slack;
    for (std::size_t i = 0; i < count; ++i) {
        const double c = cs[i], sn = sns[i];
        // m·(e n + s u) = m·q0; the crossing must lie between the ends (λ along q0 → q1).
        const double D = mx * c + my * sn, D1 = my * c - mx * sn;
        const double crosses = std::abs(D) - 1e-15;
        const double s = (mq - e * D1) / (crosses >= 0.0 ? D : 1.0);
        const double lambda = (s * c - e * sn - qx) * dx + (s * sn + e * c - qy) * dy;
        keep(best, code, i, std::min(crosses, std::min(lambda - lo, hi - lambda)), s, candidate);
    }
}

template <int Mode>
void considerSupports(const double* __restrict cs, const double* __restrict sns,
                      double* __restrict best, double* __restrict code, std::size_t count,
                      const FollowerModel::Piece& piece, double candidate) {
    const double cx = piece.center.x(), cy = piece.center.y();
    const double R = piece.kind == FollowerModel::Piece::Kind::Circle ? piece.radius : 0.0;
    const Wedge wedge(piece, 1.0);
    for (std::size_t i = 0; i < count; ++i) {
        const double c = cs[i], sn = sns[i];
        keep(best, code, i, wedge.margin<Mode>(c, sn), cx * c + cy * sn + R, candidate);
    }
}

/// Calls the loop compiled for the piece's kind of span.
template <class Loop>
void byWedge(const Wedge& wedge, const Loop& loop) {
    switch (wedge.mode) {
        case 0:
            return loop(std::integral_constant<int, 0>{});
        case 1:
            return loop(std::integral_constant<int, 1>{});
        default:
            return loop(std::integral_constant<int, 2>{});
    }
}

CAMWRIGHT_MULTIVERSION
void considerPiece(Run& run, std::size_t count, const FollowerModel::Piece& piece, double e,
                   bool flat, double candidate) {
    using Kind = FollowerModel::Piece::Kind;
    const double* c = run.c.data();
    const double* s = run.s.data();
    double* best = run.best.data();
    double* code = run.code.data();
    if (flat) {
        // A vertex supports the face at every angle of its bin; a convex circle where u is in
        // its span.
        if (piece.kind == Kind::Vertex) {
            considerSupports<0>(c, s, best, code, count, piece, candidate);
        } else if (piece.kind == Kind::Circle && piece.convex) {
            byWedge(Wedge(piece, 1.0), [&](auto mode) {
                considerSupports<mode()>(c, s, best, code, count, piece, candidate);
            });
        }
    } else if (piece.kind == Kind::Circle) {
        byWedge(Wedge(piece, piece.radius), [&](auto mode) {
            considerCircleCrossings<mode()>(c, s, best, code, run.root.data(), count, piece, e,
                                            candidate);
        });
    } else if (piece.kind == Kind::Line) {
        considerLineCrossings(c, s, best, code, count, piece, e, candidate);
    }
}

// ---- Pass 2: the winner's closed form over each stretch: q into the output, d1 … d3 ----

void circleCrossing(const double* __restrict cs, const double* __restrict sns,
                    const double* __restrict root, double* __restrict d0, double* __restrict d1,
                    double* __restrict d2, double* __restrict d3, std::size_t i0, std::size_t i1,
                    const FollowerModel::Piece& piece, double e, double sigma) {
    const double cx = piece.center.x(), cy = piece.center.y();
    for (std::size_t i = i0; i < i1; ++i) {
        const double c = cs[i], sn = sns[i];
        // (s − a)² + (e − b)² = Rp², a = c·u, b = c·n; a' = b, b' = −a (as FollowerModel::at);
        // q = √(Rp² − w²) as pass 1 took it.
        const double a = cx * c + cy * sn, b = cy * c - cx * sn;
        const double w = e - b, q = root[i];
        const double f1 = -2.0 * w * a, f2 = -2.0 * (a * a + w * b),
                     f3 = -2.0 * (3.0 * a * b - w * a);
        const double half = 0.5 / q;
        const double q1 = f1 * half, q2 = (f2 - 2.0 * q1 * q1) * half,
                     q3 = (f3 - 6.0 * q1 * q2) * half;
        d0[i] = a + sigma * q;
        d1[i] = b + sigma * q1;
        d2[i] = -a + sigma * q2;
        d3[i] = -b + sigma * q3;
    }
}

void lineCrossing(const double* __restrict cs, const double* __restrict sns, double* __restrict d0,
                  double* __restrict d1, double* __restrict d2, double* __restrict d3,
                  std::size_t i0, std::size_t i1, const FollowerModel::Piece& piece, double e) {
    const double mx = piece.m.x(), my = piece.m.y(), mq = piece.m.dot(piece.q0);
    for (std::size_t i = i0; i < i1; ++i) {
        const double c = cs[i], sn = sns[i];
        // m·(e n + s u) = m·q0: s = N/D.
        const double D = mx * c + my * sn, D1 = my * c - mx * sn, D2 = -D, D3 = -D1;
        const double N = mq - e * D1, N1 = e * D, N2 = e * D1, N3 = -e * D;
        const double inverse = 1.0 / D;
        const double s = N * inverse;
        const double s1 = (N1 - s * D1) * inverse;
        const double s2 = (N2 - 2.0 * s1 * D1 - s * D2) * inverse;
        d0[i] = s;
        d1[i] = s1;
        d2[i] = s2;
        d3[i] = (N3 - 3.0 * s2 * D1 - 3.0 * s1 * D2 - s * D3) * inverse;
    }
}

void support(const double* __restrict cs, const double* __restrict sns, double* __restrict d0,
             double* __restrict d1, double* __restrict d2, double* __restrict d3, std::size_t i0,
             std::size_t i1, const FollowerModel::Piece& piece) {
    const double cx = piece.center.x(), cy = piece.center.y();
    const double R = piece.kind == FollowerModel::Piece::Kind::Circle ? piece.radius : 0.0;
    for (std::size_t i = i0; i < i1; ++i) {
        // The support function h = c·u + R and its derivatives c·n, −c·u, −c·n.
        const double a = cx * cs[i] + cy * sns[i], b = cy * cs[i] - cx * sns[i];
        d0[i] = a + R;
        d1[i] = b;
        d2[i] = -a;
        d3[i] = -b;
    }
}

/// q of sample i goes to d0[i], the run's first sample's output.
CAMWRIGHT_MULTIVERSION
void winnerDerivatives(Run& run, double* d0, std::size_t i0, std::size_t i1,
                       const FollowerModel::Piece& piece, double e, bool flat, double sigma) {
    const double* c = run.c.data();
    const double* s = run.s.data();
    double *d1 = run.d1.data(), *d2 = run.d2.data(), *d3 = run.d3.data();
    if (flat) {
        support(c, s, d0, d1, d2, d3, i0, i1, piece);
    } else if (piece.kind == FollowerModel::Piece::Kind::Circle) {
        circleCrossing(c, s, run.root.data(), d0, d1, d2, d3, i0, i1, piece, e, sigma);
    } else {
        lineCrossing(c, s, d0, d1, d2, d3, i0, i1, piece, e);
    }
}

// ---- Pass 3: what FollowerModel::at() makes of q and its derivatives, over the whole run ----

/// The output columns from a run's first sample on.
struct Columns {
    double* s;
    double* v;
    double* a;
    double* j;
    double* pressureAngle;
    double* rhoProfile;
    double* rhoPitch;
};

void finishFlat(const double* __restrict d0, const double* __restrict d1,
                const double* __restrict d2, const double* __restrict d3, double* __restrict v,
                double* __restrict a, double* __restrict j, double* __restrict pressureAngle,
                double* __restrict rhoProfile, double* __restrict rhoPitch, std::size_t count,
                double omega) {
    for (std::size_t i = 0; i < count; ++i) {
        v[i] = omega * d1[i];
        a[i] = omega * omega * d2[i];
        j[i] = omega * omega * omega * d3[i];
        pressureAngle[i] = 0.0;
        rhoProfile[i] = d0[i] + d2[i];  // h + h''
        rhoPitch[i] = d0[i] + d2[i];
    }
}

void finishOnLine(const double* __restrict d0, const double* __restrict d1,
                  const double* __restrict d2, const double* __restrict d3, double* __restrict v,
                  double* __restrict a, double* __restrict j, double* __restrict pressureAngle,
                  double* __restrict rhoProfile, double* __restrict rhoPitch, std::size_t count,
                  double omega, double e, double rho) {
    for (std::size_t i = 0; i < count; ++i) {
        const double s0 = d0[i], s1 = d1[i], s2 = d2[i];
        v[i] = omega * s1;
        a[i] = omega * omega * s2;
        j[i] = omega * omega * omega * d3[i];
        // The pitch curve C = e·n + s·u: C' = (s' − e)·u + s·n, C'' = (s'' − s)·u + (2s' − e)·n.
        const double y = s1 - e;
        const double crossed = y * (2.0 * s1 - e) - s0 * (s2 - s0);
        const double speed2 = y * y + s0 * s0;
        const double speed3 = speed2 * std::sqrt(speed2);
        const double radius = speed3 / crossed;
        // A straight stretch has no finite radius: +∞, not the rounding noise of a cross product
        // (curvature · max(|s|, 1) ≤ 1e-12, as FollowerModel::at() decides it).
        const bool straight = std::abs(crossed) * std::max(std::abs(s0), 1.0) <= 1e-12 * speed3;
        rhoPitch[i] = straight ? kInfinity : radius;
        rhoProfile[i] = straight ? kInfinity : radius - rho;
    }
    // A loop of its own: with the call in it the loop above would not be if-converted.
    for (std::size_t i = 0; i < count; ++i) pressureAngle[i] = std::atan2(d1[i] - e, d0[i]);
}

CAMWRIGHT_MULTIVERSION
void finish(const Run& run, const Columns& o, std::size_t count, double omega, double e, double rho,
            bool flat) {
    if (flat) {
        finishFlat(o.s, run.d1.data(), run.d2.data(), run.d3.data(), o.v, o.a, o.j, o.pressureAngle,
                   o.rhoProfile, o.rhoPitch, count, omega);
    } else {
        finishOnLine(o.s, run.d1.data(), run.d2.data(), run.d3.data(), o.v, o.a, o.j,
                     o.pressureAngle, o.rhoProfile, o.rhoPitch, count, omega, e, rho);
    }
}

}  // namespace

/// Walks the turn bin by bin of the model's index (follower.h), a block of angles at most at a
/// time.
class FollowerTurnSampler {
public:
    FollowerTurnSampler(const FollowerModel& model, double omega, std::size_t n, FollowerTurn& out)
        : m_model(model),
          m_omega(omega),
          m_dt(kTwoPi / std::abs(omega) / static_cast<double>(n)),
          m_n(n),
          m_out(out),
          m_angles(omega, m_dt, 0, n) {
        const FollowerSpec& spec = model.spec();
        m_e = spec.offset;
        m_rho = contactRadius(spec);
        m_flat = spec.type == FollowerType::Flat;
    }

    bool run(const std::atomic<bool>* cancel) {
        const std::size_t bins = m_model.m_binOffsets.size() - 1;
        if (m_model.m_binOffsets.size() < 2) {
            for (std::size_t k = 0; k < m_n; ++k) sampleOne(k);
            return true;
        }
        const double dphi = std::abs(m_omega * m_dt);
        constexpr std::size_t kSamplesBetweenPolls = 16 * kBlock;
        std::size_t nextPoll = 0;
        for (std::size_t k = 0; k < m_n;) {
            if (k >= nextPoll) {
                if (cancel && cancel->load(std::memory_order_relaxed)) return false;
                nextPoll = k + kSamplesBetweenPolls;
            }
            const double into = intoTurn(phiOf(k));
            const std::size_t bin = binOf(into, bins);
            // Where the bin ends, estimated, then settled by the same lookup as piecesAt().
            const double edge = m_omega > 0.0 ? static_cast<double>(bin + 1) * m_model.m_binWidth
                                              : static_cast<double>(bin) * m_model.m_binWidth;
            const double steps = std::floor(std::abs(edge - into) / dphi);
            const std::size_t blockEnd = std::min(m_n, TurnAngles::blockEnd(k));
            std::size_t end = std::min(
                blockEnd, k + 1 + static_cast<std::size_t>(std::clamp(steps, 0.0, double(kBlock))));
            while (end > k + 1 && binOf(intoTurn(phiOf(end - 1)), bins) != bin) --end;
            while (end < blockEnd && binOf(intoTurn(phiOf(end)), bins) == bin) ++end;
            sampleRun(k, end, bin);
            k = end;
        }
        return true;
    }

private:
    [[nodiscard]] double phiOf(std::size_t k) const {
        return m_omega * (static_cast<double>(k) * m_dt);
    }
    /// φ − φ_begin reduced into [0, 2π), as FollowerModel::piecesAt() reduces it.
    [[nodiscard]] double intoTurn(double phi) const {
        double into = std::fmod(phi - m_model.m_phiBegin, kTwoPi);
        if (into < 0.0) into += kTwoPi;
        return into;
    }
    [[nodiscard]] std::size_t binOf(double into, std::size_t bins) const {
        return std::min(bins - 1, static_cast<std::size_t>(into / m_model.m_binWidth));
    }

    [[nodiscard]] Columns columnsFrom(std::size_t k) const {
        return {m_out.s.data() + k,
                m_out.v.data() + k,
                m_out.a.data() + k,
                m_out.j.data() + k,
                m_out.pressureAngle.data() + k,
                m_out.rhoProfile.data() + k,
                m_out.rhoPitch.data() + k};
    }

    /// FollowerModel::at() for one sample (splines, arms, and an angle without a contact).
    void sampleOne(std::size_t k) {
        const FollowerState f = m_model.at(phiOf(k), m_omega);
        m_out.s[k] = f.s;
        m_out.v[k] = f.v;
        m_out.a[k] = f.a;
        m_out.j[k] = f.j;
        m_out.pressureAngle[k] = f.pressureAngle;
        m_out.rhoProfile[k] = f.rhoProfile;
        m_out.rhoPitch[k] = f.rhoPitch;
        m_out.segment[k] = static_cast<std::int32_t>(f.segment);
    }

    void sampleRun(std::size_t k0, std::size_t k1, std::size_t bin) {
        using Kind = FollowerModel::Piece::Kind;
        const std::span<const std::uint32_t> pieces(
            m_model.m_binPieces.data() + m_model.m_binOffsets[bin],
            m_model.m_binOffsets[bin + 1] - m_model.m_binOffsets[bin]);
        const bool scalar =
            m_model.oscillating() || std::any_of(pieces.begin(), pieces.end(), [&](auto index) {
                return m_model.m_pieces[index].kind == Kind::Spline;
            });
        if (scalar) {
            for (std::size_t k = k0; k < k1; ++k) sampleOne(k);
            return;
        }
        const std::size_t count = k1 - k0;
        const std::size_t j0 = k0 & (kBlock - 1);
        startRun(m_run.c.data(), m_run.s.data(), m_run.best.data(), m_run.code.data(),
                 m_angles.ct.data() + j0, m_angles.st.data() + j0, m_angles.blockCos(k0),
                 m_angles.blockSin(k0), count);
        for (const std::uint32_t index : pieces) {
            considerPiece(m_run, count, m_model.m_pieces[index], m_e, m_flat,
                          2.0 * static_cast<double>(index));
        }
        // Stretches of one winner, each by its closed form. An angle without a contact (none of
        // the bin's pieces holds it) goes through at() after, as it would alone.
        bool someWithout = false;
        for (std::size_t i = 0; i < count;) {
            const double code = m_run.code[i];
            std::size_t i1 = i + 1;
            while (i1 < count && m_run.code[i1] == code) ++i1;
            if (code < 0.0) {
                someWithout = true;
                std::fill(m_out.s.begin() + static_cast<std::ptrdiff_t>(k0 + i),
                          m_out.s.begin() + static_cast<std::ptrdiff_t>(k0 + i1), 1.0);
                std::fill(m_run.d1.begin() + i, m_run.d1.begin() + i1, 0.0);
                std::fill(m_run.d2.begin() + i, m_run.d2.begin() + i1, 0.0);
                std::fill(m_run.d3.begin() + i, m_run.d3.begin() + i1, 0.0);
            } else {
                const auto index = static_cast<std::size_t>(code / 2.0);
                const FollowerModel::Piece& piece = m_model.m_pieces[index];
                const double sigma = code > 2.0 * static_cast<double>(index) ? -1.0 : 1.0;
                winnerDerivatives(m_run, m_out.s.data() + k0, i, i1, piece, m_e, m_flat, sigma);
                std::fill(m_out.segment.begin() + static_cast<std::ptrdiff_t>(k0 + i),
                          m_out.segment.begin() + static_cast<std::ptrdiff_t>(k0 + i1),
                          static_cast<std::int32_t>(piece.segment));
            }
            i = i1;
        }
        finish(m_run, columnsFrom(k0), count, m_omega, m_e, m_rho, m_flat);
        for (std::size_t i = 0; i < count && someWithout; ++i) {
            if (m_run.code[i] < 0.0) sampleOne(k0 + i);
        }
    }

    const FollowerModel& m_model;
    double m_omega, m_dt;
    std::size_t m_n;
    FollowerTurn& m_out;
    TurnAngles m_angles;
    double m_e = 0.0, m_rho = 0.0;
    bool m_flat = false;
    Run m_run;
};

bool sampleFollowerTurn(const FollowerModel& model, double omega, std::size_t n, FollowerTurn& out,
                        const std::atomic<bool>* cancel) {
    out.resize(n);
    if (n == 0) return true;
    auto sampler = std::make_unique<FollowerTurnSampler>(model, omega, n, out);  // Run: 64 kB
    return sampler->run(cancel);
}

}  // namespace cam
