// Sc750DriveSession: the SC750 behind the one DriveSession contract — a Sc750Session (Motion Dialogue
// frames, PROTOCOL.md) with the compiler in front of its download: the source is compiled to a .BIN, the
// .BIN sent and checked by the drive's CRC-32 before it replaces its program, then the source stored in
// the controller's non-volatile memory (T/t/Q) so an upload (u) gives it back. The SC750 has no command
// line: sendLine() reads a variable ("POSITION"), writes one ("KVP=200") or calls a real-time function.
#pragma once

#include "drive_session.h"
#include "sc750_session.h"

#include <functional>
#include <map>

namespace serialport {

class Sc750Download;

class Sc750DriveSession final : public DriveSession {
    Q_OBJECT
public:
    explicit Sc750DriveSession(Link& link, QObject* parent = nullptr);

    drive_core::DriveFamily family() const override { return drive_core::DriveFamily::Sc750; }
    bool isReady() const override { return m_identified && !m_session.busy(); }
    quint64 sendLine(const QString& line) override;
    void download(const QString& programText) override;
    void upload() override;
    void cancelTransfer() override;
    void run(const QString& label) override;
    void stop() override;

    Sc750Session& sc750() { return m_session; }

private:
    using OnReply = std::function<void(const Sc750Reply&)>;
    using OnFail = std::function<void(const QString&)>;
    void request(char letter, const QString& payload, OnReply onReply, OnFail onFail);
    void storeSource(int offset);
    void askSource();
    void finishTransfer(TransferResult result);

    Sc750Session m_session;
    bool m_identified = false;
    std::map<quint64, std::pair<OnReply, OnFail>> m_requests; // this session's own frames
    std::map<quint64, QString> m_lines;                     // sendLine() frames: the line sent
    Sc750Download* m_download = nullptr;
    bool m_transferring = false;
    bool m_cancelled = false;
    QByteArray m_source;   // download: the text to store; upload: what came back so far
    QString m_verified;    // download: the CRC the drive checked
    bool m_running = false;
};

} // namespace serialport
