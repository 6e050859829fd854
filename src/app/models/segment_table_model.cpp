#include "models/segment_table_model.h"

#include <QColor>
#include <cmath>
#include <utility>
#include <vector>

#include "common/angles.h"
#include "contour/change_type.h"
#include "messages/diagnostic_text.h"
#include "project/validate.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

quint64 key(int row, int column) { return (static_cast<quint64>(row) << 8) | column; }

const SegmentSpec& segmentOf(const ProjectDocument* d, int row) {
    return d->project().contour.at(static_cast<std::size_t>(row));
}

}  // namespace

SegmentTableModel::SegmentTableModel(ProjectDocument* document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document) {
    rebuildProblems();
    // Every structural change is bracketed: begin… while the document still has the old
    // contour, end… once it has the new one (a view may read any row in between).
    connect(document, &ProjectDocument::segmentChanged, this,
            [this](int row) { emit dataChanged(index(row, 0), index(row, ColumnCount - 1)); });
    connect(document, &ProjectDocument::segmentAboutToBeInserted, this,
            [this](int row) { beginInsertRows({}, row, row); });
    connect(document, &ProjectDocument::segmentInserted, this, [this] { endInsertRows(); });
    connect(document, &ProjectDocument::segmentAboutToBeRemoved, this,
            [this](int row) { beginRemoveRows({}, row, row); });
    connect(document, &ProjectDocument::segmentRemoved, this, [this] { endRemoveRows(); });
    connect(document, &ProjectDocument::segmentAboutToBeMoved, this, [this](int from, int to) {
        beginMoveRows({}, from, from, {}, to > from ? to + 1 : to);
    });
    connect(document, &ProjectDocument::segmentMoved, this, [this] { endMoveRows(); });
    connect(document, &ProjectDocument::contourAboutToBeReset, this, [this] { beginResetModel(); });
    connect(document, &ProjectDocument::contourReset, this, [this] { endResetModel(); });
    connect(document, &ProjectDocument::changed, this, [this] {
        // Only the rows whose problems changed are repainted: a refresh of the whole table
        // repainted every cell on every edit (2.5 ms for the six-lobe cam's seven rows). A
        // segment's own cells change with segmentChanged and the row signals.
        const QHash<quint64, QStringList> before = std::exchange(m_problems, {});
        rebuildProblems();
        std::vector<bool> changedRows(static_cast<std::size_t>(rowCount()), false);
        const auto differ = [&](const QHash<quint64, QStringList>& a,
                                const QHash<quint64, QStringList>& b) {
            for (auto it = a.cbegin(); it != a.cend(); ++it) {
                const auto row = static_cast<std::size_t>(it.key() >> 8);
                if (row < changedRows.size() && b.value(it.key()) != it.value()) {
                    changedRows[row] = true;
                }
            }
        };
        differ(before, m_problems);
        differ(m_problems, before);
        for (int first = 0; first < rowCount(); ++first) {
            if (!changedRows[static_cast<std::size_t>(first)]) continue;
            int last = first;
            while (last + 1 < rowCount() && changedRows[static_cast<std::size_t>(last + 1)]) ++last;
            emit dataChanged(index(first, 0), index(last, ColumnCount - 1),
                             {Qt::BackgroundRole, Qt::ToolTipRole});
            first = last;
        }
    });
}

int SegmentTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_document->project().contour.size());
}

int SegmentTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

bool SegmentTableModel::isApplicable(int row, int column) const {
    const SegmentType type = segmentOf(m_document, row).type();
    switch (column) {
        case CenterX:
        case CenterY:
        case Radius:
        case Branch:
            return type == SegmentType::Arc;
        case FromX:
        case FromY:
        case ToX:
        case ToY:
            return type == SegmentType::Line;
        default:
            return true;
    }
}

QVariant SegmentTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const SegmentSpec& s = segmentOf(m_document, index.row());
    const int c = index.column();
    if (role == ChoicesRole) {
        if (c == Type) return QStringList{tr("Arc"), tr("Line"), tr("Bézier"), tr("Hermite")};
        if (c == Branch) return QStringList{tr("outer"), tr("inner")};
        return {};
    }
    if (role == Qt::ToolTipRole) {
        const QStringList problems = problemsAt(index.row(), c);
        if (!problems.isEmpty()) return problems.join('\n');
        if (c == Branch)
            return tr(
                "outer: far intersection of the ray with the circle; "
                "inner: near intersection");
        if (c == PhiStart || c == PhiEnd) {
            return s.type() != SegmentType::Arc ? tr("This segment's window follows its end points")
                                                : tr("Polar window of this segment, degrees");
        }
        if (c == Type && isSpline(s.type())) {
            const bool bezier = s.type() == SegmentType::Bezier;
            const QStringList names =
                bezier ? QStringList{"P0", "P1", "P2", "P3"} : QStringList{"p0", "t0", "p3", "t1"};
            const CubicBezier b = bezierOf(s);
            const HermiteCurve h = HermiteCurve::of(b);
            const Eigen::Vector2d points[4] = {b.p[0], bezier ? b.p[1] : h.t0,
                                               bezier ? b.p[2] : h.p3, bezier ? b.p[3] : h.t1};
            QStringList lines{
                tr("Drag the handles in the contour view to shape the curve, or type its "
                   "control points in the Control Points tab.")};
            for (int i = 0; i < 4; ++i) {
                lines << QStringLiteral("%1 = %2").arg(names[i],
                                                       formatPoint(points[i].x(), points[i].y()));
            }
            return lines.join('\n');
        }
        return {};
    }
    if (role == Qt::BackgroundRole) {
        if (!problemsAt(index.row(), c).isEmpty()) return QColor(255, 205, 205);
        if (!isApplicable(index.row(), c)) return QColor(238, 238, 238);
        return {};
    }
    if (role == Qt::TextAlignmentRole) {
        return c == Type || c == Branch ? QVariant() : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    }
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    if (!isApplicable(index.row(), c)) return {};
    const bool edit = role == Qt::EditRole;
    auto number = [&](double v) -> QVariant {
        return edit ? QVariant(v) : QVariant(formatQuantityValue(DisplayQuantity::Input, v));
    };
    const Arc* arc = s.as<Arc>();
    const Line* line = s.as<Line>();
    switch (c) {
        case Type: {
            const QStringList names{tr("Arc"), tr("Line"), tr("Bézier"), tr("Hermite")};
            const int t = static_cast<int>(s.type());
            return edit ? QVariant(t) : QVariant(names[t]);
        }
        case CenterX:
            return number(arc->center.x());
        case CenterY:
            return number(arc->center.y());
        case Radius:
            return number(arc->radius);
        case Branch:
            return edit ? QVariant(arc->branch == Branch::Outer ? 0 : 1)
                        : QVariant(arc->branch == Branch::Outer ? tr("outer") : tr("inner"));
        case FromX:
            return number(line->from.x());
        case FromY:
            return number(line->from.y());
        case ToX:
            return number(line->to.x());
        case ToY:
            return number(line->to.y());
        case PhiStart:
            return number(s.phiStartDeg);
        case PhiEnd:
            return number(s.phiEndDeg);
        default:
            return {};
    }
}

QVariant SegmentTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Vertical) {
        return role == Qt::DisplayRole ? QVariant(section) : QVariant();
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
            case Type:
                return tr(
                    "What the segment is: an arc of a circle, a line, or a cubic spline "
                    "piece (Bézier or Hermite)");
            case Branch:
                return tr(
                    "Which of the two points where the follower's ray meets the arc's "
                    "circle the contour takes: outer, the one farther from the rotation "
                    "centre (a lobe); inner, the nearer one (a notch, a concave flank)");
            case CenterX:
            case CenterY:
                return tr("Centre of the arc's circle, mm");
            case Radius:
                return tr("Radius of the arc, mm");
            case FromX:
            case FromY:
            case ToX:
            case ToY:
                return tr("End points of the line, mm (counter-clockwise around the centre)");
            case PhiStart:
            case PhiEnd:
                return tr("Polar window [φ start, φ end), degrees");
            default:
                return {};
        }
    }
    if (role != Qt::DisplayRole) return {};
    const QString title = columnTitle(section);
    return title.isEmpty() ? QVariant() : QVariant(title);
}

QString SegmentTableModel::columnTitle(int column) { return segmentColumnTitle(column); }

Qt::ItemFlags SegmentTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    // A field the segment does not have (an arc's end points, a line's centre) is no cell to
    // go to: Tab passes over it, a click does not make it current (issue 31: typing there
    // was lost).
    if (!isApplicable(index.row(), index.column())) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    const bool lineWindow = segmentOf(m_document, index.row()).type() != SegmentType::Arc &&
                            (index.column() == PhiStart || index.column() == PhiEnd);
    if (!lineWindow) f |= Qt::ItemIsEditable;
    return f;
}

// Columns are listed in the order of the fields they edit, so a column is its field.
static_assert(static_cast<int>(EditedField::Type) == SegmentTableModel::Type &&
              static_cast<int>(EditedField::Radius) == SegmentTableModel::Radius &&
              static_cast<int>(EditedField::ToY) == SegmentTableModel::ToY &&
              static_cast<int>(EditedField::PhiEnd) == SegmentTableModel::PhiEnd);

EditedField SegmentTableModel::fieldOf(int column) { return static_cast<EditedField>(column); }

bool SegmentTableModel::applyValue(SegmentSpec& s, int column, const QVariant& value) {
    bool ok = false;
    if (column == Type) {
        const int choice = value.toInt(&ok);
        if (!ok || choice < 0 || choice > 3) return false;
        s = withType(s, static_cast<SegmentType>(choice));
        return true;
    }
    if (column == Branch) {
        const int choice = value.toInt(&ok);
        Arc* arc = s.as<Arc>();
        if (!ok || !arc || choice < 0 || choice > 1) return false;
        arc->branch = choice == 0 ? Branch::Outer : Branch::Inner;
        return true;
    }
    const double v = value.toDouble(&ok);
    if (!ok || !std::isfinite(v)) return false;
    if (column == PhiStart || column == PhiEnd) {
        (column == PhiStart ? s.phiStartDeg : s.phiEndDeg) = v;
        return true;
    }
    if (Arc* arc = s.as<Arc>()) {
        switch (column) {
            case CenterX:
                arc->center.x() = v;
                return true;
            case CenterY:
                arc->center.y() = v;
                return true;
            case Radius:
                arc->radius = v;
                return true;
            default:
                return false;
        }
    }
    Line* line = s.as<Line>();
    if (!line || column < FromX || column > ToY) return false;
    Eigen::Vector2d& point = column <= FromY ? line->from : line->to;
    point[(column - FromX) % 2] = v;
    // A line's window follows its end points.
    std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, s.phiStartDeg);
    return true;
}

bool SegmentTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || !(flags(index) & Qt::ItemIsEditable)) return false;
    QVariant v = value;
    int gesture = 0;
    if (role == MergingEditRole) {
        const QVariantList pair = value.toList();
        if (pair.size() != 2) return false;
        v = pair[0];
        gesture = pair[1].toInt();
    } else if (role != Qt::EditRole) {
        return false;
    }
    SegmentSpec s = segmentOf(m_document, index.row());
    if (!applyValue(s, index.column(), v)) return false;
    if (s == segmentOf(m_document, index.row())) return true;  // nothing changed: no undo step
    const QString text =
        tr("Edit %1 of segment %2")
            .arg(headerData(index.column(), Qt::Horizontal, Qt::DisplayRole).toString(),
                 QString::number(index.row()));
    m_document->undoStack()->push(
        new EditSegment(m_document, index.row(), s, fieldOf(index.column()), text, gesture));
    return true;
}

QStringList SegmentTableModel::problemsAt(int row, int column) const {
    return m_problems.value(key(row, column));
}

QList<int> SegmentTableModel::columnsOf(const SegmentPlace& place) {
    auto pair = [&](int x, int y) {
        return place.axis == 0 ? QList<int>{x} : place.axis == 1 ? QList<int>{y} : QList<int>{x, y};
    };
    switch (place.part) {
        case SegmentPart::Whole: {
            QList<int> all;
            for (int c = 0; c < ColumnCount; ++c) all << c;
            return all;
        }
        case SegmentPart::Type:
        case SegmentPart::Points:
        case SegmentPart::P0:
        case SegmentPart::T0:
        case SegmentPart::P3:
        case SegmentPart::T1:
            return {Type};
        case SegmentPart::Center:
            return pair(CenterX, CenterY);
        case SegmentPart::Radius:
            return {Radius};
        case SegmentPart::Branch:
            return {Branch};
        case SegmentPart::From:
            return pair(FromX, FromY);
        case SegmentPart::To:
            return pair(ToX, ToY);
        case SegmentPart::PhiStart:
            return {PhiStart};
        case SegmentPart::PhiEnd:
            return {PhiEnd};
    }
    return {};
}

void SegmentTableModel::rebuildProblems() {
    m_problems.clear();
    const int rows = rowCount();
    for (const Diagnostic& d : m_document->diagnostics()) {
        const QString message = diagnosticText(d);
        for (const SegmentPlace& place : d.segmentFields()) {
            if (place.segment >= static_cast<std::size_t>(rows)) continue;
            const int row = static_cast<int>(place.segment);
            for (int c : columnsOf(place)) {
                QStringList& list = m_problems[key(row, c)];
                if (!list.contains(message)) list << message;
            }
        }
    }
}

}  // namespace cam
