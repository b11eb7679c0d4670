// FamilyWorkspace: everything the IDE offers for one drive family (app/families/<family>/): its menus,
// toolbars and docks, its entries in the Drive menu, and its own link and session. The main window shows
// the workspace of the family chosen in Drive > Connect and hides the rest; a workspace opens its link in
// activate() and closes it in deactivate(), so only one family talks on a port at a time. GUI thread only.
//
//   auto* sc750 = new Sc750Workspace(window);   // parented to the window
//   window.addWorkspace(sc750);                  // before show(); menus and docks are added hidden
#pragma once

#include "connection_choice.h"

#include "drive_core/drive.h"

#include <QList>
#include <QObject>

class QAction;
class QDockWidget;
class QMenu;
class QToolBar;

namespace serialport {
class DriveSession;
class Link;
} // namespace serialport

namespace app {

class ErrorSource;

class FamilyWorkspace : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    virtual drive_core::DriveFamily family() const = 0;
    // Menus placed before the Drive menu, and docks, both visible only while the workspace is active.
    virtual QList<QMenu*> menus() const = 0;
    virtual QList<QDockWidget*> docks() const = 0;
    // The family's Run, Stop and such for its own toolbar (the main window makes it, shown with the family),
    // in the order shown; nullptr puts a separator. Empty: no toolbar.
    virtual QList<QAction*> toolBarActions() const { return {}; }
    // Toolbars the family makes itself (the BDS5's Drive and Debug), shown with it.
    virtual QList<QToolBar*> toolBars() const { return {}; }
    // The family's entries in the Drive menu, after Connect and Disconnect; nullptr puts a separator.
    virtual QList<QAction*> driveMenuActions() const { return {}; }
    // Connect to the choice's port (or the family's simulated drive); called again to reconnect.
    virtual void activate(const ConnectionChoice& choice) = 0;
    // Close the link; the editors keep their contents.
    virtual void deactivate() = 0;
    virtual bool isConnected() const = 0;
    // For the status bar: "SC750 axis 255, Ready" and similar.
    virtual QString statusText() const = 0;
    // The status bar's other cells: the port ("9600 baud"), the drive's mode ("Interactive -->"), each hidden
    // when empty; the connection's state, a word and its colour.
    struct LinkState {
        QString text;
        QString colour; // "#1e8e3e"
    };
    virtual QString portText() const { return {}; }
    virtual QString modeText() const { return {}; }
    virtual LinkState linkState() const;
    // The family-neutral session and its link while connected (nullptr otherwise): the generic tools (the
    // tuning panel) work through these.
    virtual serialport::DriveSession* driveSession() const { return nullptr; }
    virtual serialport::Link* link() const { return nullptr; }
    // The family's errors for the Error Log dock (owned by the workspace), or nullptr.
    virtual ErrorSource* errorSource() const { return nullptr; }
    // Why the link can take no poll now though connected ("a download is under way"), or empty when it can:
    // the watch and the other polling tools wait while it says so.
    virtual QString busyReason() const { return {}; }
    // The family's sample program, a resource (":/samples/hello.bas"): the first tab when the IDE starts
    // with this family, named after the resource's file name. Empty: the BDS5's opens instead.
    virtual QString sampleProgram() const { return {}; }
    // Help > <family> Reference opens the reference at this topic.
    virtual QString referenceTopic() const { return QStringLiteral("intro"); }
    // The Terminal dock while this workspace is active: bytes typed there (urgent: ^X, Esc). False when the
    // family has no terminal of its own (the main window then says where to type instead).
    virtual bool typeIntoTerminal(const QByteArray& bytes, bool urgent) {
        Q_UNUSED(bytes);
        Q_UNUSED(urgent);
        return false;
    }

signals:
    // statusText() or isConnected() changed.
    void statusChanged();
    // A message for the status bar and the terminal ("The controller did not answer...").
    void message(const QString& text);
    // Bytes from the drive for the Terminal dock (the answers to the user's typing, not to polls).
    void terminalReceived(const QByteArray& bytes);
};

} // namespace app
