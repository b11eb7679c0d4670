// Pmc960DriveSession: the PMC-960 behind the one DriveSession contract — a Pmc960Session (MPL at the
// prompt) with its download verified by the communications checksum (pmc960_download.h), its upload (P!),
// B<label> to run a routine and ESC to stop.
#pragma once

#include "drive_session.h"
#include "pmc960_session.h"

#include <QPointer>

namespace serialport {

class Pmc960Download;

class Pmc960DriveSession final : public DriveSession {
    Q_OBJECT
public:
    explicit Pmc960DriveSession(Link& link, QObject* parent = nullptr);

    drive_core::DriveFamily family() const override { return drive_core::DriveFamily::Pmc960; }
    bool isReady() const override { return m_session.state() == Pmc960Session::State::Ready; }
    quint64 sendLine(const QString& line) override;
    void download(const QString& programText) override;
    void upload() override;
    void cancelTransfer() override;
    void run(const QString& label) override;
    void stop() override;

    Pmc960Session& pmc960() { return m_session; }

private:
    void onRunBytes(const QByteArray& bytes);

    Pmc960Session m_session;
    QPointer<Pmc960Download> m_download;
    quint64 m_run = 0;    // the B<label> request: its prompt comes when the routine ends
    QByteArray m_runEcho; // B<label> as the controller echoes it
    QByteArray m_runSeen; // what came since B<label> was written
    bool m_runStarted = false;
    bool m_stopping = false;
};

} // namespace serialport
