#pragma once
/// @file
/// @brief The small dialogs of the Edit menu's contour operations: they only ask; the
/// operations themselves are in document/contour_edits.h.

#include <QCoreApplication>
#include <QString>
#include <optional>

#include "spline/teach_in.h"

class QWidget;

namespace cam {

struct TeachInInput {
    QString points;  ///< "x, y" per line
    HandleRule rule = HandleRule::Oval;
    double bulge = 1.0;
};

class ContourDialogs {
    Q_DECLARE_TR_FUNCTIONS(cam::ContourDialogs)
public:
    /// @brief Teach-in points, handle rule and bulge factor; none when cancelled.
    [[nodiscard]] static std::optional<TeachInInput> askTeachIn(QWidget* parent);
    /// @brief The admissible radial error of an arc's Bézier approximation, mm.
    [[nodiscard]] static std::optional<double> askRadialError(QWidget* parent);
};

}  // namespace cam
