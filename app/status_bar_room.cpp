#include "status_bar_room.h"

#include <QLayout>
#include <QStatusBar>

#include <algorithm>

namespace app {
namespace {
// QStatusBar draws its message with a few pixels of margin on each side.
constexpr int kMessageMargins = 16;
} // namespace

StatusBarRoom::StatusBarRoom(QStatusBar& bar, QList<QWidget*> cells) : QObject(&bar), m_bar(bar) {
    for (QWidget* cell : cells) m_cells << cell;
    connect(&bar, &QStatusBar::messageChanged, this, &StatusBarRoom::makeRoomFor);
}

int StatusBarRoom::messageRoom(const QStatusBar& bar) {
    int left = bar.width();
    for (const QWidget* child : bar.findChildren<QWidget*>(Qt::FindDirectChildrenOnly)) {
        if (!child->isVisible() || child->width() == 0 || child->x() <= 0) continue;
        left = std::min(left, child->x());
    }
    return left;
}

void StatusBarRoom::makeRoomFor(const QString& message) {
    unfoldAll();
    if (message.isEmpty()) return;
    const int needed = m_bar.fontMetrics().horizontalAdvance(message) + kMessageMargins;
    int room = m_bar.width() - kMessageMargins;
    const int spacing = m_bar.layout() ? std::max(0, m_bar.layout()->spacing()) : 0;
    for (const QWidget* child : m_bar.findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
        if (child->isVisible() && child->x() > 0) room -= child->sizeHint().width() + spacing;
    for (QWidget* cell : m_cells) {
        if (room >= needed) break;
        if (!cell || !cell->isVisible()) continue;
        room += cell->sizeHint().width();
        cell->setMaximumWidth(0);
    }
}

void StatusBarRoom::unfoldAll() {
    for (QWidget* cell : m_cells)
        if (cell) cell->setMaximumWidth(QWIDGETSIZE_MAX);
}

} // namespace app
