// VariableWatcher: polls, one at a time, into a rolling window.
#include "variable_watcher.h"

#include "watch_source.h"

namespace app {

namespace {
constexpr int kRetryMs = 250;    // while paused
constexpr int kRateSamples = 10; // the rate is measured over the last ten answers
} // namespace

VariableWatcher::VariableWatcher(WatchSource& source, QObject* parent)
    : QObject(parent), m_source(source), m_store(100'000) {
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &VariableWatcher::poll);
    connect(&m_source, &WatchSource::answered, this, &VariableWatcher::onAnswered);
    connect(&m_source, &WatchSource::failed, this, &VariableWatcher::onFailed);
}

QString VariableWatcher::rateText() const {
    if (isPaused()) return tr("polled, paused: %1").arg(m_pauseReason);
    return tr("polled, %1 samples/s").arg(m_rate_hz, 0, 'f', 1);
}

void VariableWatcher::start() {
    if (m_variables.isEmpty()) return emit message(tr("Choose at least one variable to watch."));
    if (m_polling) m_source.cancel();
    m_store = scope::SeriesStore(100'000);
    for (const QString& name : m_variables) {
        const auto choice = m_source.choice(name);
        m_store.addChannel((choice ? choice->label : name).toStdString(), choice ? choice->unit.toStdString() : "");
    }
    m_rate_hz = 0;
    m_polling = false;
    m_running = true;
    m_pauseReason.clear();
    m_clock.start();
    emit stateChanged();
    poll();
}

void VariableWatcher::stop() {
    m_running = false;
    m_pauseReason.clear();
    m_retry.stop();
    if (m_polling) m_source.cancel(); // an answer still on its way is ignored
    m_polling = false;
    emit stateChanged();
}

void VariableWatcher::setPauseReason(const QString& reason) {
    if (reason == m_pauseReason) return;
    m_pauseReason = reason;
    emit stateChanged();
}

void VariableWatcher::poll() {
    if (!m_running || m_polling) return;
    setPauseReason(m_source.notReady());
    if (isPaused()) return m_retry.start(kRetryMs);
    const double now_s = double(m_clock.nsecsElapsed()) / 1e9;
    const double wait_ms = (m_sentAt_s - now_s) * 1e3 + m_source.minimumIntervalMs();
    if (m_store.channel(0).samples.size() > 0 && wait_ms >= 1) return m_retry.start(int(wait_ms));
    m_sentAt_s = now_s;
    m_polling = true;
    m_source.poll(m_variables);
}

void VariableWatcher::onAnswered(const QList<double>& values) {
    if (!m_polling || !m_running) return;
    m_polling = false;
    if (values.size() == m_variables.size()) {
        const double t = (m_sentAt_s + double(m_clock.nsecsElapsed()) / 1e9) / 2;
        for (int i = 0; i < values.size(); ++i) m_store.append(std::size_t(i), {t, values[i]});
        m_store.dropBefore(t - kWindow_s);
        const auto& s = m_store.channel(0).samples;
        const std::size_t n = std::min<std::size_t>(s.size(), kRateSamples);
        if (n >= 2) m_rate_hz = double(n - 1) / (s.back().time_s - s[s.size() - n].time_s);
        emit sampled(t);
    }
    poll();
}

void VariableWatcher::onFailed(const QString& reason, bool stopWatching) {
    if (!m_polling) return;
    m_polling = false;
    if (stopWatching) {
        stop();
        return emit message(tr("Watching stopped: %1").arg(reason));
    }
    emit message(tr("A poll failed: %1").arg(reason));
    if (m_running) m_retry.start(kRetryMs);
}

} // namespace app
