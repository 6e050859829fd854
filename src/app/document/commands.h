#pragma once
/// @file
/// @brief The undo commands: one class per kind of edit to the project document.

#include <QUndoCommand>
#include <vector>

#include "document/project_document.h"

namespace cam {

/// @brief Every merge id in one place: consecutive commands with the same id may merge.
enum class MergeId : int {
    None = -1,
    EditEditedField = 1,  ///< repeated edits of one cell (spin-box steps, a drag)
    EditMotion = 2,
    EditMachining = 3,
    EditFollower = 4,
    EditDesign = 5,
    EditDynamics = 6,
};

/// @brief Which part of a segment an edit touched; edits of the same part of the same row merge.
/// The first eleven are in the order of SegmentTableModel's columns.
enum class EditedField {
    Type,
    CenterX,
    CenterY,
    Radius,
    Branch,
    FromX,
    FromY,
    ToX,
    ToY,
    PhiStart,
    PhiEnd,
    FirstHandleDrag,   ///< the contour view's first handle: an arc's centre, a spline's P1
    SecondHandleDrag,  ///< the second: an arc's radius, a spline's P2
    ControlPoint,      ///< a spline's control point or handle typed in the Control Points dock
    Whole
};

/// @brief Replaces segment `row` by a new value (any field or fields).
///
/// Consecutive edits of the same field of the same row merge when they carry the same non-zero
/// `gesture` (one spin-box editing session, one mouse drag); gesture 0 never merges.
class EditSegment : public QUndoCommand {
public:
    EditSegment(ProjectDocument* document, int row, SegmentSpec after, EditedField field,
                const QString& text, int gesture = 0, QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;
    [[nodiscard]] int id() const override { return static_cast<int>(MergeId::EditEditedField); }
    bool mergeWith(const QUndoCommand* other) override;

private:
    ProjectDocument* m_document;
    int m_row;
    SegmentSpec m_before;
    SegmentSpec m_after;
    EditedField m_field;
    int m_gesture;
};

class InsertSegment : public QUndoCommand {
public:
    InsertSegment(ProjectDocument* document, int row, SegmentSpec segment,
                  QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    ProjectDocument* m_document;
    int m_row;
    SegmentSpec m_segment;
    int m_colourSlot = -1;  ///< chosen at the first redo, the same at every later one
};

class RemoveSegment : public QUndoCommand {
public:
    RemoveSegment(ProjectDocument* document, int row, QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    ProjectDocument* m_document;
    int m_row;
    SegmentSpec m_segment;
    int m_colourSlot;  ///< undone, the segment comes back in its colour
};

/// @brief Moves segment `from` so that it ends up at index `to`.
class MoveSegment : public QUndoCommand {
public:
    MoveSegment(ProjectDocument* document, int from, int to, QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    ProjectDocument* m_document;
    int m_from;
    int m_to;
};

/// @brief Replaces the whole contour at once (Fit windows and other whole-contour operations).
class ReplaceContour : public QUndoCommand {
public:
    ReplaceContour(ProjectDocument* document, std::vector<SegmentSpec> after, const QString& text,
                   QUndoCommand* parent = nullptr);
    void undo() override;
    void redo() override;

private:
    ProjectDocument* m_document;
    std::vector<SegmentSpec> m_before;
    std::vector<SegmentSpec> m_after;
};

/// @brief One command for every project-wide value: keeps the value before and after and swaps
/// them through the document's `apply` function. Edits with the same non-zero gesture (one
/// spin-box session) merge when the value has a merge id.
template <class T, T Project::*Field, void (ProjectDocument::*Apply)(const T&), MergeId Id>
class SetProjectValue : public QUndoCommand {
public:
    SetProjectValue(ProjectDocument* document, T after, const QString& text, int gesture)
        : QUndoCommand(text),
          m_document(document),
          m_before(document->project().*Field),
          m_after(std::move(after)),
          m_gesture(gesture) {}
    void undo() override { (m_document->*Apply)(m_before); }
    void redo() override { (m_document->*Apply)(m_after); }
    [[nodiscard]] int id() const override { return static_cast<int>(Id); }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = static_cast<const SetProjectValue*>(other);
        if (m_gesture == 0 || o->m_gesture != m_gesture) return false;
        m_after = o->m_after;
        setObsolete(m_after == m_before);  // stepped back to where it started
        return true;
    }

private:
    ProjectDocument* m_document;
    T m_before;
    T m_after;
    int m_gesture;
};

/// @brief Sets the turning speed and its unit.
class SetMotion : public SetProjectValue<MotionSpec, &Project::motion,
                                         &ProjectDocument::applyMotion, MergeId::EditMotion> {
public:
    SetMotion(ProjectDocument* document, MotionSpec after, int gesture = 0);
};

/// @brief Renames the project (its own name, which exports carry; not its file's).
class SetProjectName : public SetProjectValue<std::string, &Project::name,
                                              &ProjectDocument::applyName, MergeId::None> {
public:
    SetProjectName(ProjectDocument* document, std::string after);
};

/// @brief Sets the samples per turn (or goes back to the default).
class SetSamplesPerTurn
    : public SetProjectValue<std::optional<std::int64_t>, &Project::samplesPerTurn,
                             &ProjectDocument::applySamplesPerTurn, MergeId::None> {
public:
    SetSamplesPerTurn(ProjectDocument* document, std::optional<std::int64_t> after);
};

/// @brief Sets, changes or removes the machining limits.
class SetMachining
    : public SetProjectValue<std::optional<MachiningSpec>, &Project::machining,
                             &ProjectDocument::applyMachining, MergeId::EditMachining> {
public:
    SetMachining(ProjectDocument* document, std::optional<MachiningSpec> after, int gesture = 0);
};

/// @brief Sets, changes or removes the follower (none: the seed's radial knife edge).
class SetFollower : public SetProjectValue<std::optional<FollowerSpec>, &Project::follower,
                                           &ProjectDocument::applyFollower, MergeId::EditFollower> {
public:
    SetFollower(ProjectDocument* document, std::optional<FollowerSpec> after, int gesture = 0);
};

}  // namespace cam

namespace cam {

/// @brief Sets, changes or removes the dynamics: masses, spring, load, materials (Forces dock).
class SetDynamics : public SetProjectValue<std::optional<DynamicsSpec>, &Project::dynamics,
                                           &ProjectDocument::applyDynamics, MergeId::EditDynamics> {
public:
    SetDynamics(ProjectDocument* document, std::optional<DynamicsSpec> after, int gesture = 0);
};

/// @brief Sets, changes or removes the motion design (Motion Design dock).
class SetDesign : public SetProjectValue<std::optional<DesignSpec>, &Project::design,
                                         &ProjectDocument::applyDesign, MergeId::EditDesign> {
public:
    SetDesign(ProjectDocument* document, std::optional<DesignSpec> after, const QString& text,
              int gesture = 0);
};

/// @brief Synthesize: the arc table made from the design replaces the contour, and the design
/// keeps the tolerance it was made with; one undo step for both.
class SynthesizeContour : public QUndoCommand {
public:
    SynthesizeContour(ProjectDocument* document, std::vector<SegmentSpec> contour,
                      double tolerance);
    void undo() override;
    void redo() override;

private:
    ProjectDocument* m_document;
    std::vector<SegmentSpec> m_contourBefore, m_contourAfter;
    std::optional<DesignSpec> m_designBefore, m_designAfter;
};

}  // namespace cam
