// Pmc960StatusDock: the PMC-960's status panel — servo mode, position, following error, velocity,
// distance to go and last label, the inputs IN07'-IN00' and outputs OUT07-OUT00 as round lights, and a
// command line. Fed by the session's out-of-band status polls (<attn> g f v i s b, digest §4.7), which
// never disturb command traffic and go on while a routine runs (issue 19); mode and outputs are read with SM!
// and OB! only while the line is idle.
// Paused while a program transfer runs. GUI thread only.
#pragma once

#include <QDockWidget>
#include <QTimer>

#include <array>

class QLabel;
class QLineEdit;

namespace serialport {
class Pmc960Session;
struct Pmc960Response;
} // namespace serialport

namespace app {

class Pmc960Light;

class Pmc960StatusDock final : public QDockWidget {
    Q_OBJECT
public:
    static constexpr int kPollMs = 150;    // one status letter per tick, round robin
    static constexpr int kIdleReadMs = 500; // SM! and OB! while the session is idle
    static constexpr int kLights = 8;

    explicit Pmc960StatusDock(QWidget* parent = nullptr);

    // The session to watch (nullptr while disconnected: the panel shows dashes).
    void setSession(serialport::Pmc960Session* session);
    // While true (a download or upload runs) nothing is polled or read.
    void setPaused(bool paused);

    // What the panel shows, for tests and the tour: "position", "following", "velocity", "mode", "togo",
    // "label", "inputs" (hex), "outputs" (hex).
    QString value(const QString& key) const;
    // Sends an MPL command typed in the command line ("SM2", "I4000+"); a trailing CR is added unless the
    // command ends in a display or sync character. The reply appears under the line.
    void sendCommand(const QString& command);
    QString lastReply() const;

private:
    void onPolled(char letter, const QString& value);
    void onFinished(quint64 id, const serialport::Pmc960Response& response);
    void readIdle();
    void updatePolling();
    void clear();
    void setLights(std::array<Pmc960Light*, kLights>& lights, int bits, const QString& key);

    serialport::Pmc960Session* m_session = nullptr;
    QLabel* m_mode;
    QLabel* m_position;
    QLabel* m_following;
    QLabel* m_velocity;
    QLabel* m_toGo;
    QLabel* m_label;
    QLineEdit* m_command;
    QLabel* m_reply;
    std::array<Pmc960Light*, kLights> m_inputs{};
    std::array<Pmc960Light*, kLights> m_outputs{};
    QTimer m_idleRead;
    quint64 m_modeRead = 0;
    quint64 m_outputsRead = 0;
    quint64 m_commandSent = 0;
    bool m_paused = false;
};

} // namespace app
