#include "translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>

namespace cam {

Translations::Translations(const QLocale& locale) {
    if (m_qt.load(locale, "qtbase", "_", QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        m_qtInstalled = QCoreApplication::installTranslator(&m_qt);
    }
    if (m_app.load(locale, "camwright", "_", ":/i18n")) {
        m_appInstalled = QCoreApplication::installTranslator(&m_app);
    }
}

Translations::~Translations() {
    if (m_appInstalled) QCoreApplication::removeTranslator(&m_app);
    if (m_qtInstalled) QCoreApplication::removeTranslator(&m_qt);
}

}  // namespace cam
