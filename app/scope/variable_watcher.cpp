// VariableWatcher: P polls, one at a time, into a rolling window.
#include "variable_watcher.h"

#include "drive_connection.h"
#include "scope_catalog.h"
#include "transfer_dialog.h"

#include "serialport/bds5_session.h"
#include "serialport/bds5_transfer.h"

namespace app {

namespace {
constexpr int kRetryMs = 250;    // while paused
constexpr int kRateSamples = 10; // the rate is measured over the last ten answers

std::optional<double> valueOf(const QString& word) {
    if (word.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0) return 1;
    if (word.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0) return 0;
    bool ok = false;
    const double v = word.toDouble(&ok);
    return ok ? std::optional<double>(v) : std::nullopt;
}
} // namespace

VariableWatcher::VariableWatcher(DriveConnection& connection, QObject* parent)
    : QObject(parent), m_connection(connection), m_store(100'000) {
    m_retry.setInterval(kRetryMs);
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &VariableWatcher::poll);
}

QString VariableWatcher::rateText() const {
    if (m_paused) return tr("polled, paused: the drive is not at an interactive prompt");
    return tr("polled, %1 samples/s").arg(m_rate_hz, 0, 'f', 1);
}

void VariableWatcher::start() {
    if (m_variables.isEmpty()) return emit message(tr("Choose at least one variable to watch."));
    m_store = scope::SeriesStore(100'000);
    for (const QString& name : m_variables)
        m_store.addChannel(name.toStdString(), unitOf(name.toUpper().toStdString()));
    m_rate_hz = 0;
    m_pollId = 0;
    m_running = true;
    m_paused = false;
    m_clock.start();
    emit stateChanged();
    poll();
}

void VariableWatcher::stop() {
    m_running = false;
    m_paused = false;
    m_retry.stop();
    m_pollId = 0; // an answer still on its way is ignored
    emit stateChanged();
}

void VariableWatcher::setPaused(bool paused) {
    if (paused == m_paused) return;
    m_paused = paused;
    emit stateChanged();
}

void VariableWatcher::poll() {
    if (!m_running || m_pollId) return;
    serialport::Bds5Session* session = m_connection.session();
    // At an interactive prompt only: not while a program runs, a transfer (RECORD/PLAY, download) is under
    // way, or the link is down. The retry timer looks again.
    const bool ready = session && m_connection.isConnected() && session->mode() == serialport::Bds5Mode::Interactive &&
                       !TransferDialog::active();
    setPaused(!ready);
    if (!ready) return m_retry.start();
    connect(session, &serialport::Bds5Session::finished, this, &VariableWatcher::onAnswer, Qt::UniqueConnection);
    connect(session, &serialport::Bds5Session::failed, this, &VariableWatcher::onFailed, Qt::UniqueConnection);
    m_sentAt_s = double(m_clock.nsecsElapsed()) / 1e9;
    m_pollId =
        session->send(QStringLiteral("P ") + m_variables.join(QLatin1Char(' ')), serialport::Bds5Session::Echo::Quiet);
}

void VariableWatcher::onAnswer(quint64 id, const serialport::Bds5Response& response) {
    if (id != m_pollId || !m_running) return;
    m_pollId = 0;
    if (!response.errors.isEmpty()) {
        stop();
        return emit message(
            tr("Watching stopped: the drive answered %1").arg(serialport::describeError(response.errors.first())));
    }
    const QStringList words = response.lines.join(QLatin1Char(' ')).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if (words.size() >= m_variables.size() && !response.garbled) {
        const double t = (m_sentAt_s + double(m_clock.nsecsElapsed()) / 1e9) / 2;
        bool all = true;
        for (int i = 0; i < m_variables.size(); ++i) all = all && valueOf(words[i]).has_value();
        if (all) {
            for (int i = 0; i < m_variables.size(); ++i) m_store.append(std::size_t(i), {t, *valueOf(words[i])});
            m_store.dropBefore(t - kWindow_s);
            const auto& s = m_store.channel(0).samples;
            const std::size_t n = std::min<std::size_t>(s.size(), kRateSamples);
            if (n >= 2) m_rate_hz = double(n - 1) / (s.back().time_s - s[s.size() - n].time_s);
            emit sampled(t);
        }
    }
    poll();
}

void VariableWatcher::onFailed(quint64 id, const QString& reason) {
    if (id != m_pollId) return;
    m_pollId = 0;
    emit message(tr("A poll failed: %1").arg(reason));
    if (m_running) m_retry.start();
}

} // namespace app
