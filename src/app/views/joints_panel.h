#pragma once
/// @file
/// @brief Every joint of the contour with its continuity and jumps; click one to go to it.

#include <QTableWidget>

#include "engine/compute_result.h"

namespace cam {

class JointsPanel : public QTableWidget {
    Q_OBJECT
public:
    explicit JointsPanel(QWidget* parent = nullptr);
    void setResult(const ComputeResultPtr& result);

signals:
    /// The user picked the joint between segments `left` and `right` at angle phi (rad).
    void jointPicked(int left, int right, double phi);

protected:
    void showEvent(QShowEvent* event) override;

private:
    void fill();

    ComputeResultPtr m_result;
    bool m_stale = false;  ///< a result arrived while hidden: fill when shown
};

}  // namespace cam
