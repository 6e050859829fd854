#pragma once
/// @file
/// @brief Marks English text of the core that the app translates, without Qt: the text itself,
/// found by lupdate as QT_TRANSLATE_NOOP (resources/translations/update_translations.py passes
/// `-tr-function-alias QT_TRANSLATE_NOOP+=CAM_TRANSLATE_NOOP`). The app translates it with
/// QCoreApplication::translate(context, text).

#define CAM_TRANSLATE_NOOP(context, text) text
