// What a simulated drive offers outside its serial port: the test bench around it. The IDE's I/O panel,
// tests and servodesk-sim's side channel flip inputs and change the load here, never through the UART.
// Real drives have no such thing, so the IDE reaches it only through SimulatorLink.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace drive_core {

// A waveform on the master (external encoder / analog) input: its frequency swings around the steady
// master frequency (setMasterFrequency_Hz) by amplitude_Hz, repeating frequency_Hz times a second. The
// BDS5's analog input option turns 10 V into 2 MHz (L2935), so an analog sine of V volts peak is a
// sine of V x 200 kHz here.
enum class MasterWaveShape { None, Sine, Square, Triangle };
struct MasterWave {
    MasterWaveShape shape = MasterWaveShape::None;
    double amplitude_Hz = 0; // peak swing of the master's frequency, counts per second
    double frequency_Hz = 1; // repetitions per second (> 0)
};

// A snapshot of the bench, for displays. Units are in the names; counts are the drive's native units.
struct SimulatorStatus {
    std::vector<bool> inputs;  // I1.. as numbered in the manual (index 0 = I1)
    std::vector<bool> outputs; // O1..
    bool enableInput = true;   // hardware ENABLE line (BDS5: J2 enable)
    bool motionInput = true;   // hardware MOTION line
    bool homeSwitch = false;
    bool positiveLimit = false; // true = limit switch tripped
    bool negativeLimit = false;
    bool active = false; // power stage on
    bool fault = false;
    double position_rev = 0; // motor shaft
    double velocity_rpm = 0;
    double current_a = 0;
    double loadTorque_Nm = 0;
    double loadInertia_kgm2 = 0;
    double couplingStiffness_NmPerRad = 0;   // motor-to-load coupling; 0: rigid (one mass)
    double couplingDamping_NmPerRadPerS = 0; // the coupling's own damping
    double resonance_Hz = 0;                 // the two-mass resonance it makes with the load; 0 when rigid
    double masterFrequency_Hz = 0;           // external encoder / master input, counts per second
    MasterWave masterWave;                   // and the wave on top of it
    std::string motorName;
    bool feedbackConnected = true;      // resolver / encoder wires (off: the drive faults, BDS5 ERR 17)
    bool relayClosed = false;           // fault relay: hardware watchdog OK (BDS5 C2 pins 16/17)
    bool brakeReleased = false;         // brake output (BDS5 STATUS): the motor is held by the drive
    double analogInput_V = 0;           // the voltage the bench applies to the analog input (SC750)
    double analogOutput_V = 0;          // the analog output (SC750: DACMON, -5..+5 V)
    long long encoderOutput_counts = 0; // quadrature counts the encoder output has emitted (SC750 ENC.OUT)
};

// What the bench's oscilloscope saw on the drive's analog monitor output (MonitorRecorder): one sample a
// servo period, oldest first; empty when the drive has no monitor output the bench records.
// The bench's second probe sits on the velocity loop's input, so one run gives the loop's frequency response
// (command -> output): `command` is empty where the drive records none, else as long as `volts`.
struct MonitorTrace {
    std::string signal;      // what the output carries: "DACMON: VEL.CMD, 1 V/kRPM" or "tach"
    double interval_s = 0;   // between samples (the servo period)
    double lastSample_s = 0; // the drive's clock at the newest sample (seconds since power-up)
    std::vector<float> volts;
    std::string commandSignal; // what the second probe carries: "VEL.CMD, 1 V/kRPM"
    std::vector<float> command;
};

class SimulatorControls {
public:
    virtual ~SimulatorControls() = default;

    virtual void setInput(int number, bool on) = 0; // I1..In
    virtual void setEnableInput(bool on) = 0;
    virtual void setMotionInput(bool on) = 0;
    virtual void setHomeSwitch(bool on) = 0;
    // Position at which the simulated HOME switch closes by itself as the motor passes (in revolutions);
    // switchless drives ignore it.
    virtual void setHomeSwitchPosition_rev(double position_rev) = 0;
    virtual void setLimitSwitches(bool positiveTripped, bool negativeTripped) = 0;
    virtual void setLoadTorque_Nm(double torque_Nm) = 0;
    virtual void setLoadInertia_kgm2(double inertia_kgm2) = 0;
    virtual void setMasterFrequency_Hz(double countsPerSecond) = 0;
    // One of physics::referenceMotors() by name; false if unknown.
    virtual bool selectMotor(std::string_view name) = 0;
    virtual void powerCycle() = 0;
    virtual SimulatorStatus status() const = 0;
    // Puts a wave on the master input (MasterWaveShape::None removes it); the wave starts at its zero
    // crossing now. False if the drive cannot simulate one.
    virtual bool setMasterWave(const MasterWave& wave) {
        (void)wave;
        return false;
    }
    // Makes the coupling between motor and load compliant (a spring of stiffness N m/rad with a damper of
    // N m s/rad: a two-mass load with a resonance) or rigid again (stiffness 0). False if the drive has no
    // load model.
    virtual bool setLoadCoupling(double stiffness_NmPerRad, double damping_NmPerRadPerS) {
        (void)stiffness_NmPerRad;
        (void)damping_NmPerRadPerS;
        return false;
    }
    // Breaks (false) or reconnects the motor's feedback wires; a drive that cannot simulate it ignores it.
    virtual void setFeedbackConnected(bool connected) { (void)connected; }
    // The voltage on the drive's analog input; a drive without one ignores it.
    virtual void setAnalogInput_V(double volts) { (void)volts; }
    // The newest seconds of the analog monitor output as the bench's oscilloscope recorded them.
    virtual MonitorTrace analogMonitor() const { return {}; }
};

// The side channel's text form, one command per line, for servodesk-sim's control socket and for tests:
//   input N on|off · enable on|off · motion on|off · home on|off · home-at REV · limits POS NEG (on|off)
//   load-torque NM · load-inertia KGM2 · load-coupling NM_PER_RAD NMS_PER_RAD · load-coupling off · master-hz HZ ·
//   master-wave sine|square|triangle AMP_HZ FREQ_HZ · master-wave off · analog-in V · motor NAME · feedback on|off ·
//   power-cycle · status · monitor [SECONDS]
// Returns "OK", "ERROR <reason>", for `status` one line of key=value pairs, for `monitor` one line
// "interval=<s> last=<s> volts=<v>,<v>,... [command=<v>,<v>,...] signal=<text>[ | command: <text>]" of the
// newest SECONDS (all held if none).
std::string runSimulatorCommand(SimulatorControls& controls, std::string_view line);

} // namespace drive_core
