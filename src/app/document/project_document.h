#pragma once
/// @file
/// @brief The open project: the core document, its undo stack, its file and its validation.

#include <QObject>
#include <QString>
#include <QUndoStack>

#include "common/diagnostic.h"
#include "project/project.h"

namespace cam {

/// @brief Owns the project being edited. Only undo commands mutate it (through the `apply…`
/// functions); everything else reads it and listens to the signals.
class ProjectDocument : public QObject {
    Q_OBJECT
public:
    explicit ProjectDocument(QObject* parent = nullptr);
    /// Silent: the undo stack's last cleanChanged would otherwise reach listeners (the main
    /// window) that are already half destroyed.
    ~ProjectDocument() override;

    [[nodiscard]] const Project& project() const { return m_project; }
    [[nodiscard]] QUndoStack* undoStack() { return &m_undoStack; }
    [[nodiscard]] const Diagnostics& diagnostics() const { return m_diagnostics; }
    [[nodiscard]] bool isValid() const { return !hasErrors(m_diagnostics); }
    /// @brief Segment row's colour slot (document/segment_colours.h): it stays with the
    /// segment through insertions, deletions and moves; a new file starts from the rows.
    [[nodiscard]] int segmentColourSlot(int row) const;
    [[nodiscard]] const std::vector<int>& segmentColourSlots() const { return m_colourSlots; }

    [[nodiscard]] QString filePath() const { return m_filePath; }
    /// @brief "Untitled" or the file name, for titles.
    [[nodiscard]] QString displayName() const;
    [[nodiscard]] bool isModified() const { return !m_undoStack.isClean(); }

    /// @brief Replaces the whole project (New, Open): clears the undo history.
    void reset(Project project, QString filePath);
    /// @brief The same, with the project's problems already computed (projectProblems, off
    /// the GUI thread for a big file), and the digest of the file's content it was read from.
    void reset(Project project, QString filePath, Diagnostics diagnostics,
               QByteArray fileDigest = {});
    /// @brief After a successful save: remembers the path and the digest of what was written,
    /// and marks the state clean.
    void markSaved(const QString& filePath, QByteArray fileDigest = {});
    /// @brief SHA-256 of the file's content as this window last read or wrote it; empty when
    /// unknown. Set before filePathChanged is emitted. What tells a save that another program
    /// or window has written the file since (files/file_watch.h).
    [[nodiscard]] const QByteArray& fileDigest() const { return m_fileDigest; }
    void setFileDigest(QByteArray digest) { m_fileDigest = std::move(digest); }
    /// @brief Marks the state as unsaved (a project restored from a recovery copy).
    void markUnsaved() { m_undoStack.resetClean(); }

    // Mutators for undo commands. Each emits exactly the signal that describes it.
    void applySegment(int row, const SegmentSpec& segment);
    /// `colourSlot` < 0: a slot neither neighbour has (colourSlotFor).
    void applyInsert(int row, const SegmentSpec& segment, int colourSlot = -1);
    void applyRemove(int row);
    void applyMove(int from, int to);
    void applyContour(const std::vector<SegmentSpec>& contour);
    void applyMotion(const MotionSpec& motion);
    void applyName(const std::string& name);
    void applySamplesPerTurn(const std::optional<std::int64_t>& samples);
    void applyMachining(const std::optional<MachiningSpec>& machining);
    void applyFollower(const std::optional<FollowerSpec>& follower);
    void applyDesign(const std::optional<DesignSpec>& design);
    void applyDynamics(const std::optional<DynamicsSpec>& dynamics);
    /// @brief Synthesize: the contour and the design (its tolerance) in one step.
    void applyContourAndDesign(const std::vector<SegmentSpec>& contour,
                               const std::optional<DesignSpec>& design);

    /// @brief A design whose contour was never synthesised (project-format.md: valid, its
    /// contour empty): nothing to compute or export until Synthesize.
    [[nodiscard]] bool awaitsSynthesis() const {
        return m_project.contour.empty() && m_project.design.has_value();
    }

signals:
    // Structural changes come in pairs, as a Qt model needs them: "about to" while the contour
    // is still as before, then the change itself once it is done.
    void segmentChanged(int row);
    void segmentAboutToBeInserted(int row);
    void segmentInserted(int row);
    void segmentAboutToBeRemoved(int row);
    void segmentRemoved(int row);
    void segmentAboutToBeMoved(int from, int to);
    void segmentMoved(int from, int to);
    void contourAboutToBeReset();
    /// The whole contour changed (reset, fit windows): rebuild every view of it.
    void contourReset();
    void motionChanged();
    /// The project's own name (not its file's).
    void nameChanged();
    void machiningChanged();
    void followerChanged();
    void designChanged();
    void dynamicsChanged();
    /// Any change at all, after the specific signal: recompute, revalidate, redraw.
    void changed();
    void filePathChanged(const QString& path);
    /// Another project took this one's place (New, Open, Revert, a recovery), after every
    /// signal of its parts; a Save is no such thing.
    void replaced();
    void modifiedChanged(bool modified);

private:
    void afterChange();
    void keepColourSlotsFor(std::size_t rows);

    Project m_project;
    std::vector<int> m_colourSlots;  ///< one per segment
    Diagnostics m_diagnostics;
    QUndoStack m_undoStack;
    QString m_filePath;
    QByteArray m_fileDigest;
};

/// @brief Diagnostics for a message box or tooltip: one per line, at most `limit` of them and
/// then "… and N more".
[[nodiscard]] QString diagnosticsText(const Diagnostics& diagnostics, int limit = 12);

}  // namespace cam
