#pragma once
// The dynamics the force tests and benchmarks put on a translating roller: every key set, with
// round values that a hand computation can follow.

#include "project/project.h"

namespace cam::test {

/// 0.5 kg on a 2 N/mm spring preloaded with 20 N, 5 N of external load, 10 N·s/m of damping, a
/// 12 mm wide contact, steel on steel (E = 210 000 MPa, ν = 0.3).
inline DynamicsSpec steelOnSteelDynamics() {
    DynamicsSpec d;
    using K = DynamicsKey;
    d[K::MassKg] = 0.5;
    d[K::SpringRateNPerMm] = 2.0;
    d[K::SpringPreloadN] = 20.0;
    d[K::ExternalForceN] = 5.0;
    d[K::DampingNsPerM] = 10.0;
    d[K::ContactWidthMm] = 12.0;
    d[K::CamModulusMpa] = 210000.0;
    d[K::CamPoisson] = 0.3;
    d[K::FollowerModulusMpa] = 210000.0;
    d[K::FollowerPoisson] = 0.3;
    return d;
}

}  // namespace cam::test
