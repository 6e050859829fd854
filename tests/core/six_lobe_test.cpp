// The seed's six-lobe arc cam (math.md §3): exact state against the 50-digit reference table,
// and why the seed's own Table 2 differs from it.

#include <gtest/gtest.h>

#include "common/angles.h"
#include "contour/contour.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"
#include "test_support.h"

namespace cam {
namespace {

using test::relClose;

struct Fixture {
    Contour contour;
    double omega;
};

Fixture load() {
    auto p = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    EXPECT_TRUE(p.ok());
    return {Contour::build(p.value()).value(), p.value().motion.omegaRadS()};
}

struct Row {
    double t, phiDeg, r, vR, vPhi, aR, aPhi;
};

// math.md §3, computed independently in 50-digit arithmetic (mm, mm/s, mm/s²).
constexpr Row kReference[] = {
    {0.05, 45, 26.218824198, -369.148280152, 411.844327435, -40298.5214382, -11597.1352501},
    {0.15, 135, 26.218824198, 369.148280152, 411.844327435, -40298.5214382, 11597.1352501},
    {0.37, 333, 28.897219241, -61.829076850, 453.916458381, -25873.4168380, -1942.4177361},
    {0.00, 0, 20.896819450, 0.0, 328.246472338, 22258.2712666, 0.0},
};

TEST(SixLobeCam, OmegaIsFivePi) { EXPECT_DOUBLE_EQ(load().omega, 5.0 * kPi); }

TEST(SixLobeCam, ReproducesTheReferenceTableToOneBillionth) {
    const Fixture f = load();
    for (const Row& row : kReference) {
        const KinematicState s = stateAt(f.contour, f.omega, row.t);
        // The table prints 11–12 significant digits: 1e-9 relative is what it can decide.
        // Exact zeros get an absolute floor of 1e-9 of the magnitude.
        EXPECT_NEAR(radToDeg(s.phi), row.phiDeg, 1e-12) << "t=" << row.t;
        EXPECT_TRUE(relClose(s.polar.r, row.r, 1e-9)) << "t=" << row.t;
        EXPECT_TRUE(relClose(s.motion.vR, row.vR, 1e-9, s.motion.v)) << "t=" << row.t;
        EXPECT_TRUE(relClose(s.motion.vPhi, row.vPhi, 1e-9)) << "t=" << row.t;
        EXPECT_TRUE(relClose(s.motion.aR, row.aR, 1e-9)) << "t=" << row.t;
        EXPECT_TRUE(relClose(s.motion.aPhi, row.aPhi, 1e-9, s.motion.a)) << "t=" << row.t;
    }
}

TEST(SixLobeCam, RadiusRangesFromD1ToTwentyNine) {
    // Closed form: notch bottoms at k·60° lie at d1, lobe tips at 30° + k·60° at 29 mm.
    const Fixture f = load();
    for (int k = 0; k < 6; ++k) {
        EXPECT_TRUE(relClose(f.contour.evaluate(degToRad(60.0 * k)).r, 20.89681945, 1e-12));
        EXPECT_TRUE(relClose(f.contour.evaluate(degToRad(30.0 + 60.0 * k)).r, 29.0, 1e-12));
    }
}

// The seed's Table 2 as printed (seed 000): r in "m" (10× too large), v in m/s, a in m/s².
struct SeedRow {
    double t, rPrinted, vR, vPhi, aR, aPhi;
};
constexpr SeedRow kSeedTable2[] = {
    {0.05, 0.262188, -0.3725573, 0.4118443, -41.080, -11.704},
    {0.15, 0.262188, 0.3657905, 0.4118442, -39.569, 11.492},
    {0.37, 0.288972, -0.0637046, 0.4539164, -25.911, -20.013},
};

TEST(SeedTable2, RadiusColumnIsPrintedTenTimesTooLarge) {
    const Fixture f = load();
    for (const SeedRow& row : kSeedTable2) {
        const double rMetres = stateAt(f.contour, f.omega, row.t).polar.r / 1000.0;
        EXPECT_TRUE(relClose(row.rPrinted / 10.0, rMetres, 2e-6)) << "t=" << row.t;
    }
}

TEST(SeedTable2, VelocitiesAndRadialAccelerationsAreForwardDifferencesWithAStepOf02ms) {
    // The seed differentiated r(t) numerically: v_r = (r(t+h) - r(t))/h and
    // r-ddot = (r(t+2h) - 2r(t+h) + r(t))/h², h = 0.2 ms. That rule reproduces its printed
    // v_r and a_r = r-ddot - r·ω² to 0.01 %, while the exact values differ by 1–2 %.
    const Fixture f = load();
    const double h = 0.2e-3;
    auto r = [&](double t) { return f.contour.evaluate(f.omega * t).r / 1000.0; };  // m
    for (const SeedRow& row : kSeedTable2) {
        const double vForward = (r(row.t + h) - r(row.t)) / h;
        const double rDdot = (r(row.t + 2 * h) - 2 * r(row.t + h) + r(row.t)) / (h * h);
        const double aForward = rDdot - r(row.t) * f.omega * f.omega;
        EXPECT_TRUE(relClose(vForward, row.vR, 1e-4)) << "t=" << row.t;
        EXPECT_TRUE(relClose(aForward, row.aR, 1e-4)) << "t=" << row.t;

        const KinematicState exact = stateAt(f.contour, f.omega, row.t);
        const double vExact = exact.motion.vR / 1000.0, aExact = exact.motion.aR / 1000.0;
        EXPECT_GT(std::abs(vExact - row.vR) / std::abs(vExact), 0.005) << "t=" << row.t;
        EXPECT_LT(std::abs(vExact - row.vR) / std::abs(vExact), 0.04) << "t=" << row.t;
        EXPECT_GT(std::abs(aExact - row.aR) / std::abs(aExact), 0.001) << "t=" << row.t;
        EXPECT_LT(std::abs(aExact - row.aR) / std::abs(aExact), 0.03) << "t=" << row.t;
        // v_phi = r·ω needs no derivative, so the seed has it right to its printed digits.
        EXPECT_TRUE(relClose(exact.motion.vPhi / 1000.0, row.vPhi, 2e-6)) << "t=" << row.t;
    }
}

TEST(SeedTable2, TangentialAccelerationIsTwiceTheForwardDifferenceVelocityTimesOmega) {
    // a_phi = 2·r-dot·ω, with the seed's forward-difference r-dot. At t = 0.37 s the printed
    // -20.013 is 10× too large: -2.0013 m/s² is what the rule gives (exact: -1.9424 m/s²).
    const Fixture f = load();
    const double h = 0.2e-3;
    auto r = [&](double t) { return f.contour.evaluate(f.omega * t).r / 1000.0; };  // m
    for (const SeedRow& row : kSeedTable2) {
        const double printed = row.t == 0.37 ? row.aPhi / 10.0 : row.aPhi;
        const double vForward = (r(row.t + h) - r(row.t)) / h;
        EXPECT_TRUE(relClose(2.0 * vForward * f.omega, printed, 1e-4)) << "t=" << row.t;
    }
    const double exact = stateAt(f.contour, f.omega, 0.37).motion.aPhi / 1000.0;
    EXPECT_TRUE(relClose(exact, -1.9424177361, 1e-9));
}

}  // namespace
}  // namespace cam
