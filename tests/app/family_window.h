// The set-up the family tests in tests/app share: the main window connected to one family's simulated drive
// (Drive > Connect, the simulator of that family) and that family's workspace, and a new program tab. The
// connection completes later: tests wait for ws.isConnected() themselves. Header only; GUI thread.
#pragma once

#include "app/drive/connection_choice.h"
#include "app/main_window.h"
#include "families/pmc960/pmc960_workspace.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_workspace.h"

#include "editor/program_editor.h"

#include <QFile>
#include <QToolBar>
#include <QToolButton>

namespace family_window {

template <class Workspace>
Workspace& connectSimulated(app::MainWindow& window, drive_core::DriveFamily family) {
    window.connectDrive(app::ConnectionChoice::simulator(family));
    return *static_cast<Workspace*>(window.workspace(family));
}

inline app::Sc750Workspace& connectSc750(app::MainWindow& window) {
    return connectSimulated<app::Sc750Workspace>(window, drive_core::DriveFamily::Sc750);
}

inline app::Pmc960Workspace& connectPmc960(app::MainWindow& window) {
    return connectSimulated<app::Pmc960Workspace>(window, drive_core::DriveFamily::Pmc960);
}

// Controller > Create Program: a new .bas tab, holding text when given.
inline editor::ProgramEditor* newBasProgram(app::Sc750Workspace& ws, const QString& text = {}) {
    qobject_cast<app::Sc750ControllerMenu*>(ws.menus().at(1))->createProgram();
    editor::ProgramEditor* program = ws.window().editor();
    if (!text.isEmpty()) program->setText(text);
    return program;
}

// Connects to the simulated SC750 and opens a new .bas tab holding text (empty when none is given).
inline app::Sc750Workspace& connectSc750WithProgram(app::MainWindow& window, const QString& text = {}) {
    app::Sc750Workspace& ws = connectSc750(window);
    newBasProgram(ws, text);
    return ws;
}

#ifdef SC750_EXAMPLES
// One of the SC750 manual's example programs (tests/drive_core/sc750/examples); "" when it is missing.
inline QString sc750Example(const char* name) {
    QFile file(QStringLiteral(SC750_EXAMPLES "/") + QLatin1String(name));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}
#endif

// The buttons of the toolbars the window shows, in order, as their text reads ("Run Program", "Stop").
inline QStringList toolBarButtons(const app::MainWindow& window) {
    QStringList texts;
    for (const QToolBar* bar : window.findChildren<QToolBar*>()) {
        if (!bar->isVisible()) continue;
        for (QAction* action : bar->actions())
            if (const auto* button = qobject_cast<QToolButton*>(bar->widgetForAction(action));
                button && button->isVisible())
                texts << button->text();
    }
    return texts;
}

} // namespace family_window
