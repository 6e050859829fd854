#pragma once

#include <QMainWindow>

class QCustomPlot;

namespace cam {

/// @brief Placeholder main window: the contour and r(phi) of one project.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    /// @brief Loads a project; returns the located problems as text, empty on success.
    QString openProject(const QString& path);

private:
    QCustomPlot* m_contourPlot = nullptr;
    QCustomPlot* m_radiusPlot = nullptr;
};

}  // namespace cam
