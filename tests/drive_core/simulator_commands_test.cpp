// The bench's text form (runSimulatorCommand) on a simulated BDS5: each command reaches the drive, the
// drive's own variables show it, and malformed lines answer ERROR without touching anything.
#include "bds5_test_drive.h"

#include "drive_core/simulator_controls.h"

#include <gtest/gtest.h>

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
    EXPECT_EQ(value(t, "I1"), "0");
}
