#pragma once
/// @file
/// @brief A dock's checks over the turn (the Follower dock's design checks, the Forces dock's
/// results): a header, one line per result — a failing one red, with a warning icon — and a
/// summary below. Clicking a line that has an angle, or Enter on it, asks to go there.

#include <QStringList>
#include <QWidget>
#include <optional>

class QLabel;
class QListWidget;

namespace cam {

class CheckList : public QWidget {
    Q_OBJECT
public:
    /// @param listName, summaryName the object names of the list and the summary label
    CheckList(const QString& header, const char* listName, const char* summaryName,
              const QString& tip, QWidget* parent);

    /// @brief Empties the list (and the count of failures); the summary stays until set.
    void clear();
    /// @brief Adds a line; `phi` (rad) is where a click goes, `problem` draws it as a failure.
    void add(const QString& text, std::optional<double> phi, bool problem);
    void setSummary(const QString& text);
    /// @brief How many lines added since clear() are failures.
    [[nodiscard]] int problemCount() const { return m_problems; }
    /// @brief The lines as shown, one each.
    [[nodiscard]] QStringList lines() const;
    [[nodiscard]] QListWidget* list() const { return m_list; }

signals:
    /// A line was clicked: go to this cam angle (rad).
    void anglePicked(double phi);

private:
    QListWidget* m_list;
    QLabel* m_summary;
    int m_problems = 0;
};

}  // namespace cam
