#pragma once
/// @file
/// @brief The window's language: Qt's own strings (dialog buttons, file dialogs, key names such
/// as "Strg" and "Entf") from Qt's translations, and Camwright's from the bundled .qm.

#include <QLocale>
#include <QTranslator>

namespace cam {

/// @brief Installs both translations for `locale` while it lives (none for English, or where a
/// file is missing: then that part stays English), and removes them when it goes.
class Translations {
public:
    explicit Translations(const QLocale& locale);
    ~Translations();
    Translations(const Translations&) = delete;
    Translations& operator=(const Translations&) = delete;

    /// @brief Qt's own strings are translated (Debian: qt6-translations-l10n is installed).
    [[nodiscard]] bool qtTranslated() const { return m_qtInstalled; }
    /// @brief Camwright's strings are translated.
    [[nodiscard]] bool appTranslated() const { return m_appInstalled; }

private:
    QTranslator m_qt, m_app;
    bool m_qtInstalled = false, m_appInstalled = false;
};

}  // namespace cam
