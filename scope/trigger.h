// Trigger: oscilloscope triggering of a continuous capture, widget-free. Samples (time + one value per
// channel) are fed one by one or in blocks into a SampleRing of frameLength samples; a condition on one
// channel picks the trigger sample, and a frame is the pre-trigger samples before it, it, and the rest
// after. Decisions:
// - Level: the channel passes through `level` -- rising: from below level - hysteresis to >= level;
//   falling: from above level + hysteresis to <= level; either. With hysteresis 0, rising is
//   prev < level <= value. Edge: a step between two consecutive samples of at least minStep
//   (rising value - prev >= minStep, falling prev - value >= minStep, either), whatever the level: a
//   command step, a digital input.
// - Pre-trigger: round(frameLength * pct / 100) samples, at most frameLength - 1; the trigger sample is
//   at that index of the frame. After arm() no trigger is taken until that many samples are in the ring,
//   so every frame is whole. Normal and Auto re-arm at the sample after a frame and keep the ring: the
//   next frame's pre-trigger part may overlap the previous frame's tail. A crossing during a frame is
//   not a trigger (not armed).
// - Modes: Single stops after one frame (arm() again for another); Normal re-arms after each frame;
//   Auto is Normal, but when autoTimeout_s of sample time (not wall clock) passes after arming with no
//   trigger, the current sample is taken as a forced trigger (frame.triggered = false).
// - Times must not go back; a sample older than the last is refused (counted, not stored).
// Settings are fixed for the object's life: make a new Trigger to change them. One thread at a time.
#pragma once

#include "sample_ring.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace scope {

enum class TriggerMode { Single, Normal, Auto };
enum class TriggerKind { Level, Edge };
enum class TriggerSlope { Rising, Falling, Either };

struct TriggerSettings {
    std::size_t channel = 0; // which of the fed channels
    TriggerKind kind = TriggerKind::Level;
    TriggerSlope slope = TriggerSlope::Rising;
    double level = 0;               // Level: in the channel's unit
    double hysteresis = 0;          // Level: >= 0, in the channel's unit (noise rejection)
    double minStep = 1;             // Edge: > 0, in the channel's unit
    std::size_t frameLength = 1000; // samples per frame, >= 2; also the ring's capacity
    double preTrigger_pct = 25;     // 0 .. 100 of frameLength
    TriggerMode mode = TriggerMode::Normal;
    double autoTimeout_s = 0.1; // Auto: > 0, in sample time
};

struct TriggerFrame {
    bool triggered = true;                   // false: forced by Auto's time-out
    std::uint64_t triggerSample = 0;         // absolute index of the trigger sample; 0 = the first fed after arm()
    double trigger_s = 0;                    // its time
    std::size_t triggerIndex = 0;            // its index in the frame: the number of pre-trigger samples
    std::vector<double> time_s;              // frameLength times, ascending
    std::vector<std::vector<double>> values; // [channel][sample], frameLength each
};

class Trigger {
public:
    enum class State {
        Filling,    // armed, waiting for the pre-trigger samples after arm()
        Armed,      // waiting for the trigger (or Auto's time-out)
        Collecting, // triggered, taking the post-trigger samples
        Stopped,    // Single after its frame, stop(), or invalid settings
    };

    // Starts armed (Filling) unless the settings are invalid (see error()).
    Trigger(std::size_t channelCount, const TriggerSettings& settings);

    // Why the settings cannot work, "" if they can.
    static std::string validate(const TriggerSettings& settings, std::size_t channelCount);
    const std::string& error() const { return m_error; }

    void arm(); // clears the ring and starts again (Single's next frame, or after stop()); no-op if invalid
    void stop();

    // values: one per channel. Returns the frame this sample completed, if any.
    std::optional<TriggerFrame> feed(double time_s, std::span<const double> values);
    // A block: times_s[i] with interleaved[i * channelCount + c]; extra values (a part sample) are ignored.
    std::vector<TriggerFrame> feed(std::span<const double> times_s, std::span<const double> interleaved);

    State state() const { return m_state; }
    const TriggerSettings& settings() const { return m_settings; }
    std::size_t preTriggerSamples() const { return m_pre; }
    const SampleRing& ring() const { return m_ring; }
    std::uint64_t refusedSamples() const { return m_refused; } // times that went back

private:
    bool conditionMet(double value);
    TriggerFrame frame() const;

    TriggerSettings m_settings;
    std::string m_error;
    SampleRing m_ring;
    std::size_t m_pre = 0;
    State m_state = State::Stopped;
    std::uint64_t m_refused = 0;

    std::optional<double> m_previous;  // the trigger channel's last value since arm()
    bool m_wasBelow = false;           // Level: below level - hysteresis since the last upward crossing
    bool m_wasAbove = false;           // Level: above level + hysteresis since the last downward crossing
    std::optional<double> m_armedAt_s; // Auto: time of the first sample after arming
    bool m_forced = false;
    std::uint64_t m_triggerSample = 0;
    double m_trigger_s = 0;
    std::size_t m_postLeft = 0; // Collecting: samples still to take after the trigger
};

} // namespace scope
