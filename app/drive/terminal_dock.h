// TerminalDock: the dock that holds the drive terminal (object name "terminalDock", title "Terminal").
#pragma once

#include <QDockWidget>

namespace app {

class TerminalWidget;

class TerminalDock final : public QDockWidget {
    Q_OBJECT
public:
    explicit TerminalDock(QWidget* parent = nullptr);

    TerminalWidget* terminal() const { return m_terminal; }

private:
    TerminalWidget* m_terminal;
};

} // namespace app
