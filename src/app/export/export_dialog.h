#pragma once
/// @file
/// @brief File → Export…: the format, the options of that format and the file, in one dialog.

#include <QDialog>
#include <optional>
#include <vector>

#include "export/export_request.h"
#include "project/project.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QStackedWidget;

namespace cam {

class NumberSpinBox;

/// @brief The G-code feed the dialog starts with for a project that sets no feed limit
/// (mm/min): a cautious one for a first cut, not the machine's top speed.
inline constexpr double kCautiousFeedMmMin = 1000.0;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    /// @brief Options start from the project (its samples per turn, tool radius, feed) and the
    /// last export (format, folder and the other options, from QSettings). One name titles the
    /// SVG and the G-code and names the cam table, as camwright-cli does (exportName): the
    /// project's, else `baseName` (the file name without .cam.json, "untitled" for a project
    /// never saved), which also names the file by default. `plots` are the plots that can be
    /// drawn now. The file goes into the folder of this project's last export, else the folder
    /// of `projectFile` (the project's own file, empty when it has none), else that of the last
    /// export of any project, else home.
    ExportDialog(const Project& project, const QString& baseName, std::vector<PlotKind> plots,
                 QWidget* parent = nullptr, const QString& projectFile = {});

    /// @brief The export as the dialog's fields say (meaningful once accepted).
    [[nodiscard]] ExportRequest request() const;
    /// @brief Chooses a format as if the user picked it (the file's suffix follows).
    void setFormat(ExportFormat format);
    /// @brief Names the file as if the user typed it.
    void setFileName(const QString& path);

    void accept() override;

private:
    void formatChanged();
    void browse();
    /// The file's suffix follows the format (and for pictures the picture format).
    void matchSuffix();
    [[nodiscard]] ExportFormat format() const;
    /// The options remembered from one export to the next (QSettings export/options/NAME):
    /// all but those the project gives (samples per turn, tool radius, feed) and the plot.
    [[nodiscard]] std::vector<QWidget*> rememberedOptions() const;
    void restoreOptions();
    /// Asks for the cam table's report as the fields now say; its answer fills m_tableReport.
    void updateTableReport();

    QString m_baseName;
    /// "-velocity": the plot's name matchSuffix added to the file's name (empty: none).
    QString m_plotTail;
    std::vector<PlotKind> m_plots;
    QComboBox* m_format = nullptr;
    QStackedWidget* m_pages = nullptr;
    QSpinBox* m_csvPoints = nullptr;
    QCheckBox* m_csvGerman = nullptr;
    NumberSpinBox* m_dxfTolerance = nullptr;
    QCheckBox* m_dxfPolyline = nullptr;
    QCheckBox* m_dxfSplines = nullptr;
    QCheckBox* m_dxfCentres = nullptr;
    QCheckBox* m_dxfToolPath = nullptr;
    NumberSpinBox* m_dxfToolRadius = nullptr;
    NumberSpinBox* m_svgTolerance = nullptr;
    NumberSpinBox* m_gcodeToolRadius = nullptr;
    NumberSpinBox* m_gcodeFeed = nullptr;
    QLabel* m_gcodePlunge = nullptr;
    QString m_projectFile;
    /// The project's feed limit (mm/min) and tool radius (mm), when its machining section
    /// gives them: the feed stays below the one, the tool radii are the other.
    std::optional<double> m_feedLimit;
    std::optional<double> m_projectToolRadius;
    /// A grooved cam's: half the groove's width, the tool that cuts it in one slot pass.
    std::optional<double> m_grooveToolRadius;
    NumberSpinBox* m_gcodeDepth = nullptr;
    QCheckBox* m_gcodeStepDownOn = nullptr;
    NumberSpinBox* m_gcodeStepDown = nullptr;
    NumberSpinBox* m_gcodeTolerance = nullptr;
    QCheckBox* m_gcodeCompensation = nullptr;
    /// A conjugate pair's: which plate the program mills (none for another cam).
    QComboBox* m_gcodePlate = nullptr;
    QSpinBox* m_tablePoints = nullptr;
    QComboBox* m_tableDialect = nullptr;
    QComboBox* m_tableSource = nullptr;
    /// The controller's interpolation error and the motion's characteristics, computed in the
    /// background for the table as the fields say (stale answers are dropped).
    QLabel* m_tableReport = nullptr;
    int m_tableReportRequest = 0;
    Project m_project;  ///< the snapshot the report is computed from
    QComboBox* m_plot = nullptr;
    QComboBox* m_picture = nullptr;
    QSpinBox* m_width = nullptr;
    QSpinBox* m_height = nullptr;
    QLineEdit* m_file = nullptr;
    QLabel* m_problem = nullptr;
    /// What the SVG's title, the G-code header and the cam table's name say (exportName).
    std::string m_title;
};

}  // namespace cam
