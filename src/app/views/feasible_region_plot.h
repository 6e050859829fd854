#pragma once
/// @file
/// @brief The feasible region of a cam over base radius × its follower's placement (issue 29:
/// a translating follower's offset, a swinging arm's pivot distance): the smallest base radius
/// at each placement, the largest where the radii end above, the region between shaded, the
/// best point and the design's own marked.

#include <array>
#include <vector>

#include <qcustomplot.h>

#include "design/sizing.h"

namespace cam {

class FeasibleRegionPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit FeasibleRegionPlot(QWidget* parent = nullptr);
    /// @brief Draws the region over the placement (offset or pivot distance, mm): the smallest
    /// base radius, the largest where the radii end above (a swinging arm), the chosen point
    /// and the design's current one.
    void setRegion(Placement placement, const std::vector<FeasibleSpan>& region,
                   std::array<double, 2> chosen, std::array<double, 2> current);
    /// @brief Moves the design's marker (placement, base radius) as the project changes, the
    /// axes widened when it leaves them.
    void setCurrent(std::array<double, 2> current);
    /// @brief The graphs, for tests: the smallest base radius, the top of the shading (the
    /// largest base radius where there is one), the chosen point, the current one.
    [[nodiscard]] QCPGraph* edgeGraph() const { return graph(0); }
    [[nodiscard]] QCPGraph* topGraph() const { return graph(1); }
    [[nodiscard]] QCPGraph* chosenGraph() const { return graph(2); }
    [[nodiscard]] QCPGraph* currentGraph() const { return graph(3); }
};

}  // namespace cam
