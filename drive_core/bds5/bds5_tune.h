// TUNE bw stab (L6264-6368, L7084-7096): shakes the simulated motor at about 15 Hz with ILIM, estimates
// the inertia from the speed swing, and sets KV, KVI, KP and KPROP for the requested velocity-loop
// bandwidth and damping; ERR 20 when the drive cannot reach them.
#pragma once

#include "bds5_servo.h"
#include "bds5_variable_store.h"

namespace drive_core::bds5 {

struct TuneGains {
    double kv = 0, kvi = 0, kp = 0, kprop = 0;
};

class Bds5Tune {
public:
    static bool validBandwidth(int bandwidth_Hz);
    // The damping ratio for a stability setting (Table 6.2): 1 slightly over-, 2 critically, 3 slightly
    // under-damped. 0 for an invalid setting.
    static double damping(int stability);
    // The gains for a bandwidth and damping on a load of inertia J (motor + load) driven with Kt and the
    // drive's peak current (IMAX). Pure arithmetic, for TUNE and for tests.
    static TuneGains gainsFor(double bandwidth_Hz, double damping, double inertia_kgm2, double torqueConstant_NmPerA,
                              double peakCurrent_A);

    // The shake: a ±ILIM square wave at 15 Hz on the motor (the servo loops off), then the inertia from
    // the current's impulse over the speed swing. Returns kg·m², or a negative error (13 over-speed).
    static double measureInertia(Bds5Servo& servo, Bds5VariableStore& vars);

    // The whole command: 0 and the gains written, or the error (20 TUNE FAILED, 13 over-speed).
    static int run(Bds5Servo& servo, Bds5VariableStore& vars, int bandwidth_Hz, int stability, bool remote);
};

} // namespace drive_core::bds5
