// Simulated-drive worker: 1 ms drive ticks paced to the wall clock, baud-paced transmit.
#include "simulator_worker.h"

#include "drive_core/drive_factory.h"
#include "drive_core/multidrop_bus.h"
#include "drive_core/pmc960/pmc960_drive.h"

#include <algorithm>

namespace serialport {

namespace {
constexpr auto kTick = std::chrono::microseconds(1000);
constexpr int kMaxTicksPerWake = 200; // after a stall, catch up at most this much at once
} // namespace

SimulatorWorker::SimulatorWorker(drive_core::DriveFamily family, SimulatorLink::Options options,
                                 std::shared_ptr<std::atomic<double>> clock)
    : m_family(family), m_options(options), m_driveClockMs(std::move(clock)) {}

SimulatorWorker::~SimulatorWorker() = default;

void SimulatorWorker::start() {
    if (!m_options.axes.empty()) {
        std::string why;
        m_drive = drive_core::MultidropBus::make(m_family, m_options.axes, why);
        if (!m_drive) return emit failed(QString::fromStdString(why));
    } else {
        m_drive = drive_core::makeDrive(m_family);
    }
    if (!m_drive) {
        emit failed(tr("No simulator for the %1 yet").arg(QString::fromLatin1(drive_core::familyName(m_family))));
        return;
    }
    m_drive->setLineRateLimited(m_options.lineRateLimited);
    if (auto* pmc = dynamic_cast<drive_core::pmc960::Pmc960Drive*>(m_drive.get()); pmc && m_options.overrunModel) {
        pmc->setOverrunModel(true);
        m_overrunDrive = pmc;
    }
    m_drive->powerUp();
    m_clock.start();
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &SimulatorWorker::tick);
    m_timer->start(1);
    tick();
}

void SimulatorWorker::receive(const QByteArray& bytes) {
    if (!m_drive) return;
    if (m_overrunDrive && m_options.hardwareFlowControl) {
        m_held += bytes;
        sendWhileClear();
    } else {
        m_drive->receive(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    }
    // Answer at once instead of at the next 1 ms tick: the drive handles its input without time passing.
    m_drive->step(std::chrono::microseconds(0));
    const std::string out = m_drive->takeTransmitted();
    if (!out.empty()) emit transmitted(QByteArray(out.data(), qsizetype(out.size())));
}

// Every family's drive has its bench (issue 20, item 15: the fallback for one without was never reached).
drive_core::SimulatorControls* SimulatorWorker::controls() {
    return m_drive ? m_drive->controls() : nullptr;
}

void SimulatorWorker::control(const std::function<void(drive_core::SimulatorControls&)>& change) {
    drive_core::SimulatorControls* bench = controls();
    if (!bench) return;
    change(*bench);
    // An input may fire an alarm at once: let the drive see it before the status goes out.
    m_drive->step(std::chrono::microseconds(0));
    const std::string out = m_drive->takeTransmitted();
    if (!out.empty()) emit transmitted(QByteArray(out.data(), qsizetype(out.size())));
    reportStatus();
}

// A UART with RTS/CTS starts a byte only while CTS is on and the byte before has gone: one byte at a time,
// so none lands on a full buffer.
void SimulatorWorker::sendWhileClear() {
    if (!m_overrunDrive || !m_options.hardwareFlowControl || m_held.isEmpty()) return;
    if (!m_overrunDrive->clearToSend() || !m_overrunDrive->lineIdle()) return;
    m_overrunDrive->receive(std::string_view(m_held.constData(), 1));
    m_held.remove(0, 1);
}

void SimulatorWorker::reportStatus() {
    if (drive_core::SimulatorControls* bench = controls()) emit statusChanged(bench->status());
}

void SimulatorWorker::tick() {
    const qint64 wallUs = m_clock.nsecsElapsed() / 1000;
    const qint64 wallDeltaUs = wallUs - m_lastWallUs;
    m_lastWallUs = wallUs;
    m_simulatedUs += double(wallDeltaUs) * m_options.speedFactor;
    int ticks = 0;
    while (double(m_drive->now().count()) + double(kTick.count()) <= m_simulatedUs && ticks < kMaxTicksPerWake) {
        sendWhileClear();
        m_drive->step(kTick);
        ++ticks;
    }
    if (ticks == kMaxTicksPerWake) m_simulatedUs = double(m_drive->now().count()); // drop the lost time
    // The drive's own UART sends at its BAUD rate: what it has sent is on the wire now. Its clock is
    // published after, so a session that reads the clock finds what came before it already posted.
    const std::string out = m_drive->takeTransmitted();
    if (!out.empty()) emit transmitted(QByteArray(out.data(), qsizetype(out.size())));
    m_driveClockMs->store(double(m_drive->now().count()) / 1000.0, std::memory_order_release);
    if (wallUs - m_lastStatusUs >= SimulatorLink::kStatusIntervalMs * 1000) {
        m_lastStatusUs = wallUs;
        reportStatus();
    }
}

} // namespace serialport
