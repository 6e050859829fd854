// Shared main for the app tests: offscreen platform (also when ctest discovers the tests at
// build time, without the ENVIRONMENT property), Fusion style, C locale, settings in a fresh
// temporary folder.

#include <gtest/gtest.h>

#include <QApplication>
#include <QLocale>
#include <QSettings>
#include <QStandardPaths>
#include <QStyleFactory>
#include <QTemporaryDir>

namespace {

/// Every test starts with the default window layout: a test that closes its window saves the
/// layout (closeEvent), and a later window would otherwise open with that test's docks.
class FreshLayout : public ::testing::EmptyTestEventListener {
    void OnTestStart(const ::testing::TestInfo&) override {
        QSettings settings;
        settings.remove("window");
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QLocale::setDefault(QLocale::c());
    // A home of this process's own: with the test mode on, Qt keeps application data (the
    // recovery folder of autosave) under ~/.qttest, which the app_tests processes ctest runs
    // side by side would otherwise share — one process's session copies offered for recovery
    // in another, a modal prompt no test answers.
    const QTemporaryDir home;
    qputenv("HOME", home.path().toLocal8Bit());
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    // Settings (layout, recent files, axis choice) start empty in every run and never touch
    // the user's own configuration.
    QTemporaryDir settingsDir;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QApplication::setStyle(QStyleFactory::create("Fusion"));
    QApplication::setOrganizationName("CamwrightTests");
    QApplication::setApplicationName("camwright-tests");
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::UnitTest::GetInstance()->listeners().Append(new FreshLayout);
    return RUN_ALL_TESTS();
}
