// WatchTrigger: feeds the watcher's samples to the trigger and says where it stands.
#include "watch_trigger.h"

#include "variable_watcher.h"

#include <vector>

namespace app {

WatchTrigger::WatchTrigger(VariableWatcher& watcher, QObject* parent) : QObject(parent), m_watcher(watcher) {
    connect(&m_watcher, &VariableWatcher::sampled, this, &WatchTrigger::onSampled);
}

void WatchTrigger::arm() {
    m_trigger.reset();
    m_error.clear();
    m_frames = 0;
    if (!m_settings) return emit statusChanged();
    const std::size_t channels = m_watcher.store().channelCount();
    m_trigger = std::make_unique<scope::Trigger>(channels, *m_settings);
    m_error = QString::fromStdString(m_trigger->error());
    emit statusChanged();
}

void WatchTrigger::stop() {
    if (m_trigger) m_trigger->stop();
    emit statusChanged();
}

// Every channel got one sample at time_s: the newest of each is this sample's row.
void WatchTrigger::onSampled(double time_s) {
    if (!m_trigger || m_trigger->state() == scope::Trigger::State::Stopped) return;
    const scope::SeriesStore& store = m_watcher.store();
    std::vector<double> row;
    for (std::size_t c = 0; c < store.channelCount(); ++c) {
        const auto& samples = store.channel(c).samples;
        row.push_back(samples.empty() ? 0.0 : samples.back().value);
    }
    const auto before = m_trigger->state();
    if (std::optional<scope::TriggerFrame> frame = m_trigger->feed(time_s, row)) {
        m_last = std::move(*frame);
        ++m_frames;
        // Single: one frame, as a scope's Single stops acquiring; the polls stop with it.
        if (m_trigger->state() == scope::Trigger::State::Stopped) m_watcher.stop();
        emit frameReady(*m_last);
        emit statusChanged();
    } else if (m_trigger->state() != before || before == scope::Trigger::State::Filling) {
        emit statusChanged();
    }
}

WatchTrigger::Status WatchTrigger::status() const {
    if (!m_settings) return Status::Off;
    if (!m_trigger) return Status::Stopped;
    switch (m_trigger->state()) {
    case scope::Trigger::State::Filling: return Status::Armed;
    case scope::Trigger::State::Armed:
        return m_settings->mode == scope::TriggerMode::Auto && m_last && !m_last->triggered && m_frames > 0
                   ? Status::Auto
                   : Status::Waiting;
    case scope::Trigger::State::Collecting: return Status::Triggered;
    case scope::Trigger::State::Stopped: return Status::Stopped;
    }
    return Status::Stopped;
}

QString WatchTrigger::sourceName() const {
    const scope::SeriesStore& store = m_watcher.store();
    const std::size_t c = m_settings ? m_settings->channel : 0;
    return c < store.channelCount() ? QString::fromStdString(store.channel(c).name) : tr("channel %1").arg(c + 1);
}

QString WatchTrigger::statusText() const {
    if (!m_error.isEmpty()) return tr("Stopped: cannot arm, %1").arg(m_error);
    const Status s = status();
    if (s == Status::Off) return tr("Rolling: no trigger");
    const scope::TriggerSettings& t = *m_settings;
    const QString slope = t.slope == scope::TriggerSlope::Rising    ? tr("rising")
                          : t.slope == scope::TriggerSlope::Falling ? tr("falling")
                                                                    : tr("rising or falling");
    const QString condition = t.kind == scope::TriggerKind::Level
                                  ? tr("%1 %2 through %3").arg(sourceName(), slope).arg(t.level)
                                  : tr("%1 stepping %2 by %3 or more").arg(sourceName(), slope).arg(t.minStep);
    switch (s) {
    case Status::Off: break;
    case Status::Armed:
        return tr("Armed: pre-trigger %1 of %2 samples")
            .arg(m_trigger->ring().size())
            .arg(m_trigger->preTriggerSamples());
    case Status::Waiting:
        return m_frames > 0 ? tr("Waiting for %1 (frame %2 shown)").arg(condition).arg(m_frames)
                            : tr("Waiting for %1").arg(condition);
    case Status::Triggered: return tr("Triggered: taking the samples after it");
    case Status::Auto: return tr("Auto: no trigger for %1 s, frame %2 forced").arg(t.autoTimeout_s).arg(m_frames);
    case Status::Stopped:
        if (t.mode == scope::TriggerMode::Single && m_frames > 0)
            return tr("Stopped: Single frame taken, triggered by %1. Arm for another.").arg(condition);
        return tr("Stopped");
    }
    return {};
}

} // namespace app
