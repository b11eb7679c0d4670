#pragma once
// Room for the status bar's messages (issue 19, item 11): on a 1366-pixel screen the permanent cells (cursor
// line, keys, link, port, mode, state) left "Verified: the drive's p" of a transfer's result. While a message
// is shown, the cells that matter least fold away, in the order given, until the message fits; they come back
// when it clears. Folding sets a cell's maximum width, never its visibility, which its owner controls.
#include <QList>
#include <QObject>
#include <QPointer>

class QStatusBar;
class QWidget;

namespace app {

class StatusBarRoom final : public QObject {
    Q_OBJECT
public:
    // cells: permanent widgets of the bar, the first to fold first.
    StatusBarRoom(QStatusBar& bar, QList<QWidget*> cells);

    static int messageRoom(const QStatusBar& bar); // pixels left of the leftmost visible permanent widget

private:
    void makeRoomFor(const QString& message);
    void unfoldAll();

    QStatusBar& m_bar;
    QList<QPointer<QWidget>> m_cells;
};

} // namespace app
