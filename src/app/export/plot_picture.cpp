#include "export/plot_picture.h"

#include <qcustomplot.h>
#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QPageSize>
#include <QPdfWriter>
#include <QStringList>
#include <QSvgGenerator>

#include "export/export_formats.h"
#include "export/free_text.h"

namespace cam {
namespace {

/// Puts the plot into the picture's state for its lifetime and back afterwards: viewport at the
/// picture's size, a title row, an x label, the ranges the fit may change.
class PictureState {
public:
    PictureState(QCustomPlot& plot, QSize size, const PictureText& text) : m_plot(plot) {
        m_viewport = plot.viewport();
        for (QCPAxis* axis : plot.axisRect()->axes()) m_ranges.push_back({axis, axis->range()});
        m_xLabel = plot.xAxis->label();
        if (m_xLabel.isEmpty() && !text.xLabel.isEmpty()) plot.xAxis->setLabel(text.xLabel);
        // A plot of a stack may leave its numbers to the plot below: a picture stands alone.
        m_xTickLabels = plot.xAxis->tickLabels();
        plot.xAxis->setTickLabels(true);
        if (!text.title.isEmpty()) {
            plot.plotLayout()->insertRow(0);
            QFont font = plot.font();
            font.setPointSizeF(font.pointSizeF() * 1.25);
            font.setBold(true);
            m_title = new QCPTextElement(&plot, text.title, font);
            plot.plotLayout()->addElement(0, 0, m_title);
        }
        // The cursor and the joint markers are for working on screen.
        for (int i = 0; i < plot.itemCount(); ++i) {
            QCPAbstractItem* item = plot.item(i);
            if (item->property(kNotInPictures).toBool() && item->visible()) {
                item->setVisible(false);
                m_hidden.push_back(item);
            }
        }
        plot.setViewport(QRect(QPoint(0, 0), size));
        plot.plotLayout()->update(QCPLayoutElement::upPreparation);
        plot.plotLayout()->update(QCPLayoutElement::upMargins);
        plot.plotLayout()->update(QCPLayoutElement::upLayout);
    }
    ~PictureState() {
        for (QCPAbstractItem* item : m_hidden) item->setVisible(true);
        if (m_title) {
            m_plot.plotLayout()->remove(m_title);
            m_plot.plotLayout()->simplify();
        }
        m_plot.xAxis->setLabel(m_xLabel);
        m_plot.xAxis->setTickLabels(m_xTickLabels);
        for (const auto& [axis, range] : m_ranges) axis->setRange(range);
        m_plot.setViewport(m_viewport);
        m_plot.replot(QCustomPlot::rpQueuedReplot);
    }
    PictureState(const PictureState&) = delete;
    PictureState& operator=(const PictureState&) = delete;

private:
    QCustomPlot& m_plot;
    QRect m_viewport;
    std::vector<std::pair<QCPAxis*, QCPRange>> m_ranges;
    std::vector<QCPAbstractItem*> m_hidden;
    QString m_xLabel;
    bool m_xTickLabels = true;
    QCPTextElement* m_title = nullptr;
};

QString creator() { return QStringLiteral("Camwright " CAMWRIGHT_VERSION); }

/// QSvgGenerator's document with its <title> and <desc> replaced by `title` and `description`,
/// escaped for XML (export/free_text.h); empty when the generator wrote neither where expected.
QByteArray withSvgTitle(const QByteArray& svg, const QString& title, const QString& description) {
    const qsizetype titleAt = svg.indexOf("<title>");
    const qsizetype descEnd = svg.indexOf("</desc>", titleAt);
    if (titleAt < 0 || descEnd < 0) return {};
    const QByteArray ours =
        "<title>" + QByteArray::fromStdString(xmlText(title.toStdString())) + "</title>\n<desc>" +
        QByteArray::fromStdString(xmlText(description.toStdString())) + "</desc>";
    return svg.left(titleAt) + ours + svg.mid(descEnd + qsizetype(sizeof "</desc>") - 1);
}

}  // namespace

QString plotKindName(PlotKind kind) {
    switch (kind) {
        case PlotKind::Contour:
            return "contour";
        case PlotKind::Velocity:
            return "velocity";
        case PlotKind::Acceleration:
            return "acceleration";
        case PlotKind::Jerk:
            return "jerk";
        case PlotKind::Feed:
            return "feed";
        case PlotKind::AxisAcceleration:
            return "axis-acceleration";
        case PlotKind::PressureAngle:
            return "pressure-angle";
        case PlotKind::Lift:
            return "lift";
        case PlotKind::Motion:
            return "motion";
    }
    return {};
}

std::optional<PlotKind> plotKindNamed(const QString& name) {
    for (PlotKind kind : kPlotKinds) {
        if (plotKindName(kind) == name) return kind;
    }
    return std::nullopt;
}

QString plotKindNames() {
    QStringList names;
    for (PlotKind kind : kPlotKinds) names << plotKindName(kind);
    return names.join(", ");
}

QString plotKindTitle(PlotKind kind) {
    switch (kind) {
        case PlotKind::Contour:
            return QCoreApplication::translate("PlotKind", "Contour");
        case PlotKind::Velocity:
            return QCoreApplication::translate("PlotKind", "Velocity");
        case PlotKind::Acceleration:
            return QCoreApplication::translate("PlotKind", "Acceleration");
        case PlotKind::Jerk:
            return QCoreApplication::translate("PlotKind", "Jerk");
        case PlotKind::Feed:
            return QCoreApplication::translate("PlotKind", "Feed along the path");
        case PlotKind::AxisAcceleration:
            return QCoreApplication::translate("PlotKind", "Axis accelerations");
        case PlotKind::PressureAngle:
            return QCoreApplication::translate("PlotKind", "Pressure angle");
        case PlotKind::Lift:
            return QCoreApplication::translate("PlotKind", "Lift");
        case PlotKind::Motion:
            return QCoreApplication::translate("PlotKind", "Lift, velocity, acceleration, jerk");
    }
    return {};
}

std::optional<PictureFormat> pictureFormatNamed(const QString& name) {
    // The core's table lists a picture's dialects in PictureFormat's order.
    const auto dialects = exportFormat(ExportFormatId::Picture).dialects;
    for (std::size_t k = 0; k < dialects.size(); ++k) {
        if (name.toLower().toStdString() == dialects[k].name) return static_cast<PictureFormat>(k);
    }
    return std::nullopt;
}

std::optional<PictureFormat> pictureFormatOfFile(const QString& fileName) {
    return pictureFormatNamed(QFileInfo(fileName).suffix());
}

QString pictureSuffix(PictureFormat format) {
    const std::string_view suffix =
        exportFormat(ExportFormatId::Picture).dialects[static_cast<std::size_t>(format)].suffix;
    return QString::fromUtf8(suffix.data(), static_cast<qsizetype>(suffix.size()));
}

QSize defaultPictureSize(PictureFormat format) {
    return format == PictureFormat::Png ? QSize(1200, 800) : QSize(842, 595);
}

namespace {

/// Runs `paint` on a painter over a picture of `size` in `format` and returns its bytes (empty
/// when the painter could not start). PNG: a white pixmap; PDF: one page of exactly that size
/// in points; SVG: that size in user units, its title escaped.
QByteArray paintPicture(PictureFormat format, QSize size, const QString& title,
                        const std::function<void(QCPPainter&)>& paint) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    const int w = size.width(), h = size.height();
    switch (format) {
        case PictureFormat::Png: {
            QPixmap pixmap(w, h);
            pixmap.fill(Qt::white);
            {
                QCPPainter painter(&pixmap);
                if (!painter.isActive()) return {};
                painter.setMode(QCPPainter::pmNoCaching);
                paint(painter);
            }
            if (!pixmap.save(&buffer, "PNG")) return {};
            break;
        }
        case PictureFormat::Pdf: {
            QPdfWriter writer(&buffer);
            writer.setTitle(title);
            writer.setCreator(creator());
            writer.setResolution(72);  // one device unit = one point: the plot's pixels
            writer.setPageSize(
                QPageSize(QSizeF(w, h), QPageSize::Point, QString(), QPageSize::ExactMatch));
            writer.setPageMargins(QMarginsF(0, 0, 0, 0));
            QCPPainter painter;
            if (!painter.begin(&writer)) return {};
            painter.setMode(QCPPainter::pmVectorized);
            painter.setMode(QCPPainter::pmNoCaching);
            paint(painter);
            painter.end();
            break;
        }
        case PictureFormat::Svg: {
            QSvgGenerator generator;
            generator.setOutputDevice(&buffer);
            generator.setSize(size);
            generator.setViewBox(QRect(QPoint(0, 0), size));
            // QSvgGenerator writes its title and description as they are, unescaped: "&" in a
            // file name made an SVG no XML reader accepts. Ours go in escaped afterwards.
            generator.setDescription(QStringLiteral("Camwright"));
            QCPPainter painter;
            if (!painter.begin(&generator)) return {};
            painter.setMode(QCPPainter::pmVectorized);
            painter.setMode(QCPPainter::pmNoCaching);
            paint(painter);
            painter.end();
            buffer.close();
            return withSvgTitle(bytes, title, creator());
        }
    }
    return bytes;
}

}  // namespace

QByteArray renderPlotPicture(QCustomPlot& plot, PictureFormat format, QSize size,
                             const PictureText& given, const std::function<void()>& fit) {
    // The title is free text (a project or file name): one line, in every format.
    PictureText text = given;
    text.title = QString::fromStdString(oneLine(given.title.toStdString()));
    const PictureState state(plot, size, text);
    if (fit) fit();
    if (format == PictureFormat::Png) {
        QByteArray bytes;
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        const QPixmap pixmap = plot.toPixmap(size.width(), size.height(), 1.0);
        if (pixmap.isNull() || !pixmap.save(&buffer, "PNG")) return {};
        return bytes;
    }
    return paintPicture(format, size, text.title, [&](QCPPainter& painter) {
        plot.toPainter(&painter, size.width(), size.height());
    });
}

QByteArray renderPlotSheet(const std::vector<QCustomPlot*>& plots, const std::vector<int>& stretch,
                           PictureFormat format, QSize size, const PictureText& given) {
    if (plots.empty() || stretch.size() != plots.size()) return {};
    const QString title = QString::fromStdString(oneLine(given.title.toStdString()));
    int total = 0;
    for (int s : stretch) total += s;
    // Each plot's band of the sheet, top to bottom; the last takes what rounding leaves.
    std::vector<QRect> bands;
    int top = 0;
    for (std::size_t i = 0; i < plots.size(); ++i) {
        const int h = i + 1 == plots.size() ? size.height() - top
                                            : size.height() * stretch[i] / std::max(total, 1);
        bands.emplace_back(0, top, size.width(), h);
        top += h;
    }
    std::vector<std::unique_ptr<PictureState>> states;
    for (std::size_t i = 0; i < plots.size(); ++i) {
        PictureText text;
        text.title = i == 0 ? title : QString();
        text.xLabel = given.xLabel;
        states.push_back(std::make_unique<PictureState>(*plots[i], bands[i].size(), text));
    }
    // Laid out once more now that all are at their picture's size: plots that share a margin
    // group (the kinematics plots) line their axes up as on screen.
    for (QCustomPlot* plot : plots) {
        plot->plotLayout()->update(QCPLayoutElement::upMargins);
        plot->plotLayout()->update(QCPLayoutElement::upLayout);
    }
    QByteArray bytes = paintPicture(format, size, title, [&](QCPPainter& painter) {
        for (std::size_t i = 0; i < plots.size(); ++i) {
            painter.save();
            painter.translate(bands[i].topLeft());
            plots[i]->toPainter(&painter, bands[i].width(), bands[i].height());
            painter.restore();
        }
    });
    return bytes;
}

}  // namespace cam
