#include "models/design_table_model.h"

#include <QColor>
#include <QCoreApplication>

#include "document/commands.h"
#include "messages/diagnostic_text.h"
#include "messages/field_titles.h"
#include "models/delegates.h"
#include "models/segment_table_model.h"
#include "widgets/law_picture.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

quint64 cellKey(int row, int column) {
    return (static_cast<quint64>(row) << 8) | static_cast<quint64>(column);
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
        default:
            for (int c = 0; c < DesignTableModel::ColumnCount; ++c) {
                if (DesignTableModel::partOf(c) == part) return c;
            }
            return -1;
    }
}

QString classTitle(BoundaryClass c) {
    switch (c) {
        case BoundaryClass::Rest:
            return DesignTableModel::tr("Rest");
        case BoundaryClass::Velocity:
            return DesignTableModel::tr("Velocity");
        case BoundaryClass::Reversal:
            return DesignTableModel::tr("Reversal");
        case BoundaryClass::Movement:
            return DesignTableModel::tr("Movement");
    }
    return {};
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
        emit headerDataChanged(Qt::Horizontal, Lift, J1);
        if (rowCount() > 0) emit dataChanged(index(0, Lift), index(rowCount() - 1, J1));
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

DesignPart DesignTableModel::partOf(int column) {
    switch (column) {
        case V0:
            return DesignPart::V0;
        case A0:
            return DesignPart::A0;
        case J0:
            return DesignPart::J0;
        case V1:
            return DesignPart::V1;
        case A1:
            return DesignPart::A1;
        case J1:
            return DesignPart::J1;
        case Lambda:
            return DesignPart::Lambda;
        case SccaB:
            return DesignPart::SccaB;
        case SccaD:
            return DesignPart::SccaD;
        case Points:
            return DesignPart::Points;
        default:
            return DesignPart::Whole;
    }
}

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
    // The classes of a few segments: a handful of evaluations, as the document's own check of
    // the design (designProblems) makes on every change.
    m_classes.clear();
    if (const auto& design = m_document->project().design) {
        if (auto classes = boundaryClasses(*design); classes.ok()) m_classes = classes.value();
    }
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
    const DesignPart part = partOf(c);
    const bool uses = part != DesignPart::Whole && lawUses(s.law, part);
    if (role == SegmentTableModel::ChoicesRole && c == Law) return lawNames();
    if (role == kChoiceIconsRole && c == Law) return motionLawPictures();
    if (role == kChoiceTipsRole && c == Law) return motionLawSummaries();
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
            case J0:
            case J1:
                return unit + QStringLiteral("/°³");
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
            case StartClass:
            case EndClass:
                return tr(
                    "The boundary class the neighbour demands here (VDI 2143): rest (v = 0, "
                    "a = 0), constant velocity (a = 0), reversal (v = 0) or movement");
            case Lambda:
                return uses ? tr("Where the acceleration changes sign, as a share of the "
                                 "segment (0.5: the symmetric law)")
                            : tr("Only for the modified sine and the modified trapezoid");
            case SccaB:
            case SccaD:
                return uses ? tr("SCCA: b is the share of the sine ramps, d of the cosine; the "
                                 "constant acceleration takes the rest (b = d = 0.25: the "
                                 "modified trapezoid)")
                            : tr("Only for SCCA");
            case Points:
                return uses ? tr("How many points the motion table has; Import Table… reads them "
                                 "from a "
                                 "two-column text file (x and y from 0 to 1)")
                            : tr("Only for a motion table");
            default:
                return uses ? tr("The lift's slope (v), curvature (a) or its rate (j) per degree "
                                 "of cam angle at the start (0) or the end (1)")
                            : tr("Not a value of this law");
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
        const LawShape shape = motionLaw(s.law).shape;
        if (shape == LawShape::Normalised) {
            // In closed form from the law's parameters, at once.
            const double from = row == 0 ? 0.0 : segments[row - 1].toDeg;
            const double lift0 = row == 0 ? 0.0 : segments[row - 1].lift;
            value = lawCoefficients(s.law, lawParameters(s, s.toDeg - from, s.lift - lift0)).*field;
        } else if (row < m_coefficients.size() && m_coefficients.size() == segments.size()) {
            value = m_coefficients[row].*field;
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
            return uses ? number(s.v0) : QVariant();
        case A0:
            return uses ? number(s.a0) : QVariant();
        case J0:
            return uses ? number(s.j0) : QVariant();
        case V1:
            return uses ? number(s.v1) : QVariant();
        case A1:
            return uses ? number(s.a1) : QVariant();
        case J1:
            return uses ? number(s.j1) : QVariant();
        case Lambda:
            return uses ? number(s.lambda) : QVariant();
        case SccaB:
            return uses ? number(s.sccaB) : QVariant();
        case SccaD:
            return uses ? number(s.sccaD) : QVariant();
        case Points:
            return uses ? QVariant(static_cast<int>(s.table.size())) : QVariant();
        case StartClass:
        case EndClass:
            if (row >= m_classes.size() || m_classes.size() != segments.size()) return {};
            return classTitle(c == StartClass ? m_classes[row].start : m_classes[row].end);
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
        case J0:
            return tr("j0 [%1/°³]").arg(unit);
        case J1:
            return tr("j1 [%1/°³]").arg(unit);
        // Shares of the stretch, without a unit; the header as wide as the values it heads.
        case Lambda:
            return QStringLiteral("λ [–]");
        case SccaB:
            return QStringLiteral("b [–]");
        case SccaD:
            return QStringLiteral("d [–]");
        case Points:
            return tr("Points");
        case StartClass:
            return tr("Start");
        case EndClass:
            return tr("End");
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
    const DesignPart part = partOf(c);
    if (part != DesignPart::Whole) {
        // A law's own values; other laws have none: no cell to go to (Tab passes over). A
        // table's points are imported (Import Table…), not typed.
        const bool uses =
            index.row() < rowCount() &&
            lawUses(
                m_document->project().design->segments[static_cast<std::size_t>(index.row())].law,
                part);
        if (!uses) return Qt::NoItemFlags;
        return part == DesignPart::Points ? f : f | Qt::ItemIsEditable;
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
        double* field = nullptr;
        switch (c) {
            case ToDeg:
                field = &s.toDeg;
                break;
            case Lift:
                field = &s.lift;
                break;
            case V0:
                field = &s.v0;
                break;
            case A0:
                field = &s.a0;
                break;
            case J0:
                field = &s.j0;
                break;
            case V1:
                field = &s.v1;
                break;
            case A1:
                field = &s.a1;
                break;
            case J1:
                field = &s.j1;
                break;
            case Lambda:
                field = &s.lambda;
                break;
            case SccaB:
                field = &s.sccaB;
                break;
            case SccaD:
                field = &s.sccaD;
                break;
            default:
                return false;
        }
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
