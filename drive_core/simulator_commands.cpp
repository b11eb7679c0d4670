// runSimulatorCommand(): the bench's text form, one command a line, for servodesk-sim's control socket
// and tests. Grammar in simulator_controls.h; answers "OK", "ERROR <reason>" or the status line.
#include "simulator_controls.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <vector>

namespace drive_core {

namespace {
std::vector<std::string> words(std::string_view line) {
    std::vector<std::string> out;
    std::istringstream in{std::string(line)};
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// "on"/"off" (also 1/0, true/false); nullopt otherwise.
std::optional<bool> onOff(const std::string& word) {
    if (word == "on" || word == "1" || word == "true") return true;
    if (word == "off" || word == "0" || word == "false") return false;
    return std::nullopt;
}

std::optional<double> number(const std::string& word) {
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (word.empty() || end != word.c_str() + word.size()) return std::nullopt;
    return value;
}

std::string bits(const std::vector<bool>& values) {
    std::string s;
    for (const bool b : values) s += b ? '1' : '0';
    return s;
}

std::string format(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

const char* shapeName(MasterWaveShape shape) {
    switch (shape) {
    case MasterWaveShape::Sine: return "sine";
    case MasterWaveShape::Square: return "square";
    case MasterWaveShape::Triangle: return "triangle";
    case MasterWaveShape::None: break;
    }
    return "off";
}

// "off", or shape:amplitude_hz:frequency_hz.
std::string waveText(const MasterWave& w) {
    if (w.shape == MasterWaveShape::None) return "off";
    return std::string(shapeName(w.shape)) + ":" + format(w.amplitude_Hz) + ":" + format(w.frequency_Hz);
}

// One line of key=value pairs; inputs and outputs as bit strings, I1 / O1 first.
std::string statusLine(const SimulatorStatus& s) {
    return "inputs=" + bits(s.inputs) + " outputs=" + bits(s.outputs) + " enable=" + (s.enableInput ? "1" : "0") +
           " motion=" + (s.motionInput ? "1" : "0") + " home=" + (s.homeSwitch ? "1" : "0") +
           " limit_pos=" + (s.positiveLimit ? "1" : "0") + " limit_neg=" + (s.negativeLimit ? "1" : "0") +
           " active=" + (s.active ? "1" : "0") + " fault=" + (s.fault ? "1" : "0") +
           " position_rev=" + format(s.position_rev) + " velocity_rpm=" + format(s.velocity_rpm) +
           " current_a=" + format(s.current_a) + " load_torque_nm=" + format(s.loadTorque_Nm) +
           " load_inertia_kgm2=" + format(s.loadInertia_kgm2) +
           " coupling_nm_per_rad=" + format(s.couplingStiffness_NmPerRad) +
           " coupling_nms_per_rad=" + format(s.couplingDamping_NmPerRadPerS) +
           " resonance_hz=" + format(s.resonance_Hz) + " master_hz=" + format(s.masterFrequency_Hz) +
           " motor=" + s.motorName + " feedback=" + (s.feedbackConnected ? "1" : "0") +
           " relay=" + (s.relayClosed ? "1" : "0") + " brake_released=" + (s.brakeReleased ? "1" : "0") +
           " master_wave=" + waveText(s.masterWave) + " analog_in_v=" + format(s.analogInput_V) +
           " analog_out_v=" + format(s.analogOutput_V) + " enc_out_counts=" + std::to_string(s.encoderOutput_counts);
}

// The newest `seconds` of the monitor (all it holds when nullopt), signal last: its text has spaces.
std::string monitorLine(const MonitorTrace& t, std::optional<double> seconds) {
    std::size_t first = 0;
    if (seconds && t.interval_s > 0) {
        const auto wanted = std::size_t(std::max(0.0, *seconds) / t.interval_s);
        if (wanted < t.volts.size()) first = t.volts.size() - wanted;
    }
    const auto list = [first](const std::vector<float>& values) {
        std::string text;
        for (std::size_t i = first; i < values.size(); ++i) (text += i == first ? "" : ",") += format(values[i]);
        return text;
    };
    std::string line = "interval=" + format(t.interval_s) + " last=" + format(t.lastSample_s) + " volts=" + list(t.volts);
    if (!t.command.empty()) line += " command=" + list(t.command);
    line += " signal=" + t.signal;
    if (!t.command.empty()) line += " | command: " + t.commandSignal;
    return line;
}
} // namespace

std::string runSimulatorCommand(SimulatorControls& controls, std::string_view line) {
    const std::vector<std::string> w = words(line);
    if (w.empty()) return "ERROR empty command";
    const std::string& verb = w[0];
    const auto arity = [&](std::size_t n) { return w.size() == n + 1; };
    if (verb == "status" && arity(0)) return statusLine(controls.status());
    if (verb == "monitor" && w.size() <= 2) {
        const MonitorTrace trace = controls.analogMonitor();
        if (trace.volts.empty()) return "ERROR this drive has no analog monitor on the bench";
        if (w.size() == 1) return monitorLine(trace, std::nullopt);
        const auto seconds = number(w[1]);
        if (!seconds) return "ERROR expected a number";
        return monitorLine(trace, seconds);
    }
    if (verb == "power-cycle" && arity(0)) {
        controls.powerCycle();
        return "OK";
    }
    if (verb == "input" && arity(2)) {
        const auto n = number(w[1]);
        const auto state = onOff(w[2]);
        const int count = int(controls.status().inputs.size());
        if (!n || *n != double(int(*n)) || *n < 1 || *n > count)
            return "ERROR input number must be 1.." + std::to_string(count);
        if (!state) return "ERROR expected on or off";
        controls.setInput(int(*n), *state);
        return "OK";
    }
    if ((verb == "enable" || verb == "motion" || verb == "home" || verb == "feedback") && arity(1)) {
        const auto state = onOff(w[1]);
        if (!state) return "ERROR expected on or off";
        if (verb == "enable") controls.setEnableInput(*state);
        if (verb == "motion") controls.setMotionInput(*state);
        if (verb == "home") controls.setHomeSwitch(*state);
        if (verb == "feedback") controls.setFeedbackConnected(*state);
        return "OK";
    }
    if (verb == "limits" && arity(2)) {
        const auto positive = onOff(w[1]);
        const auto negative = onOff(w[2]);
        if (!positive || !negative) return "ERROR expected limits on|off on|off";
        controls.setLimitSwitches(*positive, *negative);
        return "OK";
    }
    if ((verb == "home-at" || verb == "load-torque" || verb == "load-inertia" || verb == "master-hz" ||
         verb == "analog-in") &&
        arity(1)) {
        const auto value = number(w[1]);
        if (!value) return "ERROR expected a number";
        if (verb == "load-inertia" && *value < 0) return "ERROR inertia must not be negative";
        if (verb == "home-at") controls.setHomeSwitchPosition_rev(*value);
        if (verb == "load-torque") controls.setLoadTorque_Nm(*value);
        if (verb == "load-inertia") controls.setLoadInertia_kgm2(*value);
        if (verb == "master-hz") controls.setMasterFrequency_Hz(*value);
        if (verb == "analog-in") controls.setAnalogInput_V(*value);
        return "OK";
    }
    // load-coupling NM_PER_RAD NMS_PER_RAD | load-coupling off (rigid)
    if (verb == "load-coupling" && (arity(1) || arity(2))) {
        if (arity(1) && w[1] != "off") return "ERROR expected load-coupling off or a stiffness and a damping";
        const auto stiffness = arity(1) ? std::optional<double>(0) : number(w[1]);
        const auto damping = arity(1) ? std::optional<double>(0) : number(w[2]);
        if (!stiffness || !damping) return "ERROR expected a number";
        if (*stiffness < 0 || *damping < 0) return "ERROR stiffness and damping must not be negative";
        return controls.setLoadCoupling(*stiffness, *damping) ? "OK" : "ERROR this drive has no load model";
    }
    // master-wave sine|square|triangle AMP_HZ FREQ_HZ | master-wave off
    if (verb == "master-wave" && (arity(1) || arity(3))) {
        MasterWave wave;
        if (arity(1)) {
            if (w[1] != "off") return "ERROR expected master-wave off or a shape, amplitude and frequency";
        } else {
            for (const auto shape : {MasterWaveShape::Sine, MasterWaveShape::Square, MasterWaveShape::Triangle})
                if (w[1] == shapeName(shape)) wave.shape = shape;
            if (wave.shape == MasterWaveShape::None) return "ERROR expected sine, square or triangle";
            const auto amplitude = number(w[2]);
            const auto frequency = number(w[3]);
            if (!amplitude || !frequency) return "ERROR expected a number";
            if (!(*frequency > 0)) return "ERROR wave frequency must be above 0";
            wave.amplitude_Hz = *amplitude;
            wave.frequency_Hz = *frequency;
        }
        return controls.setMasterWave(wave) ? "OK" : "ERROR this drive has no master waveform";
    }
    if (verb == "motor" && arity(1)) return controls.selectMotor(w[1]) ? "OK" : "ERROR unknown motor " + w[1];
    for (const char* known :
         {"status", "monitor", "power-cycle", "input", "enable", "motion", "home", "limits", "home-at", "load-torque",
          "load-inertia", "load-coupling", "master-hz", "master-wave", "analog-in", "motor", "feedback"})
        if (verb == known) return "ERROR wrong number of arguments for " + verb;
    return "ERROR unknown command " + verb;
}

} // namespace drive_core
