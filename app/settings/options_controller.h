// OptionsController: the Options menu — Options..., Wake Up Axis, Cable Disconnect, Reconnect — and what
// the options do: the autobaud sequence and the multidrop wake-up after each connect, the colours of the
// terminal and editor. GUI thread only.
#pragma once

#include "app_options.h"

#include <QObject>
#include <QPointer>

class QAction;
class QMenu;

namespace app {

class DebugHighlighter;
class MainWindow;
class OptionsDialog;

class OptionsController final : public QObject {
    Q_OBJECT
public:
    OptionsController(MainWindow& window, DebugHighlighter& highlighter);

    void addToMenu(QMenu* menu);
    // Options...: the dialog, shown without blocking; OK applies and stores the options.
    OptionsDialog* showDialog();
    // Applies options (colours now; autobaud and axis at the next connect) and tells listeners.
    void apply(const AppOptions& options);
    // Sends "\" + axis ID when an axis is chosen.
    void wakeUpAxis();
    // Cable Disconnect: lets the command in flight finish, drops the queue, closes the port.
    void cableDisconnect();
    void reconnect();

    QAction* cableDisconnectAction() const { return m_cableDisconnect; }
    QAction* reconnectAction() const { return m_reconnect; }

signals:
    void optionsChanged(const app::AppOptions& options); // the keymap and anything else others apply

private:
    void onConnected(bool connected);
    void closeWhenQuiet();
    void updateActions();

    MainWindow& m_window;
    DebugHighlighter& m_highlighter;
    AppOptions m_options;
    QAction* m_wakeUp;
    QAction* m_cableDisconnect;
    QAction* m_reconnect;
    bool m_disconnecting = false;
};

} // namespace app
