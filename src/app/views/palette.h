#pragma once
/// @file
/// @brief Colours shared by the views: one per segment (cycled), and the curve colours.

#include <QColor>

#include "document/segment_colours.h"

namespace cam {

/// @brief How many colours segments are drawn in.
inline constexpr int kSegmentColorCount = kSegmentColourSlots;

/// @brief The colour of slot k mod kSegmentColorCount (Tableau 10); a segment's slot is the
/// document's segmentColourSlot, k itself where there is no document (the CLI's pictures).
inline QColor segmentColor(int k) {
    static const QColor colors[kSegmentColorCount] = {
        {31, 119, 180}, {255, 127, 14},  {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
        {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
    return colors[k % kSegmentColorCount];
}

/// @brief Radial, tangential, magnitude.
inline QColor componentColor(int component) {
    static const QColor colors[] = {{31, 119, 180}, {214, 39, 40}, {40, 40, 40}};
    return colors[component % 3];
}

}  // namespace cam
