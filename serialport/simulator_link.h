// A Link to an in-process simulated drive. The drive runs in a worker thread, stepped in 1 ms ticks
// paced to the wall clock (times a speed factor); its own UART paces the bytes it sends.
#pragma once

#include "link.h"

#include "drive_core/drive.h"

#include <QThread>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace serialport {

class SimulatorWorker;

class SimulatorLink final : public Link {
    Q_OBJECT
public:
    struct Options {
        double speedFactor = 1.0;    // simulated seconds per wall-clock second
        int baudRate = 9600;         // the drive's BAUD: its UART paces what it sends; sessions time out by it
        bool lineRateLimited = true; // false: no wire, every byte crosses at once (fast tests, benchmarks)
        // PMC-960 only: the controller's one-character receive buffer overruns as the real one does
        // (Pmc960Drive::setOverrunModel, seed-pmc960 §9.6): bytes cross at the baud rate, and one that lands
        // while the firmware is busy overwrites the one before.
        bool overrunModel = false;
        // With overrunModel: this side's UART sends a byte only while the controller's CTS is on (RTS/CTS, as
        // SerialPortLink::FlowControl::Hardware). false: bytes go out back to back and may be lost.
        bool hardwareFlowControl = true;
        // A multidrop line of drives with these axis IDs, each in its family's form ("A", "B" or "1", "17";
        // drive_core::MultidropBus) instead of one drive; empty for one drive.
        std::vector<std::string> axes;
    };

    SimulatorLink(drive_core::DriveFamily family, Options options, QObject* parent = nullptr);
    explicit SimulatorLink(drive_core::DriveFamily family, QObject* parent = nullptr)
        : SimulatorLink(family, Options{}, parent) {}
    ~SimulatorLink() override;

    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    void write(const QByteArray& bytes) override;
    QString description() const override;
    int baudRate() const override { return m_options.baudRate; }
    // The worker hands bytes over every 1 ms tick: a few ticks of silence is a pause.
    int quietMs() const override { return 4; }
    std::optional<double> driveClockMs() const override;

    // The simulator's bench (inputs, load, motor, power), not its serial port: the change runs in the
    // worker thread before the drive's next step. Ignored while the link is closed. GUI thread.
    void control(std::function<void(drive_core::SimulatorControls&)> change);
    // The bench's oscilloscope: the drive's analog monitor output as recorded, newest last
    // (SimulatorControls::analogMonitor), handed to `done` in the GUI thread; empty volts when the drive has
    // none. Not called when the link is closed (or closes first).
    void readMonitor(std::function<void(const drive_core::MonitorTrace&)> done);
    // The latest bench snapshot (also sent by simulatorStatus() every kStatusIntervalMs while open).
    drive_core::SimulatorStatus lastStatus() const { return m_status; }
    static constexpr int kStatusIntervalMs = 100;

signals:
    void simulatorStatus(const drive_core::SimulatorStatus& status);

private:
    drive_core::DriveFamily m_family;
    Options m_options;
    QThread m_thread;
    SimulatorWorker* m_worker = nullptr; // lives in m_thread; deleted when the thread finishes
    bool m_open = false;
    std::shared_ptr<std::atomic<double>> m_driveClockMs; // this opening's drive, written by its worker
    quint64 m_generation = 0; // one per open(): bytes of an earlier worker are not this opening's
    drive_core::SimulatorStatus m_status;
};

} // namespace serialport

Q_DECLARE_METATYPE(drive_core::SimulatorStatus)
