#pragma once
/// @file
/// @brief The tables that describe each kind of something once (motion laws, follower kinds,
/// export formats) are indexed by their enum: row k describes enumerator k.

#include <array>
#include <cstddef>

namespace cam {

/// @brief Whether row k of `rows` names enumerator k (its member `id`), for every k: for a
/// static_assert beside the table.
template <class Row, std::size_t N, class Enum>
constexpr bool rowsFollowTheirEnum(const std::array<Row, N>& rows, Enum Row::*id) {
    for (std::size_t k = 0; k < N; ++k) {
        if (static_cast<std::size_t>(rows[k].*id) != k) return false;
    }
    return true;
}

}  // namespace cam
