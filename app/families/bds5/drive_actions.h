// DriveActions: the Drive menu's control actions and the drive and debug toolbars — Run label..., Break,
// Stop motion, Kill, Enable/Disable, Monitor, single-step and trace on/off, Variable input, and Step /
// Continue at the single-step prompt. What each sends depends on the drive's mode (its last prompt);
// enablement follows the mode. GUI thread only.
#pragma once

#include "serialport/bds5_protocol.h"

#include <QByteArray>
#include <QObject>
#include <QSet>

class QAction;
class QMenu;
class QToolBar;
class QWidget;

namespace app {

class MainWindow;
class RunLabelDialog;

class DriveActions final : public QObject {
    Q_OBJECT
public:
    explicit DriveActions(MainWindow& window);

    // The Drive menu's BDS5 entries in order; nullptr puts a separator.
    QList<QAction*> menuActions() const;
    // Toolbars parented to the main window, object names "driveToolBar" and "debugToolBar".
    QToolBar* createDriveToolBar();
    QToolBar* createDebugToolBar();

    QAction* runAction() const { return m_run; }
    QAction* breakAction() const { return m_break; }
    QAction* stopAction() const { return m_stop; }
    QAction* killAction() const { return m_kill; }
    QAction* enableAction() const { return m_enable; }
    QAction* disableAction() const { return m_disable; }
    QAction* monitorAction() const { return m_monitor; }
    QAction* singleStepAction() const { return m_singleStep; }
    QAction* traceAction() const { return m_trace; }
    QAction* variableInputAction() const { return m_variableInput; }
    QAction* stepAction() const { return m_step; }
    QAction* continueAction() const { return m_continue; }

    // Drive > Run label...: offers the labels of the program in the current editor (any other number can be
    // typed) without blocking; returns the open dialog.
    RunLabelDialog* askRunLabel();
    // RUN [label] as typed at the prompt (label < 0: RUN alone).
    void run(int label);

private:
    QAction* make(const QString& text, const QString& tip, const QString& shortcut, const QString& name);
    void command(const QString& line);
    void raw(const QByteArray& bytes);
    void breakOrKill(const QString& letter);
    void setSingleStep(bool on);
    void setTrace(bool on);
    void updateEnabled();
    void watchSession();
    void commandDone(quint64 id);
    serialport::Bds5Mode mode() const;

    MainWindow& m_window;
    QAction* m_run;
    QAction* m_break;
    QAction* m_stop;
    QAction* m_kill;
    QAction* m_enable;
    QAction* m_disable;
    QAction* m_monitor;
    QAction* m_singleStep;
    QAction* m_trace;
    QAction* m_variableInput;
    QAction* m_step;
    QAction* m_continue;
    // Raw bytes (RUN, Step) wait for the commands queued before them: the session passes raw bytes ahead
    // of its queue, but SS ON then RUN must reach the drive in that order.
    QSet<quint64> m_outstanding;
    serialport::Bds5Mode m_lastMode = serialport::Bds5Mode::Unknown;
    QByteArray m_deferred;
};

} // namespace app
