// servodesk-cli's engine: opens one connection (a fresh simulated drive, or a port) and runs the commands
// in order through the same session and transfers as the IDE. Event-driven: main() runs the event loop
// and exits with done()'s code. stdout carries machine-readable output, stderr progress and reasons.
#pragma once

#include "cli_options.h"

#include "serialport/bds5_session.h"
#include "serialport/link.h"

#include <QByteArray>
#include <QObject>
#include <QTimer>

#include <memory>

namespace serialport {
class Bds5Transfer;
struct Bds5TransferResult;
} // namespace serialport

namespace app::cli {

class CliRunner final : public QObject {
    Q_OBJECT
public:
    explicit CliRunner(CliOptions options, QObject* parent = nullptr);
    ~CliRunner() override;

    void start();

    enum ExitCode { kOk = 0, kDriveError = 1, kUsage = 2, kNoAnswer = 3 };

signals:
    void done(int exitCode);

private:
    void connectDrive();
    void next();
    void fail(int code, const QString& reason);
    void out(const QString& text);
    void progress(const QString& text);

    void check(const CliCommand& c);
    void transfer(const CliCommand& c);
    void sendLines(const QStringList& lines, int index);
    void run(const CliCommand& c);
    void stop();
    void record(const CliCommand& c);
    void play(const CliCommand& c);
    void watchTransfer(serialport::Bds5Transfer* transfer, const CliCommand& c);
    void transferDone(const CliCommand& c, const serialport::Bds5TransferResult& result);

    CliOptions m_options;
    std::size_t m_next = 0;
    std::unique_ptr<serialport::Link> m_link;
    std::unique_ptr<serialport::Bds5Session> m_session;
    QByteArray m_raw; // what the drive sent while a run is followed
    QTimer m_deadline;
    bool m_following = false;
    bool m_failed = false;
    bool m_progressOnTty = false;
    double m_speed = 1; // simulated seconds per wall second
};

} // namespace app::cli
