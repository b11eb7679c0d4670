// SimulatorLink: the GUI-thread face of a simulated drive running in a worker thread.
#include "simulator_link.h"

#include "simulator_worker.h"

#include "drive_core/drive_factory.h"

namespace serialport {

SimulatorLink::SimulatorLink(drive_core::DriveFamily family, Options options, QObject* parent)
    : Link(parent), m_family(family), m_options(options) {
    qRegisterMetaType<drive_core::SimulatorStatus>();
    m_thread.setObjectName(QStringLiteral("simulated-drive"));
}

SimulatorLink::~SimulatorLink() { close(); }

void SimulatorLink::open() {
    if (m_open) return;
    m_driveClockMs = std::make_shared<std::atomic<double>>(0.0);
    m_worker = new SimulatorWorker(m_family, m_options, m_driveClockMs);
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    // What the worker sent before close() stopped it may still wait in this thread's event queue: a closed
    // link (or one reopened since, with a new worker) delivers none of it, as a closed port reads nothing.
    // Passed on, the BDS5's last answer reached the terminal after the switch to another family (" RAMP").
    connect(m_worker, &SimulatorWorker::transmitted, this,
            [this, generation = ++m_generation](const QByteArray& bytes) {
                if (m_open && generation == m_generation) emit bytesReceived(bytes);
            });
    connect(m_worker, &SimulatorWorker::statusChanged, this, [this](const drive_core::SimulatorStatus& status) {
        m_status = status;
        emit simulatorStatus(status);
    });
    connect(m_worker, &SimulatorWorker::failed, this, [this](const QString& message) {
        emit errorOccurred(message);
        close();
    });
    m_thread.start();
    QMetaObject::invokeMethod(m_worker, &SimulatorWorker::start, Qt::QueuedConnection);
    m_open = true;
    emit opened();
}

std::optional<double> SimulatorLink::driveClockMs() const {
    if (!m_driveClockMs) return std::nullopt;
    return m_driveClockMs->load(std::memory_order_acquire);
}

void SimulatorLink::close() {
    if (!m_open) return;
    m_open = false;
    m_thread.quit();
    m_thread.wait();
    m_worker = nullptr;
    emit closed();
}

void SimulatorLink::write(const QByteArray& bytes) {
    if (!m_open || !m_worker) {
        emit errorOccurred(tr("The simulated drive is not running: nothing was sent"));
        return;
    }
    QMetaObject::invokeMethod(m_worker, [worker = m_worker, bytes] { worker->receive(bytes); }, Qt::QueuedConnection);
}

void SimulatorLink::control(std::function<void(drive_core::SimulatorControls&)> change) {
    if (!m_open || !m_worker || !change) return;
    QMetaObject::invokeMethod(
        m_worker, [worker = m_worker, change = std::move(change)] { worker->control(change); },
        Qt::QueuedConnection);
}

void SimulatorLink::readMonitor(std::function<void(const drive_core::MonitorTrace&)> done) {
    const quint64 generation = m_generation;
    // The worker runs while this link lives (the destructor waits for its thread), so `this` is safe to post
    // to; a call still queued when the link is deleted is dropped with it.
    control([this, generation, done = std::move(done)](drive_core::SimulatorControls& bench) {
        QMetaObject::invokeMethod(
            this,
            [this, generation, done, trace = bench.analogMonitor()] {
                if (m_open && generation == m_generation) done(trace);
            },
            Qt::QueuedConnection);
    });
}

QString SimulatorLink::description() const {
    const QString family = QString::fromLatin1(drive_core::familyName(m_family)).toUpper();
    if (m_options.axes.empty()) return tr("Simulated %1").arg(family);
    QStringList ids;
    for (const std::string& id : m_options.axes) ids << QString::fromStdString(id);
    return tr("Simulated %1 line (axes %2)").arg(family, ids.join(QLatin1Char(',')));
}

} // namespace serialport
