#include "project/dynamics.h"

#include <array>

#include "common/translate_marker.h"

namespace cam {
namespace {

using K = DynamicsKey;
using R = DynamicsRule;
using F = DynamicsFollower;

constexpr std::array<DynamicsKeyInfo, kDynamicsKeyCount> kKeys{{
    {K::MassKg, "kg", R::Positive, F::Translating, 0.0},
    {K::SpringRateNPerMm, "N/mm", R::Positive, F::Translating, 0.0},
    {K::SpringPreloadN, "N", R::Finite, F::Translating, 0.0},
    {K::ExternalForceN, "N", R::Finite, F::Translating, 0.0},
    {K::DampingNsPerM, "N·s/m", R::NonNegative, F::Translating, 0.0},
    {K::InertiaKgM2, "kg·m²", R::Positive, F::Swinging, 0.0},
    {K::SpringRateNmPerRad, "N·m/rad", R::Positive, F::Swinging, 0.0},
    {K::SpringPreloadNm, "N·m", R::Finite, F::Swinging, 0.0},
    {K::ExternalMomentNm, "N·m", R::Finite, F::Swinging, 0.0},
    {K::DampingNmsPerRad, "N·m·s/rad", R::NonNegative, F::Swinging, 0.0},
    {K::ContactWidthMm, "mm", R::Positive, F::Any, 0.0},
    {K::CamModulusMpa, "MPa", R::Positive, F::Any, 0.0},
    {K::CamPoisson, "", R::Poisson, F::Any, 0.0},
    {K::FollowerModulusMpa, "MPa", R::Positive, F::Any, 0.0},
    {K::FollowerPoisson, "", R::Poisson, F::Any, 0.0},
    {K::AllowableContactStressMpa, "MPa", R::Positive, F::Any, 0.0},
    {K::SpringSafetyFactor, "", R::Positive, F::Any, 1.0},
}};

constexpr bool inKeyOrder() {
    for (std::size_t i = 0; i < kKeys.size(); ++i) {
        if (static_cast<std::size_t>(kKeys[i].key) != i) return false;
    }
    return true;
}
static_assert(inKeyOrder(), "kKeys must have one row per DynamicsKey, in its order");

// Typical room-temperature values; a designer with a data sheet types his own.
// - Steel and hardened rolling-bearing steel (100Cr6): E 210 GPa, ν 0.3, the values of
//   math.md §9 and of the rolling-bearing makers' catalogues.
// - Grey cast iron EN-GJL-250: E 103–118 GPa and ν 0.26 (EN 1561, informative annex); the
//   middle of the range.
// - Nodular cast iron EN-GJS-400-15: E 169 GPa, ν 0.275 (EN 1563, informative annex).
// - Tin bronze CuSn12-C: E about 100 GPa, ν 0.35 (copper institutes' data sheets give 95–110).
// - POM copolymer: E_t about 2,800 MPa (ISO 527; makers' sheets give 2,600–3,100), ν 0.35.
// - PA 6, dry: E_t about 3,000 MPa (ISO 527; conditioned at 50 % RH about a third less),
//   ν 0.39.
constexpr std::array<Material, 7> kMaterials{{
    {"steel", CAM_TRANSLATE_NOOP("Material", "Steel"), 210000.0, 0.30},
    {"bearing-steel", CAM_TRANSLATE_NOOP("Material", "Hardened bearing steel (100Cr6)"), 210000.0,
     0.30},
    {"grey-cast-iron", CAM_TRANSLATE_NOOP("Material", "Grey cast iron (EN-GJL-250)"), 110000.0,
     0.26},
    {"nodular-cast-iron", CAM_TRANSLATE_NOOP("Material", "Nodular cast iron (EN-GJS-400-15)"),
     169000.0, 0.275},
    {"bronze", CAM_TRANSLATE_NOOP("Material", "Tin bronze (CuSn12)"), 100000.0, 0.35},
    {"pom", CAM_TRANSLATE_NOOP("Material", "POM (acetal)"), 2800.0, 0.35},
    {"pa6", CAM_TRANSLATE_NOOP("Material", "PA 6 (dry)"), 3000.0, 0.39},
}};

}  // namespace

std::span<const DynamicsKeyInfo> dynamicsKeys() { return kKeys; }

const DynamicsKeyInfo& dynamicsKey(DynamicsKey key) { return kKeys[static_cast<std::size_t>(key)]; }

bool dynamicsKeyApplies(DynamicsKey key, const FollowerSpec& follower) {
    switch (dynamicsKey(key).follower) {
        case DynamicsFollower::Translating:
            return follower.motion == FollowerMotion::Translating;
        case DynamicsFollower::Swinging:
            return follower.motion == FollowerMotion::Oscillating;
        case DynamicsFollower::Any:
            return true;
    }
    return true;
}

double dynamicsValue(const DynamicsSpec& dynamics, DynamicsKey key) {
    return dynamics[key].value_or(dynamicsKey(key).defaultValue);
}

std::span<const Material> materials() { return kMaterials; }

const Material* materialWith(double modulusMpa, double poisson) {
    for (const Material& m : materials()) {
        if (m.modulusMpa == modulusMpa && m.poisson == poisson) return &m;
    }
    return nullptr;
}

}  // namespace cam
