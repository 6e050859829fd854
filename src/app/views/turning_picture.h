#pragma once
/// @file
/// @brief The turning direction as a button that shows it: the cam, its centre, the follower's
/// line of motion at the offset e (to the left of its direction seen from the centre when
/// positive) with its roller, knife or face, and an arrow for the turning direction. It
/// answers the question the offset's sign raises (which side is which); checked: clockwise,
/// and a click (or Space) turns the cam round.

#include <QAbstractButton>
#include <optional>

#include "project/project.h"

namespace cam {

/// @brief Whether the cam turns clockwise under its follower, seen from the front (the drawing
/// of the contour): a positive speed (or a period) does. The follower assembly turns by
/// φ = ω·t in the cam's frame (math.md §7), counter-clockwise round the drawing for ω > 0, so
/// the cam turns the other way under a follower that stands still.
[[nodiscard]] bool turnsClockwise(const MotionSpec& motion);

class TurningPicture : public QAbstractButton {
    Q_OBJECT
public:
    explicit TurningPicture(QWidget* parent = nullptr);
    /// @brief What to draw: the turning direction and the project's follower (none: the ray of
    /// a radial knife, as the window uses without one).
    void show(bool clockwise, const std::optional<FollowerSpec>& follower);
    [[nodiscard]] bool clockwise() const { return m_clockwise; }
    [[nodiscard]] QSize sizeHint() const override { return {120, 56}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    bool m_clockwise = false;
    std::optional<FollowerSpec> m_follower;
};

}  // namespace cam
