#include "models/arc_table_model.h"

#include <QColor>
#include <QLocale>
#include <QRegularExpression>
#include <cmath>

#include "common/angles.h"
#include "geometry/line.h"
#include "project/validate.h"

namespace cam {
namespace {

quint64 key(int row, int column) { return (static_cast<quint64>(row) << 8) | column; }

const SegmentSpec& segmentOf(const ProjectDocument* d, int row) {
    return d->project().contour.at(static_cast<std::size_t>(row));
}

}  // namespace

ArcTableModel::ArcTableModel(ProjectDocument* document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document) {
    m_rows = static_cast<int>(document->project().contour.size());
    rebuildProblems();
    connect(document, &ProjectDocument::segmentChanged, this,
            [this](int row) { emit dataChanged(index(row, 0), index(row, ColumnCount - 1)); });
    connect(document, &ProjectDocument::segmentInserted, this, [this](int row) {
        beginInsertRows({}, row, row);
        ++m_rows;
        endInsertRows();
    });
    connect(document, &ProjectDocument::segmentRemoved, this, [this](int row) {
        beginRemoveRows({}, row, row);
        --m_rows;
        endRemoveRows();
    });
    connect(document, &ProjectDocument::segmentMoved, this, [this](int from, int to) {
        beginMoveRows({}, from, from, {}, to > from ? to + 1 : to);
        endMoveRows();
    });
    connect(document, &ProjectDocument::contourReset, this, [this] {
        beginResetModel();
        m_rows = static_cast<int>(m_document->project().contour.size());
        endResetModel();
    });
    connect(document, &ProjectDocument::changed, this, [this] {
        rebuildProblems();
        if (m_rows > 0) {
            emit dataChanged(index(0, 0), index(m_rows - 1, ColumnCount - 1),
                             {Qt::BackgroundRole, Qt::ToolTipRole, Qt::DisplayRole});
        }
    });
}

int ArcTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : m_rows;
}

int ArcTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

bool ArcTableModel::isApplicable(int row, int column) const {
    const SegmentType type = segmentOf(m_document, row).type;
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

QVariant ArcTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= m_rows) return {};
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
            return s.type != SegmentType::Arc ? tr("This segment's window follows its end points")
                                              : tr("Polar window of this segment, degrees");
        }
        if (c == Type && isSpline(s.type)) {
            const QStringList names = s.type == SegmentType::Bezier
                                          ? QStringList{"P0", "P1", "P2", "P3"}
                                          : QStringList{"p0", "t0", "p3", "t1"};
            QStringList lines{tr("Drag the handles in the contour view to shape the curve.")};
            for (int i = 0; i < 4; ++i) {
                lines << QStringLiteral("%1 = (%2, %3)")
                             .arg(names[i], QLocale().toString(s.controls[i].x(), 'g', 8),
                                  QLocale().toString(s.controls[i].y(), 'g', 8));
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
        return edit ? QVariant(v) : QVariant(QLocale().toString(v, 'g', 10));
    };
    switch (c) {
        case Type: {
            const QStringList names{tr("Arc"), tr("Line"), tr("Bézier"), tr("Hermite")};
            const int t = static_cast<int>(s.type);
            return edit ? QVariant(t) : QVariant(names[t]);
        }
        case CenterX:
            return number(s.center.x());
        case CenterY:
            return number(s.center.y());
        case Radius:
            return number(s.radius);
        case Branch:
            return edit ? QVariant(s.branch == Branch::Outer ? 0 : 1)
                        : QVariant(s.branch == Branch::Outer ? tr("outer") : tr("inner"));
        case FromX:
            return number(s.from.x());
        case FromY:
            return number(s.from.y());
        case ToX:
            return number(s.to.x());
        case ToY:
            return number(s.to.y());
        case PhiStart:
            return number(s.phiStartDeg);
        case PhiEnd:
            return number(s.phiEndDeg);
        default:
            return {};
    }
}

QVariant ArcTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Vertical) {
        return role == Qt::DisplayRole ? QVariant(section) : QVariant();
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
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
    switch (section) {
        case Type:
            return tr("Type");
        case CenterX:
            return tr("Centre x [mm]");
        case CenterY:
            return tr("Centre y [mm]");
        case Radius:
            return tr("Radius [mm]");
        case Branch:
            return tr("Branch");
        case FromX:
            return tr("From x [mm]");
        case FromY:
            return tr("From y [mm]");
        case ToX:
            return tr("To x [mm]");
        case ToY:
            return tr("To y [mm]");
        case PhiStart:
            return tr("φ start [°]");
        case PhiEnd:
            return tr("φ end [°]");
        default:
            return {};
    }
}

Qt::ItemFlags ArcTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    const bool lineWindow = segmentOf(m_document, index.row()).type != SegmentType::Arc &&
                            (index.column() == PhiStart || index.column() == PhiEnd);
    if (isApplicable(index.row(), index.column()) && !lineWindow) f |= Qt::ItemIsEditable;
    return f;
}

// Columns are listed in the order of the fields they edit, so a column is its field.
static_assert(static_cast<int>(SegmentField::Type) == ArcTableModel::Type &&
              static_cast<int>(SegmentField::Radius) == ArcTableModel::Radius &&
              static_cast<int>(SegmentField::ToY) == ArcTableModel::ToY &&
              static_cast<int>(SegmentField::PhiEnd) == ArcTableModel::PhiEnd);

SegmentField ArcTableModel::fieldOf(int column) { return static_cast<SegmentField>(column); }

bool ArcTableModel::applyValue(SegmentSpec& s, int column, const QVariant& value) {
    bool ok = false;
    if (column == Type || column == Branch) {
        const int choice = value.toInt(&ok);
        if (column == Branch) {
            if (!ok || choice < 0 || choice > 1) return false;
            s.branch = choice == 0 ? Branch::Outer : Branch::Inner;
            return true;
        }
        if (!ok || choice < 0 || choice > 3) return false;
        return changeType(s, static_cast<SegmentType>(choice));
    }
    const double v = value.toDouble(&ok);
    if (!ok || !std::isfinite(v)) return false;
    switch (column) {
        case CenterX:
            s.center.x() = v;
            break;
        case CenterY:
            s.center.y() = v;
            break;
        case Radius:
            s.radius = v;
            break;
        case FromX:
            s.from.x() = v;
            break;
        case FromY:
            s.from.y() = v;
            break;
        case ToX:
            s.to.x() = v;
            break;
        case ToY:
            s.to.y() = v;
            break;
        case PhiStart:
            s.phiStartDeg = v;
            break;
        case PhiEnd:
            s.phiEndDeg = v;
            break;
        default:
            return false;
    }
    if (s.type == SegmentType::Line && column >= FromX && column <= ToY) {
        std::tie(s.phiStartDeg, s.phiEndDeg) = lineWindowDeg(s, s.phiStartDeg);
    }
    return true;
}

bool ArcTableModel::changeType(SegmentSpec& s, SegmentType type) {
    if (type == s.type) return true;
    // The curve's points at its window ends: the new segment joins the same two points, so the
    // contour stays closed.
    Eigen::Vector2d ends[2] = {pointOnSegment(s, s.phiStartDeg), pointOnSegment(s, s.phiEndDeg)};
    for (int e = 0; e < 2; ++e) {
        if (!ends[e].allFinite()) {  // an invalid row: keep at least a direction
            const double phi = degToRad(e == 0 ? s.phiStartDeg : s.phiEndDeg);
            ends[e] = {std::cos(phi), std::sin(phi)};
        }
    }
    if (type == SegmentType::Line) {
        s.from = ends[0];
        s.to = ends[1];
    } else if (isSpline(type)) {
        CubicBezier b;
        if (isSpline(s.type)) {
            b = bezierOf(s);  // Bézier ↔ Hermite: the same curve, exactly
        } else if (s.type == SegmentType::Arc) {
            // κ-approximation of the arc between the same end points (math.md §4).
            const Eigen::Vector2d a = ends[0] - s.center, c = ends[1] - s.center;
            const double sweep = std::atan2(a.x() * c.y() - a.y() * c.x(), a.dot(c));
            const double kappa = 4.0 / 3.0 * std::tan(sweep / 4.0);
            b.p = {ends[0], ends[0] + kappa * Eigen::Vector2d(-a.y(), a.x()),
                   ends[1] - kappa * Eigen::Vector2d(-c.y(), c.x()), ends[1]};
        } else {
            const Eigen::Vector2d d = (ends[1] - ends[0]) / 3.0;  // the same straight line
            b.p = {ends[0], ends[0] + d, ends[1] - d, ends[1]};
        }
        if (type == SegmentType::Bezier) {
            s.controls = b.p;
        } else {
            const auto t = b.hermiteTangents();
            s.controls = {b.p[0], t[0], b.p[3], t[1]};
        }
    }
    s.type = type;
    return true;
}

bool ArcTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
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

QStringList ArcTableModel::problemsAt(int row, int column) const {
    return m_problems.value(key(row, column));
}

void ArcTableModel::rebuildProblems() {
    m_problems.clear();
    static const QRegularExpression pattern(
        R"(^contour\[(\d+)\](?:/contour\[(\d+)\])?(?:\.([a-z_]+))?(?:\[(\d)\])?$)");
    for (const Diagnostic& d : m_document->diagnostics()) {
        const auto m = pattern.match(QString::fromStdString(d.location));
        if (!m.hasMatch()) continue;
        const QString message = QString::fromStdString(d.message);
        const int row = m.captured(1).toInt();
        if (!m.captured(2).isEmpty()) {  // a joint or window boundary between two rows
            m_problems[key(row, PhiEnd)] << message;
            m_problems[key(m.captured(2).toInt(), PhiStart)] << message;
            continue;
        }
        const QString field = m.captured(3);
        const int axis = m.captured(4).isEmpty() ? -1 : m.captured(4).toInt();
        QList<int> columns;
        if (field.isEmpty()) {
            for (int c = 0; c < ColumnCount; ++c) columns << c;
        } else if (field == "center") {
            columns = axis == 1   ? QList<int>{CenterY}
                      : axis == 0 ? QList<int>{CenterX}
                                  : QList<int>{CenterX, CenterY};
        } else if (field == "from") {
            columns = axis == 1   ? QList<int>{FromY}
                      : axis == 0 ? QList<int>{FromX}
                                  : QList<int>{FromX, FromY};
        } else if (field == "to") {
            columns = axis == 1   ? QList<int>{ToY}
                      : axis == 0 ? QList<int>{ToX}
                                  : QList<int>{ToX, ToY};
        } else if (field == "radius") {
            columns = {Radius};
        } else if (field == "branch") {
            columns = {Branch};
        } else if (field == "type") {
            columns = {Type};
        } else if (field == "phi_start") {
            columns = {PhiStart};
        } else if (field == "phi_end") {
            columns = {PhiEnd};
        }
        for (int c : columns) m_problems[key(row, c)] << message;
    }
}

}  // namespace cam
