// Bds5DriveSession: the BDS5 behind the one DriveSession contract — a Bds5Session with its verified
// download (read back + P CHECKSUM, bds5_download.h), its upload (<BDS), RUN and ^X.
#pragma once

#include "bds5_session.h"
#include "bds5_transfer.h"
#include "drive_session.h"

#include <QPointer>

namespace serialport {

class Bds5DriveSession final : public DriveSession {
    Q_OBJECT
public:
    explicit Bds5DriveSession(Link& link, QObject* parent = nullptr);

    drive_core::DriveFamily family() const override { return drive_core::DriveFamily::Bds5; }
    bool isReady() const override { return m_session.state() == Bds5Session::State::Ready; }
    quint64 sendLine(const QString& line) override;
    quint64 sendQuiet(const QString& line) override;
    void download(const QString& programText) override;
    void upload() override;
    void cancelTransfer() override;
    void run(const QString& label) override;
    void stop() override;

    // The BDS5's own session, for what only it has (RECORD/PLAY, .VAR files).
    Bds5Session& bds5() { return m_session; }

    static TransferResult toResult(const Bds5TransferResult& r, int linesSent);

private:
    void watch(Bds5Transfer* transfer, int linesSent);
    void onRunBytes(const QByteArray& bytes);

    Bds5Session m_session;
    QPointer<Bds5Transfer> m_transfer;
    bool m_runStarted = false; // the echo of RUN came
    bool m_running = false; // RUN sent: the program's output is followed until the prompt comes back
    QByteArray m_runBytes;
    QByteArray m_runEcho;
    QString m_runError; // the drive's ERR line while the program ran
};

} // namespace serialport
