#pragma once
/// @file
/// @brief A motion law's picture: its normalised lift s, velocity v and acceleration a over the
/// stretch, as the law list in the Motion Design table shows them.

#include <QPixmap>
#include <QSize>
#include <QVariantList>

#include "design/motion_law.h"

namespace cam {

/// @brief The size of a law's picture in the law list.
inline constexpr QSize kLawPictureSize{72, 36};

/// @brief s (blue) from 0 to 1, v (green) and a (red) each scaled to its largest magnitude,
/// a about the middle line; a dwell is flat. Laws whose shape depends on their segment (poly5,
/// poly7, a table) are drawn rest to rest.
[[nodiscard]] QPixmap lawPicture(MotionLawType law, QSize size = kLawPictureSize,
                                 const LawParameters& parameters = {});
/// @brief Every law's picture as a QIcon, in MotionLawType's order.
[[nodiscard]] QVariantList motionLawPictures();

}  // namespace cam
