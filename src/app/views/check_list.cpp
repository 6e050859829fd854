#include "views/check_list.h"

#include <QLabel>
#include <QListWidget>
#include <QStyle>
#include <QVBoxLayout>

namespace cam {

CheckList::CheckList(const QString& header, const char* listName, const char* summaryName,
                     const QString& tip, QWidget* parent)
    : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(header, this));
    m_list = new QListWidget(this);
    m_list->setObjectName(listName);
    m_list->setToolTip(tip);
    m_list->setWordWrap(true);
    m_list->setIconSize(QSize(14, 14));
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    layout->addWidget(m_list, 1);
    m_summary = new QLabel(this);
    m_summary->setObjectName(summaryName);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    const auto pick = [this](QListWidgetItem* item) {
        const QVariant phi = item->data(Qt::UserRole);
        if (phi.isValid()) emit anglePicked(phi.toDouble());
    };
    connect(m_list, &QListWidget::itemClicked, this, pick);
    connect(m_list, &QListWidget::itemActivated, this, pick);
}

void CheckList::clear() {
    m_list->clear();
    m_problems = 0;
}

void CheckList::add(const QString& text, std::optional<double> phi, bool problem) {
    auto* item = new QListWidgetItem(text, m_list);
    item->setToolTip(text);
    if (phi) item->setData(Qt::UserRole, *phi);
    if (problem) {
        item->setForeground(QColor(180, 0, 0));
        item->setIcon(style()->standardIcon(QStyle::SP_MessageBoxWarning));
        ++m_problems;
    }
}

void CheckList::setSummary(const QString& text) { m_summary->setText(text); }

QStringList CheckList::lines() const {
    QStringList lines;
    for (int i = 0; i < m_list->count(); ++i) lines << m_list->item(i)->text();
    return lines;
}

}  // namespace cam
