// TerminalDock: a QDockWidget around a TerminalWidget.
#include "terminal_dock.h"

#include "terminal_widget.h"

namespace app {

TerminalDock::TerminalDock(QWidget* parent)
    : QDockWidget(tr("Terminal"), parent), m_terminal(new TerminalWidget(this)) {
    setObjectName(QStringLiteral("terminalDock"));
    setAllowedAreas(Qt::AllDockWidgetAreas);
    setWidget(m_terminal);
    setFocusProxy(m_terminal);
}

} // namespace app
