// Runs one simulated drive in its own thread: steps it against the wall clock, carries its UART bytes.
// Internal to SimulatorLink.
#pragma once

#include "simulator_link.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>

namespace drive_core::pmc960 {
class Pmc960Drive;
}

namespace serialport {

class SimulatorWorker final : public QObject {
    Q_OBJECT
public:
    // clock: where the worker publishes the drive's time in ms after each step (SimulatorLink::driveClockMs).
    SimulatorWorker(drive_core::DriveFamily family, SimulatorLink::Options options,
                    std::shared_ptr<std::atomic<double>> clock);
    ~SimulatorWorker() override;

    // Worker thread only (invoked through queued calls).
    void start();
    void receive(const QByteArray& bytes);
    // Applies a bench change (SimulatorLink::control), then reports the status at once.
    void control(const std::function<void(drive_core::SimulatorControls&)>& change);

signals:
    void transmitted(const QByteArray& bytes);
    void statusChanged(const drive_core::SimulatorStatus& status);
    void failed(const QString& message);

private:
    void tick();
    drive_core::SimulatorControls* controls();
    void reportStatus();
    void sendWhileClear(); // overrun model with flow control: one byte onto the wire while CTS is on

    drive_core::DriveFamily m_family;
    SimulatorLink::Options m_options;
    std::unique_ptr<drive_core::Drive> m_drive;
    drive_core::pmc960::Pmc960Drive* m_overrunDrive = nullptr;         // m_drive, when its overrun model is on
    QByteArray m_held;                                                 // written, held by CTS off
    qint64 m_lastStatusUs = 0;
    QTimer* m_timer = nullptr;
    QElapsedTimer m_clock;
    qint64 m_lastWallUs = 0;
    double m_simulatedUs = 0; // how far the drive should have got
    std::shared_ptr<std::atomic<double>> m_driveClockMs;
};

} // namespace serialport
