#include "document/commands.h"

#include <QCoreApplication>

namespace cam {

EditSegment::EditSegment(ProjectDocument* document, int row, SegmentSpec after, EditedField field,
                         const QString& text, int gesture, QUndoCommand* parent)
    : QUndoCommand(text, parent),
      m_document(document),
      m_row(row),
      m_before(document->project().contour.at(static_cast<std::size_t>(row))),
      m_after(std::move(after)),
      m_field(field),
      m_gesture(gesture) {}

void EditSegment::undo() { m_document->applySegment(m_row, m_before); }
void EditSegment::redo() { m_document->applySegment(m_row, m_after); }

bool EditSegment::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const EditSegment*>(other);
    if (m_gesture == 0 || o->m_gesture != m_gesture || o->m_row != m_row || o->m_field != m_field) {
        return false;
    }
    m_after = o->m_after;
    setObsolete(m_after == m_before);  // stepped back to where it started: nothing to undo
    return true;
}

InsertSegment::InsertSegment(ProjectDocument* document, int row, SegmentSpec segment,
                             QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("cam::Commands", "Insert segment"), parent),
      m_document(document),
      m_row(row),
      m_segment(std::move(segment)) {}

void InsertSegment::undo() { m_document->applyRemove(m_row); }
void InsertSegment::redo() {
    m_document->applyInsert(m_row, m_segment, m_colourSlot);
    m_colourSlot = m_document->segmentColourSlot(m_row);
}

RemoveSegment::RemoveSegment(ProjectDocument* document, int row, QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("cam::Commands", "Delete segment"), parent),
      m_document(document),
      m_row(row),
      m_segment(document->project().contour.at(static_cast<std::size_t>(row))),
      m_colourSlot(document->segmentColourSlot(row)) {}

void RemoveSegment::undo() { m_document->applyInsert(m_row, m_segment, m_colourSlot); }
void RemoveSegment::redo() { m_document->applyRemove(m_row); }

MoveSegment::MoveSegment(ProjectDocument* document, int from, int to, QUndoCommand* parent)
    : QUndoCommand(QCoreApplication::translate("cam::Commands", "Move segment"), parent),
      m_document(document),
      m_from(from),
      m_to(to) {}

void MoveSegment::undo() { m_document->applyMove(m_to, m_from); }
void MoveSegment::redo() { m_document->applyMove(m_from, m_to); }

ReplaceContour::ReplaceContour(ProjectDocument* document, std::vector<SegmentSpec> after,
                               const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent),
      m_document(document),
      m_before(document->project().contour),
      m_after(std::move(after)) {}

void ReplaceContour::undo() { m_document->applyContour(m_before); }
void ReplaceContour::redo() { m_document->applyContour(m_after); }

SetMotion::SetMotion(ProjectDocument* document, MotionSpec after, int gesture)
    : SetProjectValue(document, after, QCoreApplication::translate("cam::Commands", "Change speed"),
                      gesture) {}

SetProjectName::SetProjectName(ProjectDocument* document, std::string after)
    : SetProjectValue(document, std::move(after),
                      QCoreApplication::translate("cam::Commands", "Rename project"), 0) {}

SetSamplesPerTurn::SetSamplesPerTurn(ProjectDocument* document, std::optional<std::int64_t> after)
    : SetProjectValue(document, after,
                      QCoreApplication::translate("cam::Commands", "Change samples per turn"), 0) {}

SetFollower::SetFollower(ProjectDocument* document, std::optional<FollowerSpec> after, int gesture)
    : SetProjectValue(document, std::move(after),
                      QCoreApplication::translate("cam::Commands", "Change follower"), gesture) {}

SetDynamics::SetDynamics(ProjectDocument* document, std::optional<DynamicsSpec> after, int gesture)
    : SetProjectValue(document, std::move(after),
                      QCoreApplication::translate("cam::Commands", "Change dynamics"), gesture) {}

SetMachining::SetMachining(ProjectDocument* document, std::optional<MachiningSpec> after,
                           int gesture)
    : SetProjectValue(document, std::move(after),
                      QCoreApplication::translate("cam::Commands", "Change machining limits"),
                      gesture) {}

SetDesign::SetDesign(ProjectDocument* document, std::optional<DesignSpec> after,
                     const QString& text, int gesture)
    : SetProjectValue(document, std::move(after), text, gesture) {}

SynthesizeContour::SynthesizeContour(ProjectDocument* document, std::vector<SegmentSpec> contour,
                                     double tolerance)
    : QUndoCommand(QCoreApplication::translate("cam::Commands", "Synthesize contour")),
      m_document(document),
      m_contourBefore(document->project().contour),
      m_contourAfter(std::move(contour)),
      m_designBefore(document->project().design),
      m_designAfter(document->project().design) {
    if (m_designAfter) m_designAfter->tolerance = tolerance;
}

void SynthesizeContour::undo() {
    m_document->applyContourAndDesign(m_contourBefore, m_designBefore);
}
void SynthesizeContour::redo() { m_document->applyContourAndDesign(m_contourAfter, m_designAfter); }

}  // namespace cam
