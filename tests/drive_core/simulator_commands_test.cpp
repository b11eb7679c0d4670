// The bench's text form (runSimulatorCommand) on a simulated BDS5: each command reaches the drive, the
// drive's own variables show it, and malformed lines answer ERROR without touching anything.
#include "bds5_test_drive.h"

#include "drive_core/simulator_controls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace bds5_test;
using drive_core::runSimulatorCommand;

namespace {
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return out.substr(start, out.find("\r\n", start) - start);
}
std::string run(TestDrive& t, std::string_view line) {
    return runSimulatorCommand(*t.drive.controls(), line);
}
} // namespace

TEST(SimulatorCommands, InputsReachTheProgram) {
    TestDrive t;
    EXPECT_EQ(run(t, "input 1 on"), "OK");
    EXPECT_EQ(value(t, "I1"), "1");
    EXPECT_EQ(run(t, "input 16 on"), "OK");
    EXPECT_EQ(value(t, "IN"), "32769");
    EXPECT_EQ(run(t, "input 1 off"), "OK");
    EXPECT_EQ(value(t, "I1"), "0");
    EXPECT_EQ(run(t, "status").substr(0, 24), "inputs=0000000000000001 ");
}

TEST(SimulatorCommands, EnableMotionHomeAndLimitsAreTheDedicatedInputs) {
    TestDrive t;
    t.type("EN\r");
    EXPECT_EQ(run(t, "enable off"), "OK");
    EXPECT_EQ(value(t, "REMOTE"), "0");
    t.wait(2ms);
    EXPECT_EQ(value(t, "ACTIVE"), "0");
    EXPECT_NE(run(t, "status").find(" enable=0 "), std::string::npos);
    EXPECT_EQ(run(t, "motion off"), "OK");
    EXPECT_EQ(value(t, "MOTION"), "0");
    EXPECT_EQ(run(t, "home on"), "OK");
    EXPECT_EQ(value(t, "HOME"), "1");
    EXPECT_EQ(run(t, "limits off on"), "OK");
    EXPECT_EQ(value(t, "LIMIT"), "0");
    EXPECT_NE(run(t, "status").find(" limit_pos=0 limit_neg=1 "), std::string::npos);
}

TEST(SimulatorCommands, LoadAndMasterInputMoveTheDrivesVariables) {
    TestDrive t;
    EXPECT_EQ(run(t, "load-torque -0.3"), "OK");
    t.wait(100ms);
    EXPECT_NE(value(t, "PFB"), "0") << "a disabled motor turns under a load torque";
    EXPECT_EQ(run(t, "master-hz 10000"), "OK");
    t.wait(100ms);
    const int pext = std::stoi(value(t, "PEXT"));
    EXPECT_NEAR(pext, 1000, 20) << "10 kHz for 0.1 s";
    EXPECT_EQ(run(t, "load-inertia 0.001"), "OK");
    EXPECT_NE(run(t, "status").find(" load_inertia_kgm2=0.001 "), std::string::npos);
}

// A waveform on the master input: the frequency swings about master-hz, the position about its steady
// course; a whole number of wave periods adds exactly master-hz x time counts.
TEST(SimulatorCommands, MasterWaveSwingsTheMastersFrequency) {
    TestDrive t;
    const auto pext = [&] { return t.drive.state().variables.read("PEXT").value_or(0); };
    const auto vextCps = [&] { return t.drive.state().variables.read("VEXT").value_or(0); }; // PXNUM/VXNUM 1:
    const auto runMs = [&](int ms) {
        for (int i = 0; i < ms; ++i) t.drive.step(1ms);
        t.drive.takeTransmitted();
    };
    t.type("VXNUM=65536\r"); // VEXT in counts per second (basic: 1/65536 count per ms)
    t.type("VXDEN=1000\r");
    EXPECT_EQ(run(t, "master-hz 2000"), "OK");
    EXPECT_EQ(run(t, "master-wave sine 10000 5"), "OK"); // +-10 kHz, 5 times a second
    EXPECT_NE(run(t, "status").find(" master_hz=2000 "), std::string::npos);
    EXPECT_NE(run(t, "status").find(" master_wave=sine:10000:5"), std::string::npos);
    const int p0 = pext();
    runMs(50); // a quarter period: the frequency at its crest
    EXPECT_NEAR(vextCps(), 12000, 10);
    // The counts so far: 2000 x 0.05 + 10000 (1 - cos(pi/2)) / (2 pi 5).
    EXPECT_NEAR(pext() - p0, 100 + 10000 / (10 * std::numbers::pi), 1);
    runMs(100); // three quarters: the trough, running backwards
    EXPECT_NEAR(vextCps(), -8000, 10);
    runMs(50); // one whole period: only the steady part is left, to the count
    EXPECT_EQ(pext() - p0, 400);
    runMs(800); // five periods
    EXPECT_EQ(pext() - p0, 2000);

    EXPECT_EQ(run(t, "master-wave square 3000 10"), "OK"); // +3 kHz for 50 ms, then -3 kHz
    runMs(20);
    EXPECT_NEAR(vextCps(), 5000, 1);
    runMs(50);
    EXPECT_NEAR(vextCps(), -1000, 1);
    EXPECT_EQ(run(t, "master-wave triangle 3000 10"), "OK");
    runMs(25); // the triangle's crest
    EXPECT_NEAR(vextCps(), 5000, 150);
    EXPECT_EQ(run(t, "master-wave off"), "OK");
    EXPECT_NE(run(t, "status").find(" master_wave=off"), std::string::npos);
    const int p1 = pext();
    runMs(100);
    EXPECT_EQ(pext() - p1, 200);
    EXPECT_EQ(vextCps(), 2000);
}

// The wave drives the electronic gearbox like any master: a sine master makes the slave oscillate.
TEST(SimulatorCommands, ASineMasterSwingsTheGearedMotor) {
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("GEARI=1\r");
    t.type("GEARO=1\r");
    t.type("EN\r");
    t.type("GEAR ON\r");
    EXPECT_EQ(run(t, "master-wave sine 20000 2"), "OK"); // 20 kHz peak: the shaft swings 1592 counts
    const auto read = [&](const char* name) { return double(t.drive.state().variables.read(name).value_or(0)); };
    double low = 1e9, high = -1e9, pfbLow = 1e9, pfbHigh = -1e9;
    for (int ms = 0; ms < 1000; ++ms) {
        t.drive.step(1ms);
        low = std::min(low, read("PCMD"));
        high = std::max(high, read("PCMD"));
        if (ms > 500) { // the motor, once the loop has settled into the swing
            pfbLow = std::min(pfbLow, read("PFB"));
            pfbHigh = std::max(pfbHigh, read("PFB"));
        }
    }
    t.drive.takeTransmitted();
    const double swing = 20000 / (std::numbers::pi * 2); // peak to peak 2 A / (2 pi f)
    EXPECT_NEAR(high - low, swing, 2);
    EXPECT_NEAR(low, 0, 1) << "from its start the sine master only runs forward first";
    EXPECT_NEAR(pfbHigh - pfbLow, swing, 0.05 * swing) << "the motor follows";
}

TEST(SimulatorCommands, MotorAndPowerCycle) {
    TestDrive t;
    EXPECT_EQ(run(t, "motor REF-LARGE"), "OK");
    EXPECT_NE(run(t, "status").find(" motor=REF-LARGE"), std::string::npos);
    EXPECT_NE(t.wait(5ms).find(drive_core::bds5::kSignOn), std::string::npos) << "a new motor is a power-up";
    EXPECT_EQ(run(t, "motor NOPE"), "ERROR unknown motor NOPE");
    EXPECT_EQ(run(t, "power-cycle"), "OK");
    EXPECT_NE(t.wait(5ms).find(drive_core::bds5::kSignOn), std::string::npos);
}

TEST(SimulatorCommands, HomeSwitchClosesAsTheShaftPasses) {
    TestDrive t;
    EXPECT_EQ(run(t, "home-at 0.5"), "OK");
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("MI 4096 60\r"); // one revolution at 60 RPM: passes 0.5 rev after about half a second
    bool seen = false;
    for (int i = 0; i < 150 && !seen; ++i) {
        t.wait(10ms);
        seen = t.drive.controls()->status().homeSwitch;
    }
    EXPECT_TRUE(seen);
}

TEST(SimulatorCommands, MalformedLinesAnswerError) {
    TestDrive t;
    EXPECT_EQ(run(t, ""), "ERROR empty command");
    EXPECT_EQ(run(t, "fly"), "ERROR unknown command fly");
    EXPECT_EQ(run(t, "input 17 on"), "ERROR input number must be 1..16");
    EXPECT_EQ(run(t, "input 1 maybe"), "ERROR expected on or off");
    EXPECT_EQ(run(t, "enable"), "ERROR wrong number of arguments for enable");
    EXPECT_EQ(run(t, "load-torque heavy"), "ERROR expected a number");
    EXPECT_EQ(run(t, "load-inertia -1"), "ERROR inertia must not be negative");
    EXPECT_EQ(run(t, "master-wave saw 1 1"), "ERROR expected sine, square or triangle");
    EXPECT_EQ(run(t, "master-wave sine 1000 0"), "ERROR wave frequency must be above 0");
    EXPECT_EQ(run(t, "master-wave sine 1000"), "ERROR wrong number of arguments for master-wave");
    EXPECT_EQ(run(t, "master-wave on"), "ERROR expected master-wave off or a shape, amplitude and frequency");
    EXPECT_EQ(value(t, "I1"), "0");
}

// A compliant coupling (DECISIONS.md 19): the status shows the two-mass resonance of the closed form
// f = sqrt(K (1/Jm + 1/Jl)) / 2 pi with the bench's motor and load; off makes the load rigid again.
TEST(SimulatorCommands, LoadCouplingMakesATwoMassLoadWithItsResonance) {
    TestDrive t;
    EXPECT_EQ(run(t, "load-inertia 0.0003"), "OK");
    EXPECT_EQ(run(t, "load-coupling 60 0.002"), "OK");
    const std::string status = run(t, "status");
    EXPECT_NE(status.find(" coupling_nm_per_rad=60 coupling_nms_per_rad=0.002 "), std::string::npos) << status;
    const double jm = 1.5e-4; // REF-MEDIUM, the bench's motor at power-up
    const double expected = std::sqrt(60 * (1 / jm + 1 / 0.0003)) / (2 * std::numbers::pi);
    const auto at = status.find(" resonance_hz=");
    ASSERT_NE(at, std::string::npos);
    EXPECT_NEAR(std::stod(status.substr(at + 14)), expected, 1e-3 * expected);
    EXPECT_EQ(run(t, "load-coupling off"), "OK");
    EXPECT_NE(run(t, "status").find(" coupling_nm_per_rad=0 coupling_nms_per_rad=0 resonance_hz=0 "),
              std::string::npos);
    EXPECT_EQ(run(t, "load-coupling -1 0"), "ERROR stiffness and damping must not be negative");
    EXPECT_EQ(run(t, "load-coupling 60"), "ERROR expected load-coupling off or a stiffness and a damping");
    EXPECT_EQ(run(t, "load-coupling"), "ERROR wrong number of arguments for load-coupling");
}
