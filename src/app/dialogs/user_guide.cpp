#include "dialogs/user_guide.h"

#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace cam {

UserGuide::UserGuide(QWidget* parent) : QDialog(parent) {
    setObjectName("userGuide");
    setWindowTitle(tr("Camwright User Guide"));
    auto* layout = new QVBoxLayout(this);
    m_browser = new QTextBrowser(this);
    m_browser->setObjectName("userGuideText");
    m_browser->setOpenExternalLinks(true);
    m_browser->setSource(QUrl(QStringLiteral("qrc") + source()));
    layout->addWidget(m_browser);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(760, 640);
}

QString UserGuide::source() {
    // The file name is a translatable string: the guide follows the translation installed.
    return QStringLiteral(":/help/") + tr("user-guide.en.html");
}

void UserGuide::showSection(const QString& anchor) {
    m_browser->scrollToAnchor(anchor);
    show();
    raise();
    activateWindow();
}

QString UserGuide::sectionFor(const QWidget* widget) {
    static const std::pair<const char*, const char*> sections[] = {
        {"segmentsDock", "table"},        {"jointsDock", "table"},
        {"controlPointsDock", "splines"}, {"pathStudyDock", "splines"},
        {"motionDock", "start"},          {"readoutDock", "plots"},
        {"machiningDock", "machining"},   {"followerDock", "followers"},
        {"forcesDock", "forces"},         {"motionDesignDock", "design"},
        {"contourView", "construction"},  {"kinematicsPlots", "plots"},
    };
    for (const QWidget* w = widget; w; w = w->parentWidget()) {
        for (const auto& [name, section] : sections) {
            if (w->objectName() == QLatin1String(name)) return QString::fromLatin1(section);
        }
    }
    return QStringLiteral("start");
}

}  // namespace cam
