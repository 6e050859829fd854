#pragma once
/// @file
/// @brief Each follower kind described once: its name in files and on the command line, its
/// title in the window, whether it has a contact circle and whether it can swing on an arm.
/// Adding a kind: docs/architecture.md, "A follower kind".

#include <optional>
#include <span>
#include <string_view>

#include "project/project.h"

namespace cam {

struct FollowerKind {
    FollowerType type;
    std::string_view name;  ///< in project files and the CLI's output: "roller"
    /// English, for the window's follower type; the app translates it in context
    /// "FollowerKind".
    const char* title;
    /// Touches the cam with a circle of FollowerSpec::radius (its centre rides the pitch curve
    /// that far off the cam); without one, the contact radius is 0.
    bool hasRadius;
    /// May ride a swinging arm (math.md §7: a flat face only translates).
    bool canSwing;
    /// Touches the cam with a flat face: its checks report the face width the contact needs,
    /// and a profile radius ≤ 0 (a concave stretch) is a problem.
    bool flatFace;
};

/// @brief Every kind, in FollowerType order.
[[nodiscard]] std::span<const FollowerKind> followerKinds();
/// @brief The row of a kind.
[[nodiscard]] const FollowerKind& followerKind(FollowerType type);
/// @brief The kind a file or command names; none for an unknown name.
[[nodiscard]] std::optional<FollowerType> followerTypeFromName(std::string_view name);

/// @brief The radius of the follower's contact circle (mm): the roller's radius, 0 for a knife
/// edge or a flat face. The pitch curve lies this far outside the cam.
[[nodiscard]] double contactRadius(const FollowerSpec& spec);

}  // namespace cam
