// Trigger: the condition on each fed sample, the state machine Filling -> Armed -> Collecting -> (frame).
#include "trigger.h"

#include <algorithm>
#include <cmath>

namespace scope {

Trigger::Trigger(std::size_t channelCount, const TriggerSettings& settings)
    : m_settings(settings), m_error(validate(settings, channelCount)),
      m_ring(m_error.empty() ? settings.frameLength : 1, channelCount) {
    if (!m_error.empty()) return;
    const double pre = std::round(double(settings.frameLength) * settings.preTrigger_pct / 100);
    m_pre = std::min(std::size_t(pre), settings.frameLength - 1);
    arm();
}

std::string Trigger::validate(const TriggerSettings& s, std::size_t channelCount) {
    if (channelCount == 0) return "no channels to trigger on";
    if (s.channel >= channelCount)
        return "trigger channel " + std::to_string(s.channel + 1) + " of " + std::to_string(channelCount);
    if (s.frameLength < 2) return "a frame needs at least 2 samples";
    if (!(s.preTrigger_pct >= 0 && s.preTrigger_pct <= 100)) return "the pre-trigger must be 0 to 100 %";
    if (s.kind == TriggerKind::Level && !std::isfinite(s.level)) return "the trigger level must be a number";
    if (s.kind == TriggerKind::Level && !(s.hysteresis >= 0 && std::isfinite(s.hysteresis)))
        return "the hysteresis must be 0 or more";
    if (s.kind == TriggerKind::Edge && !(s.minStep > 0 && std::isfinite(s.minStep)))
        return "an edge trigger needs a step greater than 0";
    if (s.mode == TriggerMode::Auto && !(s.autoTimeout_s > 0 && std::isfinite(s.autoTimeout_s)))
        return "auto mode needs a time-out greater than 0";
    return {};
}

void Trigger::arm() {
    if (!m_error.empty()) return;
    m_ring.clear();
    m_previous.reset();
    m_wasBelow = m_wasAbove = false;
    m_armedAt_s.reset();
    m_state = State::Filling;
}

void Trigger::stop() {
    m_state = State::Stopped;
}

bool Trigger::conditionMet(double value) {
    const TriggerSettings& s = m_settings;
    bool up = false, down = false;
    if (s.kind == TriggerKind::Level) {
        // A crossing clears its flag whether or not it triggers, so a crossing missed while not armed
        // cannot fire later without a new excursion.
        up = m_wasBelow && value >= s.level;
        down = m_wasAbove && value <= s.level;
        if (value >= s.level) m_wasBelow = false;
        if (value < s.level - s.hysteresis) m_wasBelow = true;
        if (value <= s.level) m_wasAbove = false;
        if (value > s.level + s.hysteresis) m_wasAbove = true;
    } else if (m_previous) {
        up = value - *m_previous >= s.minStep;
        down = *m_previous - value >= s.minStep;
    }
    m_previous = value;
    switch (s.slope) {
    case TriggerSlope::Rising: return up;
    case TriggerSlope::Falling: return down;
    case TriggerSlope::Either: return up || down;
    }
    return false;
}

std::optional<TriggerFrame> Trigger::feed(double time_s, std::span<const double> values) {
    if (m_state == State::Stopped) return std::nullopt;
    if (!std::isfinite(time_s) || (m_ring.size() > 0 && time_s < m_ring.time(m_ring.size() - 1))) {
        ++m_refused;
        return std::nullopt;
    }
    const std::size_t held = m_ring.size(); // samples before this one
    m_ring.push(time_s, values);
    const bool met = conditionMet(m_settings.channel < values.size() ? values[m_settings.channel] : 0.0);

    if (m_state == State::Collecting) {
        --m_postLeft;
    } else {
        if (!m_armedAt_s) m_armedAt_s = time_s;
        if (m_state == State::Filling && held >= m_pre) m_state = State::Armed;
        if (m_state == State::Armed) {
            const bool timedOut =
                m_settings.mode == TriggerMode::Auto && time_s - *m_armedAt_s >= m_settings.autoTimeout_s;
            if (met || timedOut) {
                m_state = State::Collecting;
                m_forced = !met;
                m_triggerSample = m_ring.pushed() - 1;
                m_trigger_s = time_s;
                m_postLeft = m_settings.frameLength - m_pre - 1;
            }
        }
    }
    if (m_state != State::Collecting || m_postLeft > 0) return std::nullopt;

    TriggerFrame f = frame();
    if (m_settings.mode == TriggerMode::Single) {
        m_state = State::Stopped;
    } else {
        m_state = State::Armed; // the ring is full: the pre-trigger part is there already
        m_armedAt_s.reset();
    }
    return f;
}

std::vector<TriggerFrame> Trigger::feed(std::span<const double> times_s, std::span<const double> interleaved) {
    std::vector<TriggerFrame> frames;
    const std::size_t channels = m_ring.channelCount();
    const std::size_t n = std::min(times_s.size(), interleaved.size() / channels);
    for (std::size_t i = 0; i < n; ++i)
        if (auto f = feed(times_s[i], interleaved.subspan(i * channels, channels))) frames.push_back(std::move(*f));
    return frames;
}

TriggerFrame Trigger::frame() const {
    // The ring holds exactly the frame now: pre + 1 + post = frameLength = its capacity.
    TriggerFrame f;
    f.triggered = !m_forced;
    f.triggerSample = m_triggerSample;
    f.trigger_s = m_trigger_s;
    f.triggerIndex = m_pre;
    const std::size_t n = m_ring.size();
    f.time_s.resize(n);
    f.values.assign(m_ring.channelCount(), std::vector<double>(n));
    for (std::size_t i = 0; i < n; ++i) {
        f.time_s[i] = m_ring.time(i);
        for (std::size_t c = 0; c < m_ring.channelCount(); ++c) f.values[c][i] = m_ring.value(i, c);
    }
    return f;
}

} // namespace scope
