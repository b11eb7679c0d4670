// The simulated SC750: power-up, the 0.427 ms tick, the serial port (logon, protocol, program I/O), the
// bench. Variables, motion, WHEN and interrupts for the VM are in sc750_drive_host.cpp.
#include "sc750_drive.h"

#include "sc750_bin.h"
#include "sc750_drive_index.h"
#include "sc750_frame.h"

#include <algorithm>
#include <cmath>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

namespace {
constexpr Microseconds kTick{427};       // 0.427 ms (L1972); TIME counts these ticks (L2048)
constexpr int kInstructionsPerTick = 40; // chosen: about 94,000 instructions a second
constexpr std::size_t kInputBuffer = 256;
constexpr char kCtrlC = 0x03;
} // namespace

Sc750Drive::Sc750Drive() : m_ix(&driveIndex()) {
    m_uart.reset(9600);
    powerUp();
}

void Sc750Drive::powerUp() {
    const auto vars = cat::variables();
    std::vector<Value> nv;
    const bool keep = !m_values.empty();
    if (keep) nv = m_values; // parameters are non-volatile (L2250-L2252)
    m_values.clear();
    for (const cat::VariableInfo& v : vars) {
        if (v.type == cat::ValueType::String)
            m_values.emplace_back(std::string());
        else if (v.type == cat::ValueType::Float)
            m_values.emplace_back(float(v.defaultValue));
        else
            m_values.emplace_back(std::int32_t(v.defaultValue));
    }
    if (keep)
        for (std::size_t i = 0; i < vars.size(); ++i)
            if (vars[i].access == cat::Access::Parameter) m_values[i] = nv[i];
    ++m_valuesVersion;
    m_inputs.fill(true); // unconnected inputs pull high (L2097)
    m_motion = Sc750Motion{};
    m_axis = m_axisSwitch;
    m_loggedOn = m_axis == 255;
    m_uart.setMuted(!m_loggedOn);
    m_programInput.clear();
    m_runFault = m_servoFault = 0;
    m_ticks = 0;
    m_timeBase = 0;
    m_timeOffset_s = 0;
    m_encoderPosition = 0;
    m_servo.powerUp(); // the shaft stays where it is; POSITION counts from 0 again
    m_actual_counts = m_lastShaft_counts = 0;
    m_analogInFiltered_V = m_dacmon_V = m_encoderOut_counts = 0;
    m_ratioFromPulses = false;
    m_lastInput7 = m_lastInput8 = true;
    m_timers = {};
    m_anyTimer = false;
    m_wasEnabled = false;
    m_charReceived = m_disableEvent = false;
    m_monitor.reset();
    m_inLogon = m_othersFrame = false;
    refreshInterruptsEnabled();
    if (m_vm.program()) {
        m_vm.powerCycle();
        if (num(ix().autostart) == 1) m_vm.start(); // AUTOSTART (L2814-L2829)
    }
}

bool Sc750Drive::loadProgram(std::vector<std::uint8_t> bin, std::string* error) {
    BinReadResult read = readBin(bin);
    if (read.status != BinStatus::Ok) {
        if (error) *error = read.message;
        if (read.status == BinStatus::BadVersion) m_runFault = cat::kFaultIncompatible;
        return false;
    }
    m_bin = std::move(bin);
    for (const ProgramParam& p : read.program->params) { // PARAMS become the NV power-on values (L1176)
        const auto& info = cat::variables()[std::size_t(p.variable)];
        if (auto v = convert(Value(float(p.value)), info.type)) set(p.variable, *v);
    }
    m_vm.load(std::move(*read.program));
    m_runFault = 0;
    refreshInterruptsEnabled();
    return true;
}

void Sc750Drive::setConfigured(bool configured) {
    m_configured = configured;
    if (!configured) set(ix().enable, std::int32_t(0));
}

int Sc750Drive::faultCode() const {
    if (m_servoFault != 0) return m_servoFault; // what stopped the motor
    if (m_runFault != 0) return m_runFault;
    return enabled() ? cat::kFaultEnabled : cat::kFaultNone;
}

bool Sc750Drive::enabled() const {
    return m_configured && m_enableInput && m_runFault == 0 && m_servoFault == 0 && num(ix().enable) == 1;
}

void Sc750Drive::receive(std::string_view bytes) {
    for (char c : bytes) handleByte(c);
}

std::string Sc750Drive::takeTransmitted() {
    return m_uart.takeSent();
}

void Sc750Drive::step(Microseconds dt) {
    m_now += dt;
    m_carry += dt;
    while (m_carry >= kTick) {
        m_carry -= kTick;
        tick();
    }
    m_uart.advance(dt);
}

void Sc750Drive::tick() {
    ++m_ticks;
    const bool en = enabled();
    if (m_wasEnabled && !en) {
        m_motion.halt(); // disabled: no torque, the motor coasts (L1481-L1512)
        m_disableEvent = true;
    }
    m_wasEnabled = en;
    servoTick(en); // the loops compare the command and the shaft at the tick's start, then the motor moves
    servoFaults();
    m_motion.step(kTick_s);
    if (en && num(ix().blktype) == 2) m_motion.stepGearing(kTick_s, gearSettings());
    analogTick();
    registration();
    m_encoderPosition += m_masterFrequency * kTick_s;
    for (int t = 0; t < 6 && m_anyTimer; ++t) {
        Timer& timer = m_timers[std::size_t(t)];
        if (!timer.configured || num(ix().tmenable1 + t) != 1) continue;
        const bool trigger = input(timer.input) == (timer.inputLevel == 1);
        if (trigger && !timer.lastTrigger) {
            const std::int64_t delay = std::llround(timer.delay_s / kTick_s);
            if (timer.pulse) {
                writeVariable(ix().out1 + timer.output - 1, std::int32_t(timer.outputLevel));
                set(ix().tmout1 + t, std::int32_t(1));
                timer.endAt = m_ticks + delay;
            } else {
                timer.fireAt = m_ticks + delay;
            }
        }
        timer.lastTrigger = trigger;
        if (timer.fireAt >= 0 && m_ticks >= timer.fireAt) {
            writeVariable(ix().out1 + timer.output - 1, std::int32_t(timer.outputLevel));
            set(ix().tmout1 + t, std::int32_t(1));
            timer.fireAt = -1;
        }
        if (timer.endAt >= 0 && m_ticks >= timer.endAt) {
            writeVariable(ix().out1 + timer.output - 1, std::int32_t(1 - timer.outputLevel));
            set(ix().tmout1 + t, std::int32_t(0));
            timer.endAt = -1;
        }
    }
    const Vm::State before = m_vm.state();
    m_vm.tick(m_ticks, kInstructionsPerTick);
    const Vm::State after = m_vm.state();
    if (before == Vm::State::Running && after != Vm::State::Running) {
        if (after == Vm::State::Error) m_runFault = cat::kFaultRunTime; // display F 4 (L2285)
        m_monitor.programHalted(after);
    }
}

void Sc750Drive::handleByte(char c) {
    if (m_inLogon) { // multidrop logon "/nnn" (App. C, L3704-L3712)
        if (c >= '0' && c <= '9' && m_logon.size() < 3) {
            m_logon += c;
            if (m_logon.size() < 3) return;
            c = 0;
        }
        m_inLogon = false;
        m_loggedOn = !m_logon.empty() && std::stoi(m_logon) == m_axis;
        set(ix().loggedon, std::int32_t(m_loggedOn ? 1 : 0));
        m_uart.setMuted(!m_loggedOn);
        if (c == 0) return;
    }
    if (!m_loggedOn && (m_othersFrame || c == kSoh)) { // a frame for the unit logged on: no logon inside it
        m_othersFrame = c != kFrameEnd;
        return;
    }
    if (m_monitor.inFrame() || c == kSoh || c == kCtrlC) {
        if (m_loggedOn) m_monitor.feed(c);
        return;
    }
    if (c == '/' && m_axis != 255) {
        m_inLogon = true;
        m_logon.clear();
        return;
    }
    if (m_loggedOn && m_vm.running()) programByte(c);
}

void Sc750Drive::programByte(char c) {
    m_charReceived = true;                // CHAR interrupt (L1846)
    if (m_vm.wait() == Vm::Wait::Input) { // INPUT echoes what is typed
        if (c == '\r')
            m_uart.write("\r\n");
        else if (c == '\b' && !m_programInput.empty())
            m_uart.write("\b \b");
        else if (c != '\n' && c != '\b')
            m_uart.write(std::string_view(&c, 1));
    }
    if (c == '\b') {
        if (!m_programInput.empty() && m_programInput.back() != '\r') m_programInput.pop_back();
        return;
    }
    if (m_programInput.size() < kInputBuffer) m_programInput += c;
}

void Sc750Drive::setInput(int number, bool on) {
    if (number >= 1 && number <= 16) m_inputs[std::size_t(number - 1)] = on;
}

bool Sc750Drive::homeClosed() const {
    if (m_homeSwitch) return true;
    if (std::isnan(m_homeCam_rev)) return false;
    return std::abs(m_actual_counts / kCountsPerRev - m_homeCam_rev) <= 0.25;
}

bool Sc750Drive::input(int number) const {
    if (number < 1 || number > 16) return true;
    if (number == 1 && homeClosed()) return false;
    return m_inputs[std::size_t(number - 1)];
}

bool Sc750Drive::output(int number) const {
    if (number < 1 || number > 12) return false;
    const int outputs = int(num(ix().outputs));
    return (outputs >> (number - 1) & 1) == 0;
}

SimulatorStatus Sc750Drive::status() const {
    SimulatorStatus s;
    for (int i = 1; i <= 16; ++i) s.inputs.push_back(input(i));
    for (int i = 1; i <= 12; ++i) s.outputs.push_back(output(i));
    s.enableInput = m_enableInput;
    s.homeSwitch = homeClosed();
    s.active = enabled();
    s.fault = m_runFault != 0;
    s.positiveLimit = m_inhibitCw;
    s.negativeLimit = m_inhibitCcw;
    s.position_rev = m_actual_counts / kCountsPerRev;
    s.velocity_rpm = m_servo.velocity_cps() / kCpsPerRpm;
    s.current_a = m_servo.current_A();
    const physics::Plant& plant = m_servo.plant();
    s.loadTorque_Nm = plant.load().externalTorque_Nm;
    s.loadInertia_kgm2 = plant.load().inertia_kgm2;
    s.couplingStiffness_NmPerRad = plant.load().couplingStiffness_NmPerRad;
    s.couplingDamping_NmPerRadPerS = plant.load().couplingDamping_NmPerRadPerS;
    s.resonance_Hz = plant.resonance_Hz();
    s.analogInput_V = m_analogIn_V;
    s.analogOutput_V = m_dacmon_V;
    s.encoderOutput_counts = std::llround(m_encoderOut_counts);
    s.masterFrequency_Hz = m_masterFrequency;
    s.motorName = m_servo.motor().name;
    return s;
}

} // namespace drive_core::sc750
