// InProcessDriveLink: a drive_core drive on the test's own thread behind the Link interface, so that a
// campaign can look into the drive afterwards (the program image an SC750 loaded, the program a PMC-960
// holds) — what SimulatorLink, with its drive in a worker thread, does not offer. No wire: bytes cross at
// once; the drive steps 1 ms per elapsed millisecond on a timer. baudRate() is what the sessions derive
// their time-outs from. Every write is logged with the drive's time (driveMs) when it reached the drive.
// Test helper; GUI thread.
#pragma once

#include "serialport/link.h"

#include "drive_core/drive_factory.h"

#include <QElapsedTimer>
#include <QList>
#include <QTimer>

#include <functional>
#include <memory>

class InProcessDriveLink final : public serialport::Link {
public:
    InProcessDriveLink(drive_core::DriveFamily family, int baudRate)
        : m_drive(drive_core::makeDrive(family)), m_baud(baudRate) {
        m_drive->setLineRateLimited(false);
        m_timer.setInterval(1);
        connect(&m_timer, &QTimer::timeout, this, [this] { tick(); });
    }

    void open() override {
        if (m_open) return;
        m_open = true;
        m_drive->powerUp();
        m_clock.start();
        m_timer.start();
        QTimer::singleShot(0, this, [this] {
            emit opened();
            deliver();
        });
    }
    void close() override {
        if (!m_open) return;
        m_open = false;
        m_timer.stop();
        emit closed();
    }
    bool isOpen() const override { return m_open; }
    void write(const QByteArray& bytes) override {
        if (!m_open) return;
        m_writes.append({m_steppedMs, bytes});
        m_drive->receive(std::string_view(bytes.constData(), std::size_t(bytes.size())));
        m_drive->step(std::chrono::microseconds(0));        // the drive answers without time passing, as in the worker
        QTimer::singleShot(0, this, [this] { deliver(); }); // never from inside write()
        if (afterWrite) afterWrite(bytes);
    }
    // Called at the end of each write, once the drive has the bytes and before it answers. With holdAnswers
    // set there, a test acts from the event loop while those bytes are in flight (a stop pressed while a
    // line is on its way) and lets the answers through afterwards.
    std::function<void(const QByteArray&)> afterWrite;
    bool holdAnswers = false;
    QString description() const override { return QStringLiteral("in-process drive"); }
    int baudRate() const override { return m_baud; }
    int quietMs() const override { return 4; }

    drive_core::Drive& drive() { return *m_drive; }
    // Milliseconds the drive has been stepped since open().
    qint64 driveMs() const { return m_steppedMs; }
    struct Write {
        qint64 driveMs = 0;
        QByteArray bytes;
    };
    const QList<Write>& writes() const { return m_writes; }
    // Everything written from the index-th write on.
    QByteArray writtenFrom(qsizetype index) const {
        QByteArray all;
        for (qsizetype i = index; i < m_writes.size(); ++i) all += m_writes.at(i).bytes;
        return all;
    }

private:
    void tick() {
        constexpr int kMaxSteps = 50; // after a stall, catch up this much at once and drop the rest
        const qint64 due = m_clock.elapsed();
        for (int i = 0; i < kMaxSteps && m_steppedMs < due; ++i, ++m_steppedMs)
            m_drive->step(std::chrono::milliseconds(1));
        m_steppedMs = std::max(m_steppedMs, due - kMaxSteps);
        deliver();
    }
    void deliver() {
        if (!m_open || holdAnswers) return;
        const std::string out = m_drive->takeTransmitted();
        if (!out.empty()) emit bytesReceived(QByteArray(out.data(), qsizetype(out.size())));
    }

    std::unique_ptr<drive_core::Drive> m_drive;
    int m_baud;
    bool m_open = false;
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_steppedMs = 0;
    QList<Write> m_writes;
};
