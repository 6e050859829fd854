#pragma once
/// @file
/// @brief Which colour each segment is drawn in: a slot that belongs to the segment, not to
/// its row, so inserting, deleting or moving one leaves every other segment its colour
/// (issue 31: the colours followed the index and all shifted after an insertion).

#include <vector>

namespace cam {

/// @brief How many colours segments are drawn in (views/palette.h has them).
inline constexpr int kSegmentColourSlots = 10;

/// @brief The slots of a contour of `rows` segments as a file opens it: row k in slot k mod
/// kSegmentColourSlots.
[[nodiscard]] std::vector<int> freshColourSlots(int rows);

/// @brief The slot for a segment inserted at `row` between the segments holding `held` (the
/// contour closes: the first and the last are neighbours): one neither neighbour has, the
/// least used of those, the lowest of equals.
[[nodiscard]] int colourSlotFor(const std::vector<int>& held, int row);

}  // namespace cam
