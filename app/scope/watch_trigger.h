// WatchTrigger: oscilloscope triggering of the polled watch. Each sample VariableWatcher takes (one value per
// watched channel) goes into a scope::Trigger, a SampleRing under it; a frame — the pre-trigger samples, the
// trigger sample, the rest — is handed on whole. Single stops the polls after its frame. Sample times are the
// watcher's; Auto's time-out counts them, not the wall clock. GUI thread only.
#pragma once

#include "scope/trigger.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>

namespace app {

class VariableWatcher;

class WatchTrigger final : public QObject {
    Q_OBJECT
public:
    enum class Status {
        Off,       // no trigger: the rolling chart
        Stopped,   // not armed (Single after its frame, Stop, settings that cannot work)
        Armed,     // taking the pre-trigger samples
        Waiting,   // waiting for the condition
        Triggered, // taking the samples after the trigger
        Auto,      // Auto mode, the last frame forced by the time-out
    };

    explicit WatchTrigger(VariableWatcher& watcher, QObject* parent = nullptr);

    // nullopt: off. Takes effect at the next arm().
    void setSettings(const std::optional<scope::TriggerSettings>& settings) { m_settings = settings; }
    const std::optional<scope::TriggerSettings>& settings() const { return m_settings; }
    // Starts again over the watcher's channels (call after the watcher's start()); no-op when off.
    void arm();
    void stop();

    Status status() const;
    QString statusText() const; // "Waiting for PFB rising through 500", as the view shows it
    const std::optional<scope::TriggerFrame>& lastFrame() const { return m_last; }
    int frameCount() const { return m_frames; } // since arm()

signals:
    void frameReady(const scope::TriggerFrame& frame);
    void statusChanged();

private:
    void onSampled(double time_s);
    QString sourceName() const;

    VariableWatcher& m_watcher;
    std::optional<scope::TriggerSettings> m_settings;
    std::unique_ptr<scope::Trigger> m_trigger; // null when off or never armed
    std::optional<scope::TriggerFrame> m_last;
    QString m_error; // why the last arm() failed
    int m_frames = 0;
};

} // namespace app
