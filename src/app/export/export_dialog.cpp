#include "export/export_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

#include "closure/groove.h"
#include "document/project_document.h"
#include "engine/background_priority.h"
#include "export/export_formats.h"
#include "messages/diagnostic_text.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

NumberSpinBox* lengthBox(QWidget* parent, const char* name, double min, double max, double value,
                         const QString& tip) {
    auto* box = new NumberSpinBox(parent);
    box->setObjectName(name);
    box->setRange(min, max);
    box->setValue(value);
    box->setSuffix(QStringLiteral(" mm"));
    box->setToolTip(tip);
    return box;
}

QWidget* page(QStackedWidget* pages, QFormLayout*& form) {
    auto* w = new QWidget(pages);
    form = new QFormLayout(w);
    pages->addWidget(w);
    return w;
}

}  // namespace

ExportDialog::ExportDialog(const Project& project, const QString& baseName,
                           std::vector<PlotKind> plots, QWidget* parent, const QString& projectFile)
    : QDialog(parent),
      m_baseName(baseName),
      m_plots(std::move(plots)),
      m_projectFile(projectFile),
      m_project(project),
      m_title(exportName(project.name, baseName.toStdString())) {
    setWindowTitle(tr("Export"));
    setObjectName("exportDialog");
    auto* layout = new QVBoxLayout(this);
    auto* top = new QFormLayout;
    m_format = new QComboBox(this);
    m_format->setObjectName("exportFormat");
    for (const ExportFormatKind& kind : exportFormats()) {
        m_format->addItem(exportFormatTitle(kind.id), static_cast<int>(kind.id));
    }
    top->addRow(tr("&Format:"), m_format);
    layout->addLayout(top);

    m_pages = new QStackedWidget(this);
    layout->addWidget(m_pages);
    const MachiningSpec machining = project.machining.value_or(MachiningSpec{});
    // Without a machining section: a 6 mm end mill, common and narrow enough for most cams.
    const double toolRadius = machining.toolRadius > 0.0 ? machining.toolRadius : 3.0;
    if (project.machining && project.machining->toolRadius > 0.0) {
        m_projectToolRadius = project.machining->toolRadius;
    }
    if (const auto groove = grooveOf(project)) m_grooveToolRadius = groove->width() / 2.0;
    QFormLayout* form = nullptr;

    // CSV
    page(m_pages, form);
    m_csvPoints = new QSpinBox(this);
    m_csvPoints->setObjectName("csvPoints");
    m_csvPoints->setRange(1, static_cast<int>(kMaxSamplesPerTurn));
    m_csvPoints->setValue(static_cast<int>(project.samplesPerTurnOrDefault()));
    m_csvPoints->setToolTip(tr("Instants over one turn, equally spaced in time"));
    form->addRow(tr("&Samples per turn:"), m_csvPoints);
    // Off at every start (not remembered): the plain form is what every other reader expects.
    m_csvGerman =
        new QCheckBox(tr("For a &German spreadsheet: “;” between cells, decimal comma"), this);
    m_csvGerman->setObjectName("csvGerman");
    m_csvGerman->setToolTip(
        tr("Excel or LibreOffice in a German locale read a plain CSV as text in one column: "
           "this writes 1,5;2,25 instead of 1.5,2.25. Other programs (and camwright-cli) "
           "expect the plain form"));
    form->addRow(m_csvGerman);

    // DXF
    page(m_pages, form);
    m_dxfTolerance = lengthBox(this, "dxfTolerance", 1e-6, 1.0, kDefaultExportToleranceMm,
                               tr("Splines become tangent arc pairs within this distance"));
    form->addRow(tr("Spline &tolerance:"), m_dxfTolerance);
    m_dxfPolyline = new QCheckBox(tr("One closed &polyline with bulges"), this);
    m_dxfPolyline->setObjectName("dxfPolyline");
    m_dxfPolyline->setToolTip(tr("Instead of one LINE or ARC entity per segment"));
    form->addRow(m_dxfPolyline);
    m_dxfSplines = new QCheckBox(tr("Splines as SP&LINE entities"), this);
    m_dxfSplines->setObjectName("dxfSplines");
    m_dxfSplines->setToolTip(tr("Bézier and Hermite segments exactly, instead of arc pairs"));
    form->addRow(m_dxfSplines);
    m_dxfCentres = new QCheckBox(tr("Arc &centres on layer CENTRES"), this);
    m_dxfCentres->setObjectName("dxfCentres");
    form->addRow(m_dxfCentres);
    m_dxfToolPath = new QCheckBox(tr("Tool centre path on layer TOOLPAT&H"), this);
    m_dxfToolPath->setObjectName("dxfToolPath");
    form->addRow(m_dxfToolPath);
    m_dxfToolRadius = lengthBox(this, "dxfToolRadius", 1e-6, 1e6, toolRadius,
                                tr("The cutter's radius: the path keeps this distance"));
    m_dxfToolRadius->setEnabled(false);
    form->addRow(tr("Tool &radius:"), m_dxfToolRadius);
    connect(m_dxfToolPath, &QCheckBox::toggled, m_dxfToolRadius, &QWidget::setEnabled);

    // SVG
    page(m_pages, form);
    m_svgTolerance = lengthBox(this, "svgTolerance", 1e-6, 1.0, kSvgToleranceMm,
                               tr("Splines become tangent arc pairs within this distance"));
    form->addRow(tr("Spline &tolerance:"), m_svgTolerance);

    // G-code
    page(m_pages, form);
    m_gcodeToolRadius = lengthBox(
        this, "gcodeToolRadius", 1e-6, 1e6, m_grooveToolRadius.value_or(toolRadius),
        m_grooveToolRadius
            ? tr("The cutter's radius. The groove's half width (the default) cuts it in one "
                 "slot pass; a narrower tool, at least a third of that, roughs its centre line "
                 "and finishes each flank")
            : tr("The cutter's radius (the project's machining section gives the default)"));
    form->addRow(tr("Tool &radius:"), m_gcodeToolRadius);
    if (project.follower && project.follower->conjugate()) {
        // Each plate of a conjugate pair is its own program.
        m_gcodePlate = new QComboBox(this);
        m_gcodePlate->setObjectName("gcodePlate");
        m_gcodePlate->addItems({tr("First plate (the contour)"), tr("Second plate")});
        m_gcodePlate->setToolTip(
            tr("Which plate of the conjugate pair this program mills: the second is fitted by "
               "arcs within the design's tolerance, as the window draws it"));
        form->addRow(tr("P&late:"), m_gcodePlate);
    }
    // A feed the machine takes: the project's feed limit, else a cautious one to start with.
    m_feedLimit =
        project.machining ? std::optional(project.machining->feedMax * 60.0) : std::nullopt;
    m_gcodeFeed = lengthBox(
        this, "gcodeFeed", 1e-3, 1e7, m_feedLimit.value_or(kCautiousFeedMmMin),
        m_feedLimit ? tr("Feed along the profile; plunges go at half. At most the project's "
                         "feed limit (Machining dock): %1 mm/min")
                          .arg(formatQuantityValue(DisplayQuantity::Input, *m_feedLimit))
                    : tr("Feed along the profile; plunges go at half. The project sets no "
                         "feed limit (Machining dock): %1 mm/min to start with")
                          .arg(formatQuantityValue(DisplayQuantity::Input, kCautiousFeedMmMin)));
    m_gcodeFeed->setSuffix(QStringLiteral(" mm/min"));
    if (m_feedLimit) m_gcodeFeed->setMaximum(*m_feedLimit);
    form->addRow(tr("Fee&d:"), m_gcodeFeed);
    m_gcodePlunge = new QLabel(this);
    m_gcodePlunge->setObjectName("gcodePlunge");
    const auto plunge = [this] {
        m_gcodePlunge->setText(
            tr("%1 mm/min (half the feed)")
                .arg(formatQuantityValue(DisplayQuantity::Input, m_gcodeFeed->value() / 2.0)));
    };
    connect(m_gcodeFeed, &QDoubleSpinBox::valueChanged, this, plunge);
    plunge();
    form->addRow(tr("Plunge:"), m_gcodePlunge);
    m_gcodeDepth = lengthBox(this, "gcodeDepth", 1e-6, 1e4, kDefaultGcodeDepthMm,
                             tr("Total depth of cut below the stock's top (Z0)"));
    form->addRow(tr("De&pth:"), m_gcodeDepth);
    m_gcodeStepDownOn = new QCheckBox(tr("&Step down by"), this);
    m_gcodeStepDownOn->setObjectName("gcodeStepDownOn");
    m_gcodeStepDown = lengthBox(this, "gcodeStepDown", 1e-6, 1e4, 1.0,
                                tr("Depth of each pass; the last pass reaches the full depth"));
    m_gcodeStepDown->setEnabled(false);
    connect(m_gcodeStepDownOn, &QCheckBox::toggled, m_gcodeStepDown, &QWidget::setEnabled);
    form->addRow(m_gcodeStepDownOn, m_gcodeStepDown);
    m_gcodeTolerance = lengthBox(this, "gcodeTolerance", 1e-6, 1.0, kDefaultGcodeToleranceMm,
                                 tr("Splines become tangent arc pairs within this distance"));
    form->addRow(tr("Spline &tolerance:"), m_gcodeTolerance);
    m_gcodeCompensation = new QCheckBox(tr("Part contour with cutter &compensation (G41)"), this);
    m_gcodeCompensation->setObjectName("gcodeCompensation");
    m_gcodeCompensation->setToolTip(
        tr("Program the profile itself and let the controller offset it by the radius of "
           "tool 1, instead of the tool centre path"));
    form->addRow(m_gcodeCompensation);

    // Cam table
    page(m_pages, form);
    m_tablePoints = new QSpinBox(this);
    m_tablePoints->setObjectName("tablePoints");
    m_tablePoints->setRange(static_cast<int>(kMinCamTablePoints),
                            static_cast<int>(kMaxCamTablePoints));
    m_tablePoints->setValue(static_cast<int>(kDefaultCamTablePoints));
    m_tablePoints->setToolTip(tr("Equidistant master angles over one turn (360° not repeated)"));
    form->addRow(tr("&Points:"), m_tablePoints);
    m_tableDialect = new QComboBox(this);
    m_tableDialect->setObjectName("tableDialect");
    // The table lists a cam table's dialects in CamTableDialect's order.
    int dialect = 0;
    for (const ExportDialectKind& kind : exportFormat(ExportFormat::CamTable).dialects) {
        m_tableDialect->addItem(exportDialectTitle(kind), dialect++);
    }
    form->addRow(tr("&Dialect:"), m_tableDialect);
    connect(m_tableDialect, &QComboBox::currentIndexChanged, this, &ExportDialog::matchSuffix);
    m_tableSource = new QComboBox(this);
    m_tableSource->setObjectName("tableSource");
    m_tableSource->addItem(tr("Motion law (exact)"), static_cast<int>(CamTableSource::Law));
    m_tableSource->addItem(tr("Contour (follower on the arcs)"),
                           static_cast<int>(CamTableSource::Contour));
    m_tableSource->setToolTip(
        tr("The design's law is exact; the arc-fitted contour's lift is only C1 (its "
           "acceleration steps at every arc joint)"));
    // As camwright-cli's default: the law when there is a design; each source only where the
    // project has it.
    m_tableSource->setCurrentIndex(project.design ? 0 : 1);
    m_tableSource->setItemData(0, project.design ? QVariant() : QVariant(0), Qt::UserRole - 1);
    m_tableSource->setItemData(1, project.contour.empty() ? QVariant(0) : QVariant(),
                               Qt::UserRole - 1);
    form->addRow(tr("&Source:"), m_tableSource);
    m_tableReport = new QLabel(this);
    m_tableReport->setObjectName("tableReport");
    m_tableReport->setWordWrap(true);
    m_tableReport->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(m_tableReport);
    for (QComboBox* box : {m_tableDialect, m_tableSource}) {
        connect(box, &QComboBox::currentIndexChanged, this, &ExportDialog::updateTableReport);
    }
    connect(m_tablePoints, &QSpinBox::valueChanged, this, &ExportDialog::updateTableReport);

    // Plot picture
    page(m_pages, form);
    m_plot = new QComboBox(this);
    m_plot->setObjectName("plotKind");
    for (PlotKind kind : m_plots) m_plot->addItem(plotKindTitle(kind), static_cast<int>(kind));
    form->addRow(tr("&Plot:"), m_plot);
    m_picture = new QComboBox(this);
    m_picture->setObjectName("pictureFormat");
    // … and a picture's in PictureFormat's.
    int type = 0;
    for (const ExportDialectKind& kind : exportFormat(ExportFormat::Picture).dialects) {
        m_picture->addItem(exportDialectTitle(kind), type++);
    }
    form->addRow(tr("&Type:"), m_picture);
    m_width = new QSpinBox(this);
    m_width->setObjectName("pictureWidth");
    m_height = new QSpinBox(this);
    m_height->setObjectName("pictureHeight");
    for (QSpinBox* s : {m_width, m_height}) s->setRange(kMinPictureSide, kMaxPictureSide);
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QStringLiteral("×"), this));
    sizeRow->addWidget(m_height);
    // A row of a layout gets no buddy by itself: without one the label would show its "&".
    auto* sizeLabel = new QLabel(tr("Si&ze (px, pt):"), this);
    sizeLabel->setBuddy(m_width);
    form->addRow(sizeLabel, sizeRow);
    const auto pictureChanged = [this] {
        const QSize size =
            defaultPictureSize(static_cast<PictureFormat>(m_picture->currentData().toInt()));
        m_width->setValue(size.width());
        m_height->setValue(size.height());
        matchSuffix();
    };
    connect(m_picture, &QComboBox::currentIndexChanged, this, pictureChanged);
    connect(m_plot, &QComboBox::currentIndexChanged, this, &ExportDialog::matchSuffix);

    auto* fileRow = new QHBoxLayout;
    m_file = new QLineEdit(this);
    m_file->setObjectName("exportFile");
    auto* browse = new QPushButton(tr("&Browse…"), this);
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(browse);
    auto* fileForm = new QFormLayout;
    auto* fileLabel = new QLabel(tr("F&ile:"), this);
    fileLabel->setBuddy(m_file);
    fileForm->addRow(fileLabel, fileRow);
    layout->addLayout(fileForm);
    m_problem = new QLabel(this);
    m_problem->setObjectName("exportProblem");
    m_problem->setStyleSheet("color: #b00020;");
    m_problem->setWordWrap(true);
    m_problem->hide();
    layout->addWidget(m_problem);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);

    const QSettings settings;
    const QString lastFolder = settings.value("export/folder", QDir::homePath()).toString();
    const bool sameProject =
        !projectFile.isEmpty() && settings.value("export/project").toString() == projectFile;
    const QString folder =
        projectFile.isEmpty() || sameProject ? lastFolder : QFileInfo(projectFile).absolutePath();
    m_file->setText(QDir(folder).filePath(baseName));
    pictureChanged();
    restoreOptions();
    const int last = m_format->findData(settings.value("export/format", 1).toInt());
    m_format->setCurrentIndex(last >= 0 ? last : 1);
    formatChanged();
}

std::vector<QWidget*> ExportDialog::rememberedOptions() const {
    // The picture's type before its size: choosing a type resets the size to its default.
    // The tool radii and the feed too: a project with a machining section then gives its own
    // tool radius, and caps the feed at its limit (restoreOptions()).
    return {m_dxfTolerance,   m_dxfPolyline,       m_dxfSplines,
            m_dxfCentres,     m_dxfToolPath,       m_dxfToolRadius,
            m_svgTolerance,   m_gcodeToolRadius,   m_gcodeFeed,
            m_gcodeDepth,     m_gcodeStepDownOn,   m_gcodeStepDown,
            m_gcodeTolerance, m_gcodeCompensation, m_tablePoints,
            m_tableDialect,   m_picture,           m_width,
            m_height};
}

void ExportDialog::restoreOptions() {
    const QSettings settings;
    for (QWidget* w : rememberedOptions()) {
        const QVariant value = settings.value("export/options/" + w->objectName());
        if (!value.isValid()) continue;
        if (auto* box = qobject_cast<QCheckBox*>(w)) box->setChecked(value.toBool());
        // Out-of-range values from an edited settings file are clamped by the boxes.
        if (auto* spin = qobject_cast<QSpinBox*>(w)) spin->setValue(value.toInt());
        if (auto* number = qobject_cast<NumberSpinBox*>(w)) {
            const double v = value.toDouble();
            if (std::isfinite(v)) number->setValue(v);
        }
        if (auto* combo = qobject_cast<QComboBox*>(w)) {
            const int i = value.toInt();
            if (i >= 0 && i < combo->count()) combo->setCurrentIndex(i);
        }
    }
    // What the project's machining section says of the tool comes from the project (the feed
    // box's maximum already holds its feed limit).
    if (m_projectToolRadius) {
        m_dxfToolRadius->setValue(*m_projectToolRadius);
        m_gcodeToolRadius->setValue(*m_projectToolRadius);
    }
    if (m_grooveToolRadius) m_gcodeToolRadius->setValue(*m_grooveToolRadius);
}

ExportFormat ExportDialog::format() const {
    return static_cast<ExportFormat>(m_format->currentData().toInt());
}

void ExportDialog::setFormat(ExportFormat format) {
    m_format->setCurrentIndex(m_format->findData(static_cast<int>(format)));
}

void ExportDialog::setFileName(const QString& path) { m_file->setText(path); }

void ExportDialog::formatChanged() {
    m_pages->setCurrentIndex(m_format->currentIndex());
    matchSuffix();
    updateTableReport();
}

void ExportDialog::matchSuffix() {
    const QString suffix = exportSuffix(request());
    QString path = m_file->text();
    if (path.isEmpty()) return;
    const QFileInfo info(path);
    const QString stem =
        info.completeSuffix().isEmpty()
            ? info.fileName()
            : info.fileName().left(info.fileName().size() - info.suffix().size() - 1);
    // A plot's name is part of its file's name: switching plots renames the file. Only the
    // tail this dialog added goes again: a project called "…-contour" keeps its name.
    QString base = stem;
    if (!m_plotTail.isEmpty() && base.endsWith(m_plotTail)) base.chop(m_plotTail.size());
    m_plotTail.clear();
    if (format() == ExportFormat::Picture && m_plot->count() > 0) {
        m_plotTail = "-" + plotKindName(static_cast<PlotKind>(m_plot->currentData().toInt()));
        base += m_plotTail;
    }
    m_file->setText(info.dir().filePath(base + "." + suffix));
}

void ExportDialog::browse() {
    const ExportRequest r = request();
    const QString filter = exportFormatTitle(r.format) + " (*." + exportSuffix(r) + ")";
    const QString chosen = QFileDialog::getSaveFileName(this, tr("Export"), m_file->text(), filter);
    if (!chosen.isEmpty()) m_file->setText(chosen);
}

ExportRequest ExportDialog::request() const {
    ExportRequest r;
    r.format = format();
    r.path = m_file->text();
    r.csvPoints = static_cast<std::size_t>(m_csvPoints->value());
    r.csvGerman = m_csvGerman->isChecked();
    r.dxf.toleranceMm = m_dxfTolerance->value();
    r.dxf.polyline = m_dxfPolyline->isChecked();
    r.dxf.splineEntities = m_dxfSplines->isChecked();
    r.dxf.centres = m_dxfCentres->isChecked();
    if (m_dxfToolPath->isChecked()) r.dxf.toolRadiusMm = m_dxfToolRadius->value();
    r.svg.toleranceMm = m_svgTolerance->value();
    r.svg.title = m_title;
    r.gcode.toolRadiusMm = m_gcodeToolRadius->value();
    r.gcode.feedMmMin = m_gcodeFeed->value();
    r.gcode.depthMm = m_gcodeDepth->value();
    if (m_gcodeStepDownOn->isChecked()) r.gcode.stepDownMm = m_gcodeStepDown->value();
    r.gcode.toleranceMm = m_gcodeTolerance->value();
    r.gcode.compensation = m_gcodeCompensation->isChecked();
    r.gcodePlate = m_gcodePlate ? m_gcodePlate->currentIndex() + 1 : 1;
    r.gcode.projectName = m_title;
    r.camTable.points = static_cast<std::size_t>(m_tablePoints->value());
    r.camTable.dialect = static_cast<CamTableDialect>(m_tableDialect->currentData().toInt());
    r.camTableSource = static_cast<CamTableSource>(m_tableSource->currentData().toInt());
    r.camTable.name = m_title;
    if (m_plot->count() > 0) r.plot = static_cast<PlotKind>(m_plot->currentData().toInt());
    r.picture = static_cast<PictureFormat>(m_picture->currentData().toInt());
    r.pictureSize = QSize(m_width->value(), m_height->value());
    return r;
}

void ExportDialog::accept() {
    const QString path = m_file->text().trimmed();
    QString problem;
    const QFileInfo info(path);
    if (path.isEmpty()) {
        problem = tr("Name the file to write.");
    } else if (!info.dir().exists()) {
        problem =
            tr("The folder %1 does not exist.").arg(QDir::toNativeSeparators(info.absolutePath()));
    } else if (info.isDir()) {
        problem = tr("%1 is a folder; name a file in it.").arg(QDir::toNativeSeparators(path));
    } else if (format() == ExportFormat::Picture && m_plot->count() == 0) {
        problem = tr("No plot can be drawn yet.");
    }
    if (!problem.isEmpty()) {
        m_problem->setText(problem);
        m_problem->show();
        return;
    }
    QSettings settings;
    settings.setValue("export/folder", info.absolutePath());
    settings.setValue("export/project", m_projectFile);
    settings.setValue("export/format", static_cast<int>(format()));
    for (QWidget* w : rememberedOptions()) {
        const QString key = "export/options/" + w->objectName();
        if (auto* box = qobject_cast<QCheckBox*>(w)) settings.setValue(key, box->isChecked());
        if (auto* spin = qobject_cast<QSpinBox*>(w)) settings.setValue(key, spin->value());
        if (auto* number = qobject_cast<NumberSpinBox*>(w)) settings.setValue(key, number->value());
        if (auto* combo = qobject_cast<QComboBox*>(w))
            settings.setValue(key, combo->currentIndex());
    }
    QDialog::accept();
}

void ExportDialog::updateTableReport() {
    if (format() != ExportFormat::CamTable) return;
    // The GUI thread never computes: the report of the table as the fields say comes from a
    // worker; a newer request makes an older answer stale.
    const int request = ++m_tableReportRequest;
    const auto source = static_cast<CamTableSource>(m_tableSource->currentData().toInt());
    CamTableOptions options;
    options.points = static_cast<std::size_t>(m_tablePoints->value());
    options.dialect = static_cast<CamTableDialect>(m_tableDialect->currentData().toInt());
    options.follower = m_project.follower.value_or(FollowerSpec{});
    m_tableReport->setText(tr("Measuring the controller's interpolation…"));
    auto* watcher = new QFutureWatcher<Result<CamTableReport>>(this);
    connect(watcher, &QFutureWatcher<Result<CamTableReport>>::finished, this,
            [this, watcher, request, arm = options.follower.motion == FollowerMotion::Oscillating] {
                const Result<CamTableReport> answer = watcher->result();
                watcher->deleteLater();
                if (request != m_tableReportRequest) return;  // stale
                if (!answer.ok()) {
                    m_tableReport->setText(diagnosticsText(answer.errors(), 3));
                    return;
                }
                const CamTableReport& r = answer.value();
                const QString unit = arm ? QStringLiteral("°") : QStringLiteral(" mm");
                const auto number = [](double v) { return QString::number(v, 'g', 3); };
                const CamCharacteristics& c = r.characteristics;
                m_tableReport->setText(
                    tr("The controller's interpolation (%1) of these %2 points is off the "
                       "motion by at most %3%4 (at %5°), %6%4/° in velocity and %7%4/°² in "
                       "acceleration.\nVelocity %8 … %9%4/°, acceleration %10 … %11%4/°², "
                       "jerk %12 … %13%4/°³.")
                        .arg(QString::fromLatin1(r.interpolation))
                        .arg(r.points)
                        .arg(number(r.positionError), unit, number(r.positionErrorAtDeg),
                             number(r.velocityError), number(r.accelerationError),
                             number(c.velocityMin.value), number(c.velocityMax.value),
                             number(c.accelerationMin.value), number(c.accelerationMax.value))
                        .arg(number(c.jerkMin.value), number(c.jerkMax.value)));
            });
    watcher->setFuture(QtConcurrent::run([project = m_project, source, options] {
        runInTheBackground();
        auto motion = camTableMotion(project, source);
        if (!motion.ok()) return Result<CamTableReport>(motion.errors());
        return camTableReport(motion.value(), options);
    }));
}

}  // namespace cam
