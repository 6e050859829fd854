#pragma once
/// @file
/// @brief The follower drawn in the contour view at the cursor angle (math.md §7): its line of
/// motion, or its arm and pivot; the roller's circle or the flat face; the contact point and the
/// contact normal; a conjugate yoke's second roller. followerGlyphShape() says where each part goes
/// (plane geometry, no Qt); FollowerGlyph holds the QCustomPlot items that show it.

#include <qcustomplot.h>

#include <Eigen/Core>
#include <array>
#include <optional>

#include "closure/conjugate.h"
#include "follower/follower.h"

namespace cam {

/// @brief Where each part of the follower glyph lies (mm, the cam frame).
struct FollowerGlyphShape {
    /// A translating follower's line of motion, from its follower point (FollowerState::center)
    /// out past the follower; or a swinging arm, from its pivot to that point.
    Eigen::Vector2d guideStart{0.0, 0.0}, guideEnd{0.0, 0.0};
    std::optional<Eigen::Vector2d> pivot;  ///< a swinging arm's pivot, turned with the cam
    /// A roller: its circle of this radius about the follower point.
    std::optional<double> rollerRadius;
    Eigen::Vector2d center{0.0, 0.0};  ///< the follower point (the roller's centre)
    /// A flat face: its ends, either side of the follower point across the line of motion.
    std::optional<std::array<Eigen::Vector2d, 2>> face;
    Eigen::Vector2d contact{0.0, 0.0};
    Eigen::Vector2d normalTip{0.0, 0.0};  ///< the contact normal's arrow runs contact → tip
    /// A conjugate pair's second roller (closure/conjugate.h): its circle and its contact on
    /// the second plate. On a yoke the line of motion runs from it through the first roller; on
    /// a bell crank its own arm runs from the pivot (`arm`).
    struct Second {
        Eigen::Vector2d center{0.0, 0.0}, contact{0.0, 0.0};
        double radius = 0.0;
        std::optional<Eigen::Vector2d> arm;  ///< a bell crank's pivot, where its arm starts
    };
    std::optional<Second> second;
};

/// @brief The glyph of follower `spec` in `state`, at cam angle `phi` (rad); none when the state
/// is not finite (no contact at this angle). Lengths scale with the follower point's distance
/// d from the centre (at least 1 mm): the line of motion reaches 0.25·d past the follower, the
/// normal is 0.12·d long, and a flat face reaches 1.3 times the contact's distance from the
/// line of motion (|ds/dφ|) either side, at least 0.1·d.
[[nodiscard]] std::optional<FollowerGlyphShape> followerGlyphShape(const FollowerSpec& spec,
                                                                   const FollowerState& state,
                                                                   double phi);
/// @brief The glyph of the follower on its cam at angle `phi`, turning at `omega` rad/s.
[[nodiscard]] std::optional<FollowerGlyphShape> followerGlyphAt(const FollowerModel& model,
                                                                double phi, double omega);

/// @brief `shape` of the roller `model` at cam angle `phi` with the second roller of `yoke`
/// added (ConjugatePoint: exact, on the second plate as computed, not as fitted).
[[nodiscard]] FollowerGlyphShape withSecondRoller(FollowerGlyphShape shape,
                                                  const FollowerModel& model,
                                                  const SecondRoller& yoke, double phi);

/// @brief `shape` turned by `angle` (rad, counter-clockwise) about the cam's centre.
[[nodiscard]] FollowerGlyphShape turnedBy(FollowerGlyphShape shape, double angle);

/// @brief Where the follower is drawn now (mm, the cam frame): for tests and pictures.
struct FollowerMarkers {
    bool shown = false;
    bool pivotShown = false;
    QPointF pivot, center, contact, normalTip;
    double rollerRadius = 0.0;  ///< 0 unless a roller is drawn
    bool secondShown = false;   ///< a conjugate yoke's second roller
    QPointF secondCenter, secondContact;
    double secondRadius = 0.0;
};

/// @brief The plot items that draw a FollowerGlyphShape; the plot owns them.
class FollowerGlyph {
public:
    /// @brief Adds the items to `plot` on `layer`, hidden and not selectable.
    FollowerGlyph(QCustomPlot* plot, QCPLayer* layer);
    /// @brief Draws `shape`; none hides the follower. (Redrawing the layer is the caller's.)
    void show(const std::optional<FollowerGlyphShape>& shape);
    /// @brief What the items show, read back from them.
    [[nodiscard]] FollowerMarkers markers() const;

private:
    [[nodiscard]] std::array<QCPAbstractItem*, 9> items() const;

    QCPItemLine* m_guide = nullptr;  ///< the line of motion, or the arm
    QCPItemTracer* m_pivot = nullptr;
    QCPItemEllipse* m_roller = nullptr;
    QCPItemLine* m_face = nullptr;
    QCPItemTracer* m_contact = nullptr;
    QCPItemLine* m_normal = nullptr;
    QCPItemEllipse* m_secondRoller = nullptr;
    QCPItemTracer* m_secondContact = nullptr;
    QCPItemLine* m_secondArm = nullptr;
    QPointF m_center;  ///< the follower point of the shape shown last
};

}  // namespace cam
