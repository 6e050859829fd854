#include "document/project_document.h"

#include <QFileInfo>

#include "document/segment_colours.h"
#include "evaluation/evaluation.h"
#include "messages/diagnostic_text.h"

namespace cam {

ProjectDocument::ProjectDocument(QObject* parent) : QObject(parent) {
    connect(&m_undoStack, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
    m_diagnostics = projectProblems(m_project);
}

ProjectDocument::~ProjectDocument() {
    m_undoStack.blockSignals(true);
    blockSignals(true);
}

QString ProjectDocument::displayName() const {
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

void ProjectDocument::reset(Project project, QString filePath) {
    Diagnostics diagnostics = projectProblems(project);
    reset(std::move(project), std::move(filePath), std::move(diagnostics));
}

void ProjectDocument::reset(Project project, QString filePath, Diagnostics diagnostics,
                            QByteArray fileDigest) {
    m_undoStack.clear();
    emit contourAboutToBeReset();
    m_project = std::move(project);
    m_colourSlots = freshColourSlots(static_cast<int>(m_project.contour.size()));
    m_diagnostics = std::move(diagnostics);
    m_filePath = std::move(filePath);
    m_fileDigest = std::move(fileDigest);
    m_undoStack.setClean();
    emit filePathChanged(m_filePath);
    emit contourReset();
    emit nameChanged();
    emit motionChanged();
    emit machiningChanged();
    emit followerChanged();
    emit designChanged();
    emit dynamicsChanged();
    emit changed();
    emit replaced();
}

void ProjectDocument::markSaved(const QString& filePath, QByteArray fileDigest) {
    m_fileDigest = std::move(fileDigest);
    if (filePath != m_filePath) {
        m_filePath = filePath;
        emit filePathChanged(m_filePath);
    }
    m_undoStack.setClean();
}

void ProjectDocument::applySegment(int row, const SegmentSpec& segment) {
    m_project.contour.at(static_cast<std::size_t>(row)) = segment;
    emit segmentChanged(row);
    afterChange();
}

int ProjectDocument::segmentColourSlot(int row) const {
    return row >= 0 && row < static_cast<int>(m_colourSlots.size())
               ? m_colourSlots[static_cast<std::size_t>(row)]
               : std::max(row, 0) % kSegmentColourSlots;
}

void ProjectDocument::applyInsert(int row, const SegmentSpec& segment, int colourSlot) {
    emit segmentAboutToBeInserted(row);
    m_colourSlots.insert(m_colourSlots.begin() + row,
                         colourSlot >= 0 ? colourSlot : colourSlotFor(m_colourSlots, row));
    m_project.contour.insert(m_project.contour.begin() + row, segment);
    emit segmentInserted(row);
    afterChange();
}

void ProjectDocument::applyRemove(int row) {
    emit segmentAboutToBeRemoved(row);
    m_project.contour.erase(m_project.contour.begin() + row);
    m_colourSlots.erase(m_colourSlots.begin() + row);
    emit segmentRemoved(row);
    afterChange();
}

void ProjectDocument::applyMove(int from, int to) {
    emit segmentAboutToBeMoved(from, to);
    auto& c = m_project.contour;
    const SegmentSpec moved = c.at(static_cast<std::size_t>(from));
    c.erase(c.begin() + from);
    c.insert(c.begin() + to, moved);
    const int slot = m_colourSlots.at(static_cast<std::size_t>(from));
    m_colourSlots.erase(m_colourSlots.begin() + from);
    m_colourSlots.insert(m_colourSlots.begin() + to, slot);
    emit segmentMoved(from, to);
    afterChange();
}

void ProjectDocument::applyContour(const std::vector<SegmentSpec>& contour) {
    emit contourAboutToBeReset();
    m_project.contour = contour;
    keepColourSlotsFor(contour.size());
    emit contourReset();
    afterChange();
}

void ProjectDocument::applyMotion(const MotionSpec& motion) {
    m_project.motion = motion;
    emit motionChanged();
    afterChange();
}

void ProjectDocument::applyName(const std::string& name) {
    m_project.name = name;
    emit nameChanged();
    afterChange();
}

void ProjectDocument::applySamplesPerTurn(const std::optional<std::int64_t>& samples) {
    m_project.samplesPerTurn = samples;
    emit motionChanged();
    afterChange();
}

void ProjectDocument::applyMachining(const std::optional<MachiningSpec>& machining) {
    m_project.machining = machining;
    emit machiningChanged();
    afterChange();
}

void ProjectDocument::applyFollower(const std::optional<FollowerSpec>& follower) {
    m_project.follower = follower;
    emit followerChanged();
    afterChange();
}

void ProjectDocument::applyDynamics(const std::optional<DynamicsSpec>& dynamics) {
    m_project.dynamics = dynamics;
    emit dynamicsChanged();
    afterChange();
}

void ProjectDocument::applyDesign(const std::optional<DesignSpec>& design) {
    m_project.design = design;
    emit designChanged();
    afterChange();
}

void ProjectDocument::applyContourAndDesign(const std::vector<SegmentSpec>& contour,
                                            const std::optional<DesignSpec>& design) {
    emit contourAboutToBeReset();
    m_project.contour = contour;
    keepColourSlotsFor(contour.size());
    m_project.design = design;
    emit contourReset();
    emit designChanged();
    afterChange();
}

void ProjectDocument::keepColourSlotsFor(std::size_t rows) {
    // The same rows (windows fitted, corners rounded in place): each keeps its colour; another
    // contour starts afresh.
    if (m_colourSlots.size() != rows) m_colourSlots = freshColourSlots(static_cast<int>(rows));
}

QString diagnosticsText(const Diagnostics& diagnostics, int limit) {
    QStringList lines;
    for (const Diagnostic& d : diagnostics) {
        if (lines.size() == limit) {
            lines << ProjectDocument::tr("… and %1 more").arg(diagnostics.size() - limit);
            break;
        }
        lines << diagnosticText(d);
    }
    return lines.join('\n');
}

void ProjectDocument::afterChange() {
    // The verdict (validation, compiling the contour, placing the follower) is linear in the
    // number of segments (microseconds for a table), so it runs here; the kinematics run in the
    // compute engine's thread.
    m_diagnostics = projectProblems(m_project);
    emit changed();
}

}  // namespace cam
