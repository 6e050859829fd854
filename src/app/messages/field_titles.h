#pragma once
/// @file
/// @brief How the window names the fields a message can point at: the segment table's column
/// titles and the motion laws' titles. Below the models, which show them, and the diagnostic
/// text, which names them in its messages.

#include <QString>
#include <QStringList>

#include "common/dynamics_key.h"

namespace cam {

/// @brief The segment table's columns, in the order of the fields they edit (EditedField in
/// document/commands.h). SegmentTableModel inherits them: SegmentTableModel::Radius.
struct SegmentColumns {
    enum Column {
        Type,
        CenterX,
        CenterY,
        Radius,
        Branch,
        FromX,
        FromY,
        ToX,
        ToY,
        PhiStart,
        PhiEnd,
        ColumnCount
    };
};

/// @brief "Radius [mm]": the title of a segment table column; empty for none.
[[nodiscard]] QString segmentColumnTitle(int column);

/// @brief The motion laws' titles in the window's language, in MotionLawType order.
[[nodiscard]] QStringList motionLawTitles();
/// @brief Each law's one-line summary (the law list's tips), translated, in MotionLawType's
/// order.
[[nodiscard]] QStringList motionLawSummaries();

/// @brief "Mass [kg]", "Cam material, E [MPa]": a dynamics value's title in the window.
[[nodiscard]] QString dynamicsKeyTitle(DynamicsKey key);

}  // namespace cam
