#pragma once
/// @file
/// @brief Help → User Guide (F1): the short guide bundled with the app (resources/help), in the
/// window's language, opened at the section of what has the focus.

#include <QDialog>

class QTextBrowser;

namespace cam {

class UserGuide : public QDialog {
    Q_OBJECT
public:
    explicit UserGuide(QWidget* parent = nullptr);

    /// @brief Scrolls to a section ("start", "table", "construction", "splines", "plots",
    /// "followers", "design", "machining", "exports", "cli", "files").
    void showSection(const QString& anchor);
    [[nodiscard]] QTextBrowser* browser() const { return m_browser; }
    /// @brief The guide's resource path in the language of the installed translation.
    [[nodiscard]] static QString source();
    /// @brief The section that explains a widget: that of the dock it sits in, of the contour
    /// view or of the plots; "start" when none does.
    [[nodiscard]] static QString sectionFor(const QWidget* widget);

private:
    QTextBrowser* m_browser;
};

}  // namespace cam
