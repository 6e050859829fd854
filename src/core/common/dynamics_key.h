#pragma once
/// @file
/// @brief The keys of a project's `dynamics` section (math.md §9, project-format.md), named once:
/// each is X(enumerator, group, key) — its key in the file, inside the object `group` when that
/// is not empty ("dynamics.cam_material.E_MPa"). What each key means and which values it takes
/// is its row in project/dynamics.cpp. Adding a key: a line here, its row there, its title in
/// the window (app/messages/dynamics_text.cpp).

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace cam {

#define CAM_DYNAMICS_KEYS(X)                                         \
    X(MassKg, "", "mass_kg")                                         \
    X(SpringRateNPerMm, "", "spring_rate_N_per_mm")                  \
    X(SpringPreloadN, "", "spring_preload_N")                        \
    X(ExternalForceN, "", "external_force_N")                        \
    X(DampingNsPerM, "", "damping_Ns_per_m")                         \
    X(InertiaKgM2, "", "inertia_kg_m2")                              \
    X(SpringRateNmPerRad, "", "spring_rate_Nm_per_rad")              \
    X(SpringPreloadNm, "", "spring_preload_Nm")                      \
    X(ExternalMomentNm, "", "external_moment_Nm")                    \
    X(DampingNmsPerRad, "", "damping_Nms_per_rad")                   \
    X(ContactWidthMm, "", "contact_width_mm")                        \
    X(CamModulusMpa, "cam_material", "E_MPa")                        \
    X(CamPoisson, "cam_material", "poisson")                         \
    X(FollowerModulusMpa, "follower_material", "E_MPa")              \
    X(FollowerPoisson, "follower_material", "poisson")               \
    X(AllowableContactStressMpa, "", "allowable_contact_stress_MPa") \
    X(SpringSafetyFactor, "", "spring_safety_factor")

#define CAM_DYNAMICS_KEY_ENUM(name, group, key) name,
enum class DynamicsKey { CAM_DYNAMICS_KEYS(CAM_DYNAMICS_KEY_ENUM) };
#undef CAM_DYNAMICS_KEY_ENUM

#define CAM_DYNAMICS_KEY_COUNT(name, group, key) +1
inline constexpr std::size_t kDynamicsKeyCount = 0 CAM_DYNAMICS_KEYS(CAM_DYNAMICS_KEY_COUNT);
#undef CAM_DYNAMICS_KEY_COUNT

/// @brief Where a key sits in the file: the object inside `dynamics` ("" for none,
/// "cam_material", …) and its own name there ("mass_kg", "E_MPa").
struct DynamicsKeyPlace {
    std::string_view group;
    std::string_view name;
};

#define CAM_DYNAMICS_KEY_PLACE(name, group, key) DynamicsKeyPlace{group, key},
inline constexpr std::array<DynamicsKeyPlace, kDynamicsKeyCount> kDynamicsKeyPlaces{
    CAM_DYNAMICS_KEYS(CAM_DYNAMICS_KEY_PLACE)};
#undef CAM_DYNAMICS_KEY_PLACE

/// @brief The object a key sits in inside `dynamics` ("" for none, "cam_material", …).
[[nodiscard]] constexpr std::string_view dynamicsKeyGroup(DynamicsKey key) {
    return kDynamicsKeyPlaces[static_cast<std::size_t>(key)].group;
}

/// @brief The key's own name in its object ("mass_kg", "E_MPa").
[[nodiscard]] constexpr std::string_view dynamicsKeyName(DynamicsKey key) {
    return kDynamicsKeyPlaces[static_cast<std::size_t>(key)].name;
}

/// @brief Its path in the file: "dynamics.mass_kg", "dynamics.cam_material.E_MPa".
[[nodiscard]] std::string dynamicsKeyPath(DynamicsKey key);

}  // namespace cam
