// Pmc960RoutineRunner: MPL > Run Routine. Asks for a label of the editor's program (Pmc960RunDialog), then
// types B<label> CR at the controller's prompt as the Terminal does — SM2 CR first when asked, once its prompt
// is back — so the routine's output shows in the Terminal. A refusal (#B6 servo not enabled, #C2 label
// undefined) is said in the status bar and the Terminal with what to do; the error log lists it as it lists
// any typed command's. GUI thread only.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QPointer>
#include <QStringList>

namespace app {

class Pmc960RunDialog;
class Pmc960Workspace;

class Pmc960RoutineRunner final : public QObject {
    Q_OBJECT
public:
    explicit Pmc960RoutineRunner(Pmc960Workspace& workspace);

    // Opens the dialog for the current editor's program (window-modal, not blocking); nullptr while
    // disconnected (said in the status bar).
    Pmc960RunDialog* ask();
    // Types SM2 CR (enableServoFirst) and B<label> CR, each after the previous one's prompt.
    void run(QChar label, bool enableServoFirst);
    // A typed SM2 or B<label> has not had its prompt yet.
    bool isRunning() const { return !m_onLine.isEmpty(); }
    // The last thing said about a run ("Routine H ended.", a refusal with its hint).
    QString lastMessage() const { return m_lastMessage; }

    // From the workspace, for every #xx at the prompt: true when it answered our SM2 or B<label> (then it was
    // said here, with the hint), false when it is someone else's.
    bool explainRefusal(int code);
    // The session's shownReceived bytes: a prompt ends the step on the line.
    void onShown(const QByteArray& bytes);
    // Forget the run (Stop, or the link closed): its prompt is no longer ours to wait for.
    void reset();

signals:
    // The run ended at the prompt: error 0, or the controller's #xx refusal of SM2 or B<label>.
    void finished(QChar label, int error);

private:
    void sendNext();
    void stepDone();
    void say(const QString& text);

    Pmc960Workspace& m_workspace;
    QPointer<Pmc960RunDialog> m_dialog;
    QChar m_label;
    QStringList m_steps; // typed lines still to send: "SM2", "BH"
    QByteArray m_onLine; // the typed line whose prompt is awaited, empty when none
    QByteArray m_shown;  // what the controller said since it was typed
    bool m_promptSeen = false;
    int m_refused = 0;
    QString m_lastMessage;
};

} // namespace app
