#pragma once
/// @file
/// @brief The status bar's two permanent labels: whether the project is valid (its problems,
/// the first one named, all in the tooltip) and what the last computation did ("… samples
/// computed in …", "computing…", "not computed: …").

#include <QObject>

#include "engine/compute_result.h"

class QLabel;
class QStatusBar;
class QTimer;

namespace cam {

class ComputeEngine;
class ProjectDocument;

class StatusLabels : public QObject {
    Q_OBJECT
public:
    StatusLabels(QStatusBar* bar, const ProjectDocument* document, const ComputeEngine* engine);

    /// @brief The validation label, after an edit.
    void showValidation();
    /// @brief A computation was requested: "computing…" if its result takes a while.
    void computing();
    /// @brief A result arrived (it ends "computing…").
    void arrived();
    /// @brief A result that could not be computed, and why.
    void showUncomputed(const ComputeResult& result);
    /// @brief A computed result, once drawn.
    void showComputed(const ComputeResult& result);

private:
    QStatusBar* m_bar;
    const ProjectDocument* m_document;
    const ComputeEngine* m_engine;
    QLabel* m_validation;
    QLabel* m_compute;
    /// Fires when a request has waited kBusyAfterMs without its result: the label then says
    /// "computing…" instead of describing a result of the project as it was.
    QTimer* m_busy;
};

}  // namespace cam
