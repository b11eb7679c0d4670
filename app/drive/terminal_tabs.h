// Docks of the bottom area open as tabs beside the terminal. Opened with a dock's own toggle action, a dock
// shows side by side with the terminal first: the Tuning panel pushed the window 1236 px wide, the Error Log
// was 318 px wide (issue 19, items 10 and 11). Not tabbed while hidden: a hidden tab takes the terminal's size.
#pragma once

#include <QString>

class QAction;
class QDockWidget;
class QMainWindow;
class QObject;

namespace app {

// Shows dock as a tab beside terminal (unless the user floated it) and raises it.
void raiseInTerminalTabs(QMainWindow& window, QDockWidget* terminal, QDockWidget* dock);

// A checkable menu action that opens dock that way and closes it; it follows the dock's own visibility. Its
// "opensDock" property names the dock (tests open docks as the menus do).
QAction* terminalTabAction(QMainWindow& window, QDockWidget* terminal, QDockWidget* dock, const QString& text,
                           QObject* parent);

} // namespace app
