#include "models/design_table_model.h"

#include <QColor>
#include <QCoreApplication>

#include "document/commands.h"
#include "messages/diagnostic_text.h"
#include "messages/field_titles.h"
#include "models/delegates.h"
#include "models/segment_table_model.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

quint64 cellKey(int row, int column) {
    return (static_cast<quint64>(row) << 8) | static_cast<quint64>(column);
}

bool isPoly5Column(int c) {
    return c == DesignTableModel::V0 || c == DesignTableModel::A0 || c == DesignTableModel::V1 ||
           c == DesignTableModel::A1;
}

/// The column a diagnostic's design field is in; -1 for the whole row.
int columnOfPart(DesignPart part) {
    switch (part) {
        case DesignPart::Whole:
            return -1;
        case DesignPart::Law:
            return DesignTableModel::Law;
        case DesignPart::ToDeg:
            return DesignTableModel::ToDeg;
        case DesignPart::Lift:
            return DesignTableModel::Lift;
        case DesignPart::V0:
            return DesignTableModel::V0;
        case DesignPart::A0:
            return DesignTableModel::A0;
        case DesignPart::V1:
            return DesignTableModel::V1;
        case DesignPart::A1:
            return DesignTableModel::A1;
    }
    return -1;
}

}  // namespace

DesignTableModel::DesignTableModel(ProjectDocument* document, QObject* parent)
    : QAbstractTableModel(parent), m_document(document) {
    connect(document, &ProjectDocument::designChanged, this, [this] {
        const auto& design = m_document->project().design;
        const std::vector<DesignSegmentSpec> now =
            design ? design->segments : std::vector<DesignSegmentSpec>{};
        if (now.size() == m_shown.size() && !now.empty()) {
            // An edit of segments (a law, a value): those rows change, the table stays put —
            // the current cell, an open editor, the columns' widths (issue 31: a reset fitted
            // the columns anew after each law change, under the mouse).
            int first = -1, last = -1;
            for (std::size_t k = 0; k < now.size(); ++k) {
                if (now[k] == m_shown[k]) continue;
                if (first < 0) first = static_cast<int>(k);
                last = static_cast<int>(k);
            }
            m_shown = now;
            rebuild();
            if (first >= 0) {
                // The next row starts where this one ends.
                last = std::min(last + 1, static_cast<int>(now.size()) - 1);
                emit dataChanged(index(first, 0), index(last, ColumnCount - 1));
            }
            return;
        }
        beginResetModel();
        m_shown = now;
        rebuild();
        endResetModel();
    });
    // Lifts are mm on a translating follower and degrees on an arm.
    connect(document, &ProjectDocument::followerChanged, this, [this] {
        emit headerDataChanged(Qt::Horizontal, Lift, A1);
        if (rowCount() > 0) emit dataChanged(index(0, Lift), index(rowCount() - 1, A1));
    });
    // Problems can come and go with any change (the follower's base circle, the speed).
    connect(document, &ProjectDocument::changed, this, [this] {
        rebuild();
        if (rowCount() > 0) {
            emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1),
                             {Qt::BackgroundRole, Qt::ToolTipRole});
        }
    });
    if (document->project().design) m_shown = document->project().design->segments;
    rebuild();
}

QStringList DesignTableModel::lawNames() { return motionLawTitles(); }

bool DesignTableModel::swinging() const {
    const auto& f = m_document->project().follower;
    return f && f->motion == FollowerMotion::Oscillating;
}

int DesignTableModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() || !m_document->project().design) return 0;
    return static_cast<int>(m_document->project().design->segments.size());
}

int DesignTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

void DesignTableModel::setCoefficients(const std::vector<LawCoefficients>& coefficients) {
    m_coefficients = coefficients;
    if (rowCount() > 0) emit dataChanged(index(0, Cv), index(rowCount() - 1, Cj));
}

void DesignTableModel::rebuild() {
    m_problems.clear();
    for (const Diagnostic& d : m_document->diagnostics()) {
        const auto* place = std::get_if<DesignSegmentPlace>(&d.place);
        if (!place) continue;
        const int row = static_cast<int>(place->segment);
        const int column = columnOfPart(place->part);
        const QString text = DiagnosticText::message(d);
        if (column >= 0) {
            m_problems[cellKey(row, column)] << text;
        } else {
            for (int c = 0; c < ColumnCount; ++c) m_problems[cellKey(row, c)] << text;
        }
    }
}

QStringList DesignTableModel::problemsAt(int row, int column) const {
    return m_problems.value(cellKey(row, column));
}

QVariant DesignTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const auto& segments = m_document->project().design->segments;
    const auto row = static_cast<std::size_t>(index.row());
    const DesignSegmentSpec& s = segments[row];
    const int c = index.column();
    const bool poly5 = motionLaw(s.law).shape == LawShape::BoundaryValues;
    if (role == SegmentTableModel::ChoicesRole && c == Law) return lawNames();
    if (role == kEditorSuffixRole) {
        const QString unit = swinging() ? QStringLiteral("°") : QStringLiteral(" mm");
        switch (c) {
            case ToDeg:
                return QStringLiteral(" °");
            case Lift:
                return unit;
            case V0:
            case V1:
                return unit + QStringLiteral("/°");
            case A0:
            case A1:
                return unit + QStringLiteral("/°²");
            default:
                return {};
        }
    }
    if (role == kEditorStepRole) return c == ToDeg ? 1.0 : c == Lift ? 0.5 : 0.01;
    if (role == Qt::ToolTipRole) {
        const QStringList problems = problemsAt(index.row(), c);
        if (!problems.isEmpty()) return problems.join('\n');
        switch (c) {
            case Law:
                return tr("How the follower moves over this segment (VDI 2143)");
            case FromDeg:
                return tr("Where the segment starts: the previous segment's end");
            case ToDeg:
                return tr("Cam angle where the segment ends (the last ends at 360°)");
            case Lift:
                return swinging() ? tr("The arm's swing at the segment's end, degrees away from "
                                       "the cam (the last returns to 0)")
                                  : tr("The follower's lift above the base circle at the "
                                       "segment's end (the last returns to 0)");
            case Cv:
                return tr("Largest velocity as a multiple of lift ÷ duration");
            case Ca:
                return tr("Largest acceleration as a multiple of lift ÷ duration²");
            case Cj:
                return tr("Largest jerk as a multiple of lift ÷ duration³");
            default:
                return poly5 ? tr("Poly 5: the lift's slope (v) or curvature (a) per degree of "
                                  "cam angle at the start (0) or the end (1)")
                             : tr("Only for Poly 5");
        }
    }
    if (role == Qt::BackgroundRole) {
        if (!problemsAt(index.row(), c).isEmpty()) return QColor(255, 205, 205);
        if (!(flags(index) & Qt::ItemIsEditable)) return QColor(238, 238, 238);
        return {};
    }
    if (role == Qt::TextAlignmentRole) {
        return c == Law ? QVariant() : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    }
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    const bool edit = role == Qt::EditRole;
    const auto number = [&](double v) -> QVariant {
        return edit ? QVariant(v) : QVariant(formatQuantityValue(DisplayQuantity::Input, v));
    };
    const auto coefficient = [&](double LawCoefficients::*field) -> QVariant {
        if (motionLaw(s.law).shape == LawShape::Dwell) return {};
        double value = 0.0;
        if (row < m_coefficients.size() && m_coefficients.size() == segments.size()) {
            value = m_coefficients[row].*field;
        } else if (!poly5) {
            value = lawCoefficients(s.law).*field;
        } else {
            return {};
        }
        return edit ? QVariant(value)
                    : QVariant(formatQuantityValue(DisplayQuantity::Ratio, value));
    };
    switch (c) {
        case Law: {
            const int law = static_cast<int>(s.law);
            return edit ? QVariant(law) : QVariant(lawNames().value(law));
        }
        case FromDeg:
            return number(row == 0 ? 0.0 : segments[row - 1].toDeg);
        case ToDeg:
            return number(s.toDeg);
        case Lift:
            return number(s.lift);
        case V0:
            return poly5 ? number(s.v0) : QVariant();
        case A0:
            return poly5 ? number(s.a0) : QVariant();
        case V1:
            return poly5 ? number(s.v1) : QVariant();
        case A1:
            return poly5 ? number(s.a1) : QVariant();
        case Cv:
            return coefficient(&LawCoefficients::cv);
        case Ca:
            return coefficient(&LawCoefficients::ca);
        case Cj:
            return coefficient(&LawCoefficients::cj);
        default:
            return {};
    }
}

QVariant DesignTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section;
    const QString unit = swinging() ? QStringLiteral("°") : QStringLiteral("mm");
    switch (section) {
        case Law:
            return tr("Law");
        case FromDeg:
            return tr("From [°]");
        case ToDeg:
            return tr("To [°]");
        case Lift:
            return tr("Lift [%1]").arg(unit);
        case V0:
            return tr("v0 [%1/°]").arg(unit);
        case A0:
            return tr("a0 [%1/°²]").arg(unit);
        case V1:
            return tr("v1 [%1/°]").arg(unit);
        case A1:
            return tr("a1 [%1/°²]").arg(unit);
        case Cv:
            return QStringLiteral("Cv");
        case Ca:
            return QStringLiteral("Ca");
        case Cj:
            return QStringLiteral("Cj");
        default:
            return {};
    }
}

Qt::ItemFlags DesignTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    const int c = index.column();
    if (c == Law || c == ToDeg || c == Lift) return f | Qt::ItemIsEditable;
    if (isPoly5Column(c)) {
        // Poly 5's boundary values; other laws have none: no cell to go to (Tab passes over).
        const bool poly5 =
            index.row() < rowCount() &&
            motionLaw(
                m_document->project().design->segments[static_cast<std::size_t>(index.row())].law)
                    .shape == LawShape::BoundaryValues;
        return poly5 ? f | Qt::ItemIsEditable : Qt::NoItemFlags;
    }
    return f;
}

bool DesignTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || !(flags(index) & Qt::ItemIsEditable)) return false;
    QVariant v = value;
    int gesture = 0;
    if (role == SegmentTableModel::MergingEditRole) {
        const QVariantList pair = value.toList();
        if (pair.size() != 2) return false;
        v = pair[0];
        gesture = pair[1].toInt();
    } else if (role != Qt::EditRole) {
        return false;
    }
    DesignSpec design = *m_document->project().design;
    DesignSegmentSpec& s = design.segments[static_cast<std::size_t>(index.row())];
    const int c = index.column();
    bool ok = false;
    if (c == Law) {
        const int law = v.toInt(&ok);
        if (!ok || law < 0 || law >= static_cast<int>(kMotionLawCount)) return false;
        s.law = static_cast<MotionLawType>(law);
        // A dwell keeps the lift it starts with: switching to one takes that lift at once.
        if (motionLaw(s.law).shape == LawShape::Dwell) {
            s.lift = index.row() == 0 ? 0.0 : design.segments[index.row() - 1].lift;
        }
    } else {
        const double number = v.toDouble(&ok);
        // A cell takes a finite number only; the editor never offers another.
        if (!ok || !std::isfinite(number)) return false;
        double* field = c == ToDeg  ? &s.toDeg
                        : c == Lift ? &s.lift
                        : c == V0   ? &s.v0
                        : c == A0   ? &s.a0
                        : c == V1   ? &s.v1
                                    : &s.a1;
        *field = number;
    }
    if (design == *m_document->project().design) return true;  // nothing changed: no undo step
    const QString text = tr("Edit %1 of design segment %2")
                             .arg(headerData(c, Qt::Horizontal, Qt::DisplayRole).toString(),
                                  QString::number(index.row()));
    m_document->undoStack()->push(new SetDesign(m_document, design, text, gesture));
    return true;
}

}  // namespace cam
