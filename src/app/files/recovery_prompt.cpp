#include "files/recovery_prompt.h"

#include <QDir>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>

namespace cam {

RecoveryPrompt::RecoveryPrompt(Autosave* autosave, QWidget* window)
    : QObject(window), m_autosave(autosave), m_window(window) {}

bool RecoveryPrompt::offer() {
    // Claimed while the question is open: a second window starting meanwhile offers another.
    const std::vector<Autosave::Orphan> orphans = m_autosave->orphans();
    if (orphans.empty()) return false;
    const Autosave::Orphan& newest = orphans.front();
    const QString name = newest.original.isEmpty() ? tr("an untitled project")
                                                   : QDir::toNativeSeparators(newest.original);
    QMessageBox box(
        QMessageBox::Question, tr("Recover Unsaved Changes"),
        tr("Camwright did not close properly. Unsaved changes to %1, autosaved %2, "
           "can be restored.")
            .arg(name, QLocale().toString(newest.saved.toLocalTime(), QLocale::ShortFormat)),
        QMessageBox::NoButton, m_window);
    box.setObjectName("recoveryBox");
    QPushButton* restore = box.addButton(tr("Restore"), QMessageBox::AcceptRole);
    QPushButton* discard = box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
    box.addButton(tr("Later"), QMessageBox::RejectRole);
    box.setDefaultButton(restore);
    box.setInformativeText(tr("Later keeps the copy and asks again at the next start."));
    box.exec();
    if (box.clickedButton() == discard) {
        Autosave::discard(newest);
        emit message(tr("The recovery copy was discarded."), 6000);
        return false;
    }
    if (box.clickedButton() != restore) return false;
    return RecoveryPrompt::restore(newest);
}

bool RecoveryPrompt::restore(const Autosave::Orphan& orphan) {
    QString problem;
    const bool restored = m_autosave->adopt(orphan, &problem);
    if (!problem.isEmpty()) QMessageBox::warning(m_window, tr("Recover Unsaved Changes"), problem);
    if (restored) {
        emit message(
            tr("Restored the unsaved changes of %1: save them to keep them.")
                .arg(orphan.original.isEmpty() ? tr("an untitled project")
                                               : QDir::toNativeSeparators(orphan.original)),
            10000);
    }
    return restored;
}

}  // namespace cam
