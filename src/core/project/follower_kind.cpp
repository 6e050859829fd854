#include "project/follower_kind.h"

#include <array>

#include "common/kind_table.h"
#include "common/translate_marker.h"

namespace cam {
namespace {

/// Every kind, one row each, in FollowerType order.
constexpr std::array<FollowerKind, 3> kKinds{{
    // type, name, title, hasRadius, canSwing, flatFace
    {FollowerType::Knife, "knife", CAM_TRANSLATE_NOOP("FollowerKind", "Knife edge"), false, true,
     false},
    {FollowerType::Roller, "roller", CAM_TRANSLATE_NOOP("FollowerKind", "Roller"), true, true,
     false},
    {FollowerType::Flat, "flat", CAM_TRANSLATE_NOOP("FollowerKind", "Flat face"), false, false,
     true},
}};

static_assert(rowsFollowTheirEnum(kKinds, &FollowerKind::type),
              "one row per follower kind, in FollowerType order");

}  // namespace

std::span<const FollowerKind> followerKinds() { return kKinds; }

const FollowerKind& followerKind(FollowerType type) {
    return kKinds.at(static_cast<std::size_t>(type));
}

std::optional<FollowerType> followerTypeFromName(std::string_view name) {
    for (const FollowerKind& kind : kKinds) {
        if (kind.name == name) return kind.type;
    }
    return std::nullopt;
}

double contactRadius(const FollowerSpec& spec) {
    return followerKind(spec.type).hasRadius ? spec.radius : 0.0;
}

}  // namespace cam
