// The simulated SC750 servocontroller: runs a downloaded ServoBASIC Plus .BIN on the Vm, its motion on the
// shared profile generator, its servo loops on the shared plant (Sc750Servo), discrete I/O, WHEN, interrupts,
// the serial port shared by the program's PRINT/INPUT and the Motion Dialogue protocol (PROTOCOL.md).
// Time is injected through step(); the drive ticks every 0.427 ms.
#pragma once

#include "drive_core/bds5/bds5_uart.h"
#include "drive_core/drive.h"
#include "drive_core/monitor_recorder.h"
#include "sc750_monitor.h"
#include "sc750_motion.h"
#include "sc750_servo.h"
#include "sc750_vm.h"
#include "sc750_vm_host.h"

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace drive_core::sc750 {

struct DriveIndex;

class Sc750Drive final : public Drive, public VmHost, public SimulatorControls {
public:
    Sc750Drive();

    // Drive
    DriveFamily family() const override { return DriveFamily::Sc750; }
    void powerUp() override;
    void receive(std::string_view bytes) override;
    std::string takeTransmitted() override;
    void step(Microseconds dt) override;
    Microseconds now() const override { return m_now; }
    void setLineRateLimited(bool limited) override { m_uart.setUnlimited(!limited); }
    int inputCount() const override { return 16; }
    int outputCount() const override { return 12; }
    void setInput(int number, bool on) override;
    bool input(int number) const override;  // the level INPn reads (home switch included)
    bool output(int number) const override; // true = transistor on (OUTn = 0, active low)
    SimulatorControls* controls() override { return this; }

    // SimulatorControls (the bench). The home switch is wired to INP1 and pulls it low when closed.
    void setEnableInput(bool on) override { m_enableInput = on; }
    void setMotionInput(bool) override {}
    void setHomeSwitch(bool on) override { m_homeSwitch = on; }
    // The home cam: closed within ±0.25 rev of this shaft position (rev since power-up). NaN = no cam.
    void setHomeSwitchPosition_rev(double position_rev) override { m_homeCam_rev = position_rev; }
    // The directional inhibit inputs INH+ (J53-1, clockwise) and INH- (J53-2, counter-clockwise), true = active.
    void setLimitSwitches(bool cwInhibit, bool ccwInhibit) override {
        m_inhibitCw = cwInhibit;
        m_inhibitCcw = ccwInhibit;
    }
    void setAnalogInput_V(double volts) override { m_analogIn_V = volts; }
    void setLoadTorque_Nm(double torque_Nm) override;
    void setLoadInertia_kgm2(double inertia_kgm2) override;
    bool setLoadCoupling(double stiffness_NmPerRad, double damping_NmPerRadPerS) override;
    void setMasterFrequency_Hz(double countsPerSecond) override { m_masterFrequency = countsPerSecond; }
    // A Controller Set Up motor (R32G ...) or a reference motor (REF-MEDIUM ...); the shaft starts at rest.
    bool selectMotor(std::string_view name) override;
    void powerCycle() override { powerUp(); }
    SimulatorStatus status() const override;
    // DACMON as the bench's oscilloscope saw it, a sample a tick, named after the DACMAP signal it carried.
    MonitorTrace analogMonitor() const override;

    // The S1 address switch, read at power-up (255 = RS-232, no multidrop).
    void setAxisAddress(int address) { m_axisSwitch = address; }

    // For the monitor (protocol) and tests.
    Vm& vm() { return m_vm; }
    const Vm& vm() const { return m_vm; }
    int faultCode() const;
    bool decimalPoint() const { return m_vm.running(); } // lit while a program executes (L2676)
    bool configured() const { return m_configured; }
    void setConfigured(bool configured);
    bool loadProgram(std::vector<std::uint8_t> bin, std::string* error); // false: refused (error says why)
    const std::vector<std::uint8_t>& programImage() const { return m_bin; }
    std::vector<std::uint8_t>& sourceStore() { return m_source; } // NV source text (Download/Upload Source)
    void setRunTimeFault(int code) { m_runFault = code; }
    void clearRunTimeFault() { m_runFault = 0; }
    // A predefined variable by name (Variables window, real-time calls): nullopt if unknown.
    std::optional<Value> readNamed(std::string_view name);
    std::string writeNamed(std::string_view name, const std::string& text); // "" ok, else the error
    void realTimeCall(int motionKind) { motion(motionKind); }
    void send(std::string_view bytes) { m_uart.write(bytes); } // protocol replies
    bool loggedOn() const { return m_loggedOn; }

    // VmHost
    Value readVariable(int catalogIndex) override;
    std::string writeVariable(int catalogIndex, const Value& value) override;
    void motion(int kind) override;
    void write(std::string_view text) override;
    std::optional<std::string> takeLine() override;
    std::string takeChar() override;
    std::size_t outputBacklog() const override { return m_uart.backlog(); }
    double whenSample(int source) override;
    void whenLatch() override;
    void whenAction(int action, int argument, float value) override;
    void tmrset(int timer, float delay_s, int packed) override;
    int takeInterrupt() override;
    bool anyInterruptEnabled() const override { return m_interruptsEnabled; }
    int axis() const override { return m_axis; }
    double pauseTime_s() override;

private:
    void tick();
    void handleByte(char c);
    void programByte(char c);
    void applyParams();
    bool enabled() const;
    bool homeClosed() const;
    double num(int index) const { return toDouble(m_values[std::size_t(index)]); }
    void set(int index, Value value) {
        m_values[std::size_t(index)] = std::move(value);
        ++m_valuesVersion;
    }
    MoveSettings settings() const;
    GearSettings gearSettings() const;
    void registration();
    void refreshInterruptsEnabled();
    bool interruptAsserted(int source);
    // sc750_drive_servo.cpp: the servo loops for the BLKTYPE, the shaft they move, the settings they read.
    void servoTick(bool enabled);
    // The servo's own faults after a tick (overspeed, I.t, following error; DECISIONS 56): the first latches
    // and disables until ENABLE or the enable input goes low.
    void servoFaults();
    // The loop settings as the variables hold them, worked out again only after a write (every tick reads
    // them: the simulator's speed, issue 18).
    const ServoSettings& servoSettings() const;
    // sc750_drive_io.cpp: analog input/output, encoder output.
    void analogTick();
    // What the analog side reads from the variables every tick, worked out again only after a write.
    struct AnalogSettings {
        std::uint64_t version = ~std::uint64_t(0); // m_valuesVersion it is for
        double adoffset_V = 0, adf0_Hz = 0, dmf0_Hz = 0, encoderLines = 0;
        int dacmap = 0;
        double analogOut_V = 0;   // DACMAP 0: ANALOG.OUT, clamped
        double voltsPerValue = 0; // DACMAP 1-13: volts per unit of the signal as dacSignal_V reads it
        bool rollsOver = false;   // a position signal: rolls over at ±5 V instead of clamping
    };
    const AnalogSettings& analogSettings();
    double dacSignal_V(const AnalogSettings& settings);
    double lag_counts() const { return m_motion.shaft_counts() - m_actual_counts; } // POS.ERROR, not rounded

    struct Timer {
        bool pulse = false;
        float delay_s = 0;
        int output = 0, outputLevel = 0, input = 0, inputLevel = 0;
        bool configured = false;
        bool lastTrigger = false;
        std::int64_t fireAt = -1, endAt = -1;
    };

    Vm m_vm{*this};
    Sc750Monitor m_monitor{*this};
    Sc750Motion m_motion;
    Sc750Servo m_servo;
    bds5::Bds5Uart m_uart;
    std::vector<Value> m_values; // predefined variables by catalog index
    std::uint64_t m_valuesVersion = 0; // counts the writes to m_values (and motor changes), for the caches
    mutable std::uint64_t m_servoSettingsVersion = ~std::uint64_t(0), m_gearSettingsVersion = ~std::uint64_t(0);
    mutable ServoSettings m_servoSettings;
    mutable GearSettings m_gearSettings;
    std::vector<std::uint8_t> m_bin;
    std::vector<std::uint8_t> m_source;
    std::array<bool, 16> m_inputs{};
    std::array<Timer, 6> m_timers{};
    bool m_anyTimer = false; // a TMRSET has configured one since power-up (the tick skips them until then)
    std::string m_programInput;
    Microseconds m_now{0};
    Microseconds m_carry{0};
    std::int64_t m_ticks = 0;
    std::int64_t m_timeBase = 0; // tick at which TIME was last written
    double m_timeOffset_s = 0;
    int m_axisSwitch = 255;
    int m_axis = 255;
    int m_runFault = 0;
    int m_servoFault = 0; // 1, 4 or 241 while latched
    double m_controllerPeak_A = 0; // the MODEL's peak current, as the last servo tick read it
    bool m_loggedOn = true;
    bool m_enableInput = true;
    bool m_homeSwitch = false;
    double m_homeCam_rev = std::nan("");
    double m_masterFrequency = 0;
    double m_encoderPosition = 0;
    bool m_inhibitCw = false, m_inhibitCcw = false;
    double m_actual_counts = 0; // the shaft (generator coordinates, counts since power-up), from the plant
    double m_analogIn_V = 0;         // the bench's voltage on the analog input
    double m_analogInFiltered_V = 0; // ANALOG.IN, after ADF0
    double m_dacmon_V = 0;           // DACMON = the analog output, after DMF0
    // A first-order low-pass over one tick, its alpha kept until the corner changes (an exp a tick each).
    struct LowPass {
        double corner_Hz = -1;
        double alpha = 0;
        double operator()(double filtered, double input, double corner);
    };
    LowPass m_adf0, m_dmf0;          // ADF0 on the analog input, DMF0 on the analog output
    AnalogSettings m_analogSettings;
    MonitorRecorder m_dacmonScope{kTick_s}; // the bench's oscilloscope on DACMON (kept over a power cycle)
    double m_encoderOut_counts = 0;  // emitted by the encoder output (ENC.OUT > 0), quadrature counts
    double m_lastShaft_counts = 0;
    bool m_configured = true;
    bool m_ratioFromPulses = false;                // PULSES.IN/OUT written after RATIO
    bool m_lastInput7 = true, m_lastInput8 = true; // registration edges
    bool m_interruptsEnabled = false;
    bool m_charReceived = false;
    bool m_wasEnabled = false;
    bool m_disableEvent = false;
    std::string m_logon; // "/nnn" being received
    bool m_inLogon = false;
    bool m_othersFrame = false; // logged off, between the SOH and CR of a frame the unit logged on answers
    // Catalog indices of the variables the drive computes or reacts to (looked up once, read every tick).
    const DriveIndex& ix() const { return *m_ix; }
    const DriveIndex* m_ix;
};

} // namespace drive_core::sc750
