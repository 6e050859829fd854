#pragma once
/// @file
/// @brief The feasible region of a translating follower's cam over base radius × offset
/// (issue 29): the smallest base radius at each offset, the region above it shaded, the best
/// point and the design's own marked.

#include <array>
#include <vector>

#include <qcustomplot.h>

namespace cam {

class FeasibleRegionPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit FeasibleRegionPlot(QWidget* parent = nullptr);
    /// @brief Draws the edge (offset, smallest base radius) in mm, NaN where no radius passes,
    /// the chosen point and the design's current one.
    void setRegion(const std::vector<std::array<double, 2>>& edge, std::array<double, 2> chosen,
                   std::array<double, 2> current);
    /// @brief The graphs, for tests: the edge, the top of the shading, the chosen point, the
    /// current one.
    [[nodiscard]] QCPGraph* edgeGraph() const { return graph(0); }
    [[nodiscard]] QCPGraph* chosenGraph() const { return graph(2); }
    [[nodiscard]] QCPGraph* currentGraph() const { return graph(3); }
};

}  // namespace cam
