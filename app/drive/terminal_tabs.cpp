#include "terminal_tabs.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>

namespace app {

void raiseInTerminalTabs(QMainWindow& window, QDockWidget* terminal, QDockWidget* dock) {
    const bool tabbed = window.tabifiedDockWidgets(terminal).contains(dock);
    if (!dock->isFloating() && !tabbed && terminal->isVisible()) window.tabifyDockWidget(terminal, dock);
    dock->show();
    dock->raise();
}

QAction* terminalTabAction(QMainWindow& window, QDockWidget* terminal, QDockWidget* dock, const QString& text,
                           QObject* parent) {
    auto* action = new QAction(text, parent);
    action->setCheckable(true);
    action->setProperty("opensDock", QVariant::fromValue(static_cast<QObject*>(dock)));
    QObject::connect(action, &QAction::triggered, dock, [&window, terminal, dock](bool shown) {
        if (shown) raiseInTerminalTabs(window, terminal, dock);
        else dock->hide();
    });
    QObject::connect(dock->toggleViewAction(), &QAction::toggled, action, &QAction::setChecked);
    QObject::connect(dock->toggleViewAction(), &QAction::changed, action,
                     [action, dock] { action->setVisible(dock->toggleViewAction()->isVisible()); });
    return action;
}

} // namespace app
