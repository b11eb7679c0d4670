// Pmc960RoutineRunner: MPL > Run Routine. Asks for a label of the editor's program (Pmc960RunDialog), then
// types B<label> CR at the controller's prompt as the Terminal does — SM2 CR first when asked, once its prompt
// is back — so the routine's output shows in the Terminal. A refusal of B<label> itself (#C2 label undefined) is
// said in the status bar and the Terminal with what to do; an error inside the routine (#B6 servo not enabled at
// its move) is placed in the program: the controller's SB& (last label, commands since) followed through the
// downloaded text names the command and its line (drive_core/pmc960/pmc960_error_place.h), said here and given
// to the error log (programFailed). A B<label> the user types in the Terminal is followed the same way (hello.mpl
// says to type BH), without the messages a run from the dialog gets when it ends well. GUI thread only.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QPointer>
#include <QStringList>

namespace serialport {
struct Pmc960Response;
}

namespace app {

class Pmc960RunDialog;
class Pmc960Workspace;

// A routine stopped on an error inside its program, as the error log shows it.
struct Pmc960ProgramStop {
    int code = 0;       // the controller's #xx
    QString detail;     // "I2048+, in routine H"; "routine H" when the command is not known
    int editorLine = 0; // 1-based line of the program's editor (Pmc960ProgramTransfer), 0 when not known
};

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
    // The last thing said about a run ("Routine H ended.", a refusal with its hint, where it stopped).
    QString lastMessage() const { return m_lastMessage; }

    // From the workspace, for every #xx at the prompt: true when it answered our SM2 or B<label> (then it is
    // said here, with the hint), false when it is someone else's.
    bool explainRefusal(int code);
    // The #xx at the prompt of our B<label> ended the routine inside its program (anything but B's own refusal):
    // the runner reports it, placed, through programFailed(); the error log leaves it to that.
    bool isProgramError(int code) const;
    // The session's shownReceived bytes: a prompt ends the step on the line.
    void onShown(const QByteArray& bytes);
    // Bytes typed in the Terminal (before they go out): a line B<label> CR, typed while no run of ours is on the
    // line, is followed as a run.
    void noteTyped(const QByteArray& bytes);
    // Forget the run (Stop, or the link closed): its prompt is no longer ours to wait for. A stop being placed
    // is reported as it is.
    void reset();

signals:
    // The run ended at the prompt: error 0, or the controller's #xx (SM2's or B<label>'s refusal, or the error
    // that stopped the routine, once placed).
    void finished(QChar label, int error);
    // The routine stopped on an error inside its program; emitted before finished().
    void programFailed(const app::Pmc960ProgramStop& stop);

private:
    void sendNext();
    void stepDone();
    void say(const QString& text);
    bool refusedByB(int code) const;
    void readPlace();
    void onPlaceRead(quint64 id, const serialport::Pmc960Response& response);
    void onPlaceFailed(quint64 id, const QString& reason);
    void reportStop(const QString& sb, const QString& unread);

    Pmc960Workspace& m_workspace;
    QPointer<Pmc960RunDialog> m_dialog;
    QChar m_label;
    QStringList m_steps; // typed lines still to send: "SM2", "BH"
    QByteArray m_onLine; // the typed line whose prompt is awaited, empty when none
    QByteArray m_shown;  // what the controller said since it was typed
    bool m_promptSeen = false;
    bool m_typed = false;    // the B<label> on the line was typed in the Terminal
    QByteArray m_typedLine;  // the Terminal's line being typed
    int m_refused = 0;       // SM2's or B<label>'s own refusal
    int m_stopped = 0;       // the error that ended the routine inside its program
    quint64 m_placeRead = 0; // the SB& request, 0 when none is out
    QString m_lastMessage;
};

} // namespace app
