#include "document/segment_colours.h"

#include <algorithm>
#include <array>
#include <limits>

namespace cam {

std::vector<int> freshColourSlots(int rows) {
    std::vector<int> held(static_cast<std::size_t>(std::max(rows, 0)));
    for (std::size_t k = 0; k < held.size(); ++k) {
        held[k] = static_cast<int>(k) % kSegmentColourSlots;
    }
    return held;
}

int colourSlotFor(const std::vector<int>& held, int row) {
    const int n = static_cast<int>(held.size());
    std::array<int, kSegmentColourSlots> used{};
    for (int s : held) ++used[static_cast<std::size_t>(s)];
    std::array<bool, kSegmentColourSlots> neighbour{};
    if (n > 0) {
        neighbour[static_cast<std::size_t>(held[static_cast<std::size_t>((row - 1 + n) % n)])] =
            true;
        neighbour[static_cast<std::size_t>(held[static_cast<std::size_t>(row % n)])] = true;
    }
    int best = 0, fewest = std::numeric_limits<int>::max();
    for (int colour = 0; colour < kSegmentColourSlots; ++colour) {
        const auto c = static_cast<std::size_t>(colour);
        if (!neighbour[c] && used[c] < fewest) {
            best = colour;
            fewest = used[c];
        }
    }
    return best;
}

}  // namespace cam
