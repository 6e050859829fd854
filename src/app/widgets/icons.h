#pragma once
/// @file
/// @brief Icons of the actions: the desktop theme's where it has the standard name (document-new,
/// edit-undo, …), Camwright's own SVGs otherwise (resources/icons, embedded under
/// :/icons/actions), and always ours for Camwright's own actions (names starting "camwright-").

#include <QIcon>
#include <QString>

namespace cam {

[[nodiscard]] QIcon actionIcon(const QString& name);

}  // namespace cam
