#pragma once
/// @file
/// @brief The path study of the contour's splines: position, first and second derivative over
/// the segment parameter, analytic and by difference quotient, and their difference.

#include <QWidget>
#include <array>

#include "engine/compute_result.h"

class QCustomPlot;
class QLabel;

namespace cam {

class PathStudyPanel : public QWidget {
    Q_OBJECT
public:
    explicit PathStudyPanel(QWidget* parent = nullptr);
    void setResult(const ComputeResultPtr& result);
    [[nodiscard]] QCustomPlot* plot(int i) const { return m_plots[static_cast<std::size_t>(i)]; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    void fill();

    std::array<QCustomPlot*, 4> m_plots{};
    QLabel* m_note;
    ComputeResultPtr m_result;
    bool m_stale = false;  ///< a result arrived while hidden: draw when shown
};

}  // namespace cam
