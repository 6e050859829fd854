#pragma once
/// @file
/// @brief What each key of a project's `dynamics` section takes (math.md §9, project-format.md):
/// its unit, the values it allows, the follower it belongs to and its default; and a small
/// table of common materials (E, ν) the window offers by name and stores as numbers.

#include <optional>
#include <span>
#include <string_view>

#include "common/dynamics_key.h"
#include "project/project.h"

namespace cam {

/// @brief The values a dynamics key allows.
enum class DynamicsRule {
    Positive,     ///< > 0 (a mass, an inertia, a rate, a width, a modulus, a stress, a factor)
    NonNegative,  ///< ≥ 0 (damping)
    Finite,       ///< any finite value (preloads and external loads, which may pull)
    Poisson,      ///< 0 ≤ ν < 0.5
};

/// @brief Which follower a key belongs to.
enum class DynamicsFollower { Translating, Swinging, Any };

struct DynamicsKeyInfo {
    DynamicsKey key;
    const char* unit;  ///< as the window and messages write it: "kg", "N/mm", "" for none
    DynamicsRule rule;
    DynamicsFollower follower;
    double defaultValue;  ///< what the computation takes when the key is absent
};

/// @brief Every key, in DynamicsKey order.
[[nodiscard]] std::span<const DynamicsKeyInfo> dynamicsKeys();
[[nodiscard]] const DynamicsKeyInfo& dynamicsKey(DynamicsKey key);
/// @brief Whether the key belongs to this follower (a swinging arm's keys only with an arm).
[[nodiscard]] bool dynamicsKeyApplies(DynamicsKey key, const FollowerSpec& follower);
/// @brief The value the computation takes: the given one, or the key's default.
[[nodiscard]] double dynamicsValue(const DynamicsSpec& dynamics, DynamicsKey key);

/// @brief The largest magnitude any dynamics value may have: within it every product the
/// forces form (m·s''·ω², k·lift, F·R'/E*) stays far inside a double.
inline constexpr double kMaxDynamicsValue = 1e12;

/// @brief A material of the built-in table.
struct Material {
    std::string_view name;  ///< in the CLI and as the window's key: "steel"
    const char* title;      ///< English; the window translates it in context "Material"
    double modulusMpa;      ///< Young's modulus E
    double poisson;         ///< ν
};

/// @brief Steel, hardened bearing steel, grey and nodular cast iron, tin bronze, POM, PA 6:
/// typical room-temperature values (sources in dynamics.cpp).
[[nodiscard]] std::span<const Material> materials();
/// @brief The table's material with this E and ν exactly, if any (the window names a stored
/// pair by it).
[[nodiscard]] const Material* materialWith(double modulusMpa, double poisson);

}  // namespace cam
