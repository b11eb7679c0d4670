// SC750 motion in simulated time: asynchronous GO.* commands, superseding moves, ENABLED gating, the
// POS.COMMAND coordinate shift, and the manual's example programs running with their described behaviour.
#include "sc750_bench.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace sc750_test {
namespace {

std::string example(const char* name) {
    std::ifstream in(std::filesystem::path(SC750_EXAMPLES_DIR) / name, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(Sc750Motion, GoIncrIsAsynchronousAndLandsExactly) {
    Bench b("ENABLE = 1\nACCEL.RATE = 10000\nDECEL.RATE = 10000\nRUN.SPEED = 1000\nINDEX.DIST = 4096\nGO.INCR\n"
            "PRINT MOVING; IN.POSITION\nWHILE MOVING : WEND\nPRINT POSITION; TIME\n");
    b.run(0.5);
    ASSERT_EQ(b.out.substr(0, 8), " 1  0 \r\n");
    // When the profile ends the shaft still lags the command by its following error (no KVFF), then lands.
    const double atEnd = std::stod(b.out.substr(8));
    EXPECT_LT(atEnd, 4096);
    EXPECT_GT(atEnd, 4096 - 100);
    EXPECT_EQ(b.value("POSITION"), 4096);
    EXPECT_EQ(b.value("IN.POSITION"), 1);
    // triangular profile: vp = sqrt(D·a), t = 2·vp/a = 2·sqrt(4096 / 682,667) = 0.155 s
    EXPECT_NEAR(std::stod(b.out.substr(b.out.find(' ', 10))), 0.155, 0.002);
}

TEST(Sc750Motion, MotionIsIgnoredUnlessEnabled) {
    Bench b("INDEX.DIST = 4096\nGO.INCR\nPRINT MOVING; ENABLED; FAULTCODE\n");
    b.run(0.3);
    EXPECT_EQ(b.out, " 0  0  0 \r\n");
    EXPECT_EQ(b.value("POSITION"), 0);
}

TEST(Sc750Motion, HardwareEnableInputGatesEnabled) {
    Bench b("ENABLE = 1\nPRINT ENABLED; FAULTCODE\n", false);
    b.drive.setEnableInput(false);
    b.drive.vm().start();
    b.run(0.05);
    EXPECT_EQ(b.out, " 0  0 \r\n");
}

TEST(Sc750Motion, GoVelAtZeroSpeedSupersedesAMoveAndStops) { // SEEKHOME's stop at the switch (L3453)
    Bench b("ENABLE = 1\nACCEL.RATE = 10000\nDECEL.RATE = 10000\nRUN.SPEED = 200\nTARGET.POS = -200 * 4096\n"
            "GO.ABS\nPAUSE.TIME = 0.5\nPAUSE\nRUN.SPEED = 0\nGO.VEL\nWHILE MOVING : WEND\nPAUSE.TIME = 0.2\nPAUSE\n"
            "PRINT VELOCITY\n");
    b.run(1.0);
    ASSERT_FALSE(b.out.empty());
    EXPECT_NEAR(std::stod(b.out), 0, 0.5); // VELOCITY, a 128 ms average, once the shaft has stopped
    // 0.02 s ramp to 200 rpm, 0.48 s at 200 rpm, 0.02 s ramp down: about -1.67 rev
    EXPECT_NEAR(b.value("POSITION") / 4096, -(0.01 + 0.48 * 200 / 60 + 0.01 * 200 / 60 * 1.0), 0.05);
}

TEST(Sc750Motion, NewGoAbsReversesFromTheMovingState) {
    Bench b("ENABLE = 1\nRUN.SPEED = 600\nDIR = 0\nGO.VEL\nPAUSE.TIME = 0.2\nPAUSE\nTARGET.POS = 0\nGO.ABS\n"
            "WHILE MOVING : WEND\nWHILE IN.POSITION = 0 : WEND\nPRINT POSITION\n");
    b.run(1.0);
    ASSERT_FALSE(b.out.empty());
    EXPECT_LE(std::abs(std::stod(b.out)), b.value("IN.POS.LIMIT")); // in position: within IN.POS.LIMIT
    EXPECT_EQ(b.value("POSITION"), 0);                                 // and, settled, on the target
}

TEST(Sc750Motion, WritingPosCommandWhileMovingShiftsCoordinates) {
    Bench b("ENABLE = 1\nRUN.SPEED = 60\nGO.VEL\nPAUSE.TIME = 0.5\nPAUSE\nPOS.COMMAND = POS.COMMAND - 1000\n"
            "PRINT MOVING\nRUN.SPEED = 0\nGO.VEL\nWHILE MOVING : WEND\nRUN.SPEED = 60\nGO.HOME\nWHILE MOVING : "
            "WEND\nWHILE IN.POSITION = 0 : WEND\nPRINT POSITION\n");
    b.run(2.0);
    ASSERT_EQ(b.out.substr(0, 5), " 1 \r\n");
    EXPECT_LE(std::abs(std::stod(b.out.substr(5))), b.value("IN.POS.LIMIT"));
    EXPECT_EQ(b.value("POSITION"), 0);
    EXPECT_NEAR(b.drive.status().position_rev, 1000.0 / 4096 + 0.0, 0.05); // home is where the shift put it
}

TEST(Sc750Motion, WhenInputStopsAMoveAndLatchesPcmd) { // f05-style WHEN with GO.VEL (L2025-L2030)
    Bench b("ENABLE = 1\nRUN.SPEED = 1000\nGO.VEL\nRUN.SPEED = 0\nWHEN INP3 = 0, GO.VEL\nWHILE MOVING : WEND\n"
            "PRINT WHEN.PCMD\n");
    b.run(0.3);
    const double at = b.value("POS.COMMAND");
    b.drive.setInput(3, false);
    b.run(0.3);
    ASSERT_FALSE(b.out.empty());
    EXPECT_NEAR(std::stod(b.out), at, 1000.0 * 4096 / 60 * 0.0015); // latched within ~1 ms
}

TEST(Sc750Examples, SeekHomeFindsTheSimulatedSwitch) { // SEEKHOME.BAS, manual §8.2
    Bench b(example("repaired/05-seekhome.bas"), false);
    b.drive.setHomeSwitchPosition_rev(-3.0);
    b.drive.vm().start();
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 30));
    EXPECT_NE(b.out.find("HOMING COMPLETE"), std::string::npos) << b.out;
    // the program waits for IN.POSITION: within IN.POS.LIMIT (10) of 8192 (the shaft then settles on it)
    const auto at = b.out.find("I'm now at absolute position ");
    ASSERT_NE(at, std::string::npos) << b.out;
    EXPECT_NEAR(std::stod(b.out.substr(at + 29)), 8192, 10) << b.out;
    // home is the CW edge of the cam, the switch's release point, plus no offset
    EXPECT_NEAR(b.drive.status().position_rev, -3.0 + 0.25 + 2.0, 0.01);
}

TEST(Sc750Examples, SeekHomeReportsFailureWithoutASwitch) {
    Bench b(example("repaired/05-seekhome.bas"));
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 120));
    EXPECT_NE(b.out.find("HOMING ROUTINE NOT SUCCESSFUL"), std::string::npos) << b.out;
}

TEST(Sc750Examples, SimpleSeekHomeCounterClockwise) { // manual §8.3, INP2 high selects the CCW routine
    Bench b(example("repaired/06-simple-seekhome.bas"), false);
    b.drive.setHomeSwitchPosition_rev(-1.0);
    EXPECT_EQ(b.drive.writeNamed("ENABLE", "1"), ""); // the program relies on an enabled drive (digest §8.4)
    b.drive.vm().start();
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 30));
    EXPECT_EQ(b.out, "counterclockwise homing complete\r\n");
    b.run(0.3); // the program ends with the profile; the shaft lands a little later
    EXPECT_EQ(b.value("POSITION"), 0);
    EXPECT_NEAR(b.drive.status().position_rev, -1.0 + 0.25, 0.01); // backing out: the edge it came in by
}

TEST(Sc750Examples, SimpleSeekHomeClockwise) {
    Bench b(example("repaired/06-simple-seekhome.bas"), false);
    b.drive.setHomeSwitchPosition_rev(1.0);
    b.drive.setInput(2, false);
    EXPECT_EQ(b.drive.writeNamed("ENABLE", "1"), "");
    b.drive.vm().start();
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 30));
    EXPECT_EQ(b.out, "clockwise homing complete\r\n");
    b.run(0.3); // the program ends with the profile; the shaft lands a little later
    EXPECT_NEAR(b.drive.status().position_rev, 1.0 - 0.25, 0.01);
}

TEST(Sc750Examples, PartNumberProgramAnswersOnTheSerialPort) { // PART_NUM.BAS, manual §8.1
    Bench b(example("repaired/04-part-num.bas"));
    ASSERT_TRUE(b.runUntil([&] { return b.out.find("PART NUMBER? ") != std::string::npos; }, 1));
    b.type("PN7\r"); // invalid: flashed twice, then asked again
    ASSERT_TRUE(b.runUntil([&] { return b.out.rfind("PART NUMBER? ") > b.out.find("INVALID PART NUMBER"); }, 10));
    b.out.clear();
    b.type("pn02-12.50\r");
    ASSERT_TRUE(b.runUntil([&] { return b.out.find("Is this OK (Y/N)? ") != std::string::npos; }, 1));
    EXPECT_NE(b.out.find("Selected Part 02 has parameters:\r\n Acceleration = 10000 RPM/Sec\r\n"), std::string::npos)
        << b.out;
    EXPECT_NE(b.out.find(" Length = 12.50 In.\r\n"), std::string::npos);
    b.type("y\r");
    ASSERT_TRUE(b.runUntil([&] { return b.out.find("Number of parts (1 to 1000)? ") != std::string::npos; }, 1));
    b.type("2\r");
    ASSERT_TRUE(b.runUntil([&] { return b.out.find("RUN COMPLETE!") != std::string::npos; }, 30));
    EXPECT_NE(b.out.find(" 1 \r\n"), std::string::npos);
    EXPECT_NE(b.out.find(" 0 \r\n"), std::string::npos);
    EXPECT_EQ(b.value("POSITION"), 2 * 102400); // 12.50 in at 0.5 in/rev, twice
    EXPECT_FALSE(b.drive.output(2));            // OUT2 = 1 again: "machine in operation" off
    b.type("x");
    ASSERT_TRUE(b.runUntil([&] { return b.out.find("Selection (1, 2 or 3)? ") != std::string::npos; }, 5));
    b.type("3\r");
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 1));
}

} // namespace
} // namespace sc750_test

namespace sc750_test {
namespace {

// The manual's gearing phase-correction fragment (L1657-L1664) with a 10 kHz master, ENC.IN = 1000,
// RATIO = 1: the slave locks at 10,000 x 4096 / 4000 = 10,240 counts/s (150 RPM) after 150 / 1200 s,
// having lagged 0.5 x 10,240 x 0.125 = 640 counts, which the GO.INCR then makes up.
TEST(Sc750Motion, GearingLocksAndThePhaseCorrectionMakesUpTheLag) {
    Bench b("DIM lag AS INTEGER\nENABLE = 1\nENC.IN = 1000\nRATIO = 1\n"
            "ACCEL.GEAR = 1200\nDECEL.GEAR = 1200\nGEARERROR = 0\nWHEN INP1=0, CONTINUE\nGEARING = 1\n"
            "WHILE GEARLOCK=0 : WEND\nlag = GEARERROR\nINDEX.DIST= GEARERROR\nGO.INCR\nWHILE MOVING : WEND\n"
            "PAUSE.TIME = 0.3\nPAUSE\nPRINT lag; VELOCITY\n",
            false);
    b.drive.setMasterFrequency_Hz(10000);
    b.drive.vm().start();
    b.run(0.2);
    EXPECT_EQ(b.value("GEARLOCK"), 0); // waiting for INP1
    b.drive.setInput(1, false);
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 2));
    ASSERT_FALSE(b.out.empty());
    EXPECT_NEAR(std::stod(b.out), 640, 10);
    EXPECT_NEAR(std::stod(b.out.substr(b.out.find(' ', 2))), 150, 0.1); // VELOCITY: the 128 ms average, settled
    EXPECT_EQ(b.value("GEARLOCK"), 1);
}

TEST(Sc750Motion, PulsesInOutOverrideRatioWhenWrittenLast) {
    Bench b("ENABLE = 1\nENC.IN = 1000\nRATIO = 3\nPULSES.IN = 2\nPULSES.OUT = 5\nACCEL.GEAR = 1000000\n"
            "GEARING = 1\nPAUSE.TIME = 0.3\nPAUSE\nPRINT VELOCITY\n",
            false);
    b.drive.setMasterFrequency_Hz(4096);
    b.drive.vm().start();
    b.run(0.4);
    ASSERT_FALSE(b.out.empty());
    EXPECT_NEAR(std::stod(b.out), 4096.0 * 5 / 2 / 4096 * 60, 0.1); // 2:5 -> 150 RPM (128 ms average, settled)
}

} // namespace
} // namespace sc750_test

namespace sc750_test {
namespace {

// ACCEL.TYPE = 1 (L1337-L1358): the same move takes the same time and lands on the same count as the
// trapezoid, but its acceleration peaks near twice the average ACCEL.RATE. The acceleration is the profile's,
// from POS.COMMAND (whole counts, so over a 40-tick second difference); the motor, behind its loops, only
// has to land where the profile ends.
TEST(Sc750Motion, SCurveKeepsTheTimingAndDoublesThePeakAcceleration) {
    auto runMove = [](int accelType, double* peak_rpm_per_s) {
        Bench b("ENABLE = 1\nACCEL.TYPE = " + std::to_string(accelType) +
                "\nACCEL.RATE = 6000\nDECEL.RATE = 6000\nRUN.SPEED = 600\nINDEX.DIST = 40960\nGO.INCR\n"
                "WHILE MOVING : WEND\nPRINT TIME\nWHILE IN.POSITION = 0 : WEND\nPRINT POSITION\n");
        constexpr int kWindow = 40;
        constexpr double kWindow_s = kWindow * 0.000427;
        std::vector<double> command;
        *peak_rpm_per_s = 0;
        for (int i = 0; i < 5000 && b.drive.vm().state() == Vm::State::Running; ++i) {
            b.drive.step(drive_core::Microseconds(427)); // one tick at a time
            b.collect();
            command.push_back(b.value("POS.COMMAND"));
            if (command.size() > 2 * kWindow) {
                const std::size_t n = command.size() - 1;
                const double a_cps2 =
                    (command[n] - 2 * command[n - kWindow] + command[n - 2 * kWindow]) / (kWindow_s * kWindow_s);
                *peak_rpm_per_s = std::max(*peak_rpm_per_s, std::abs(a_cps2) * 60 / 4096);
            }
        }
        b.run(0.3);
        EXPECT_EQ(b.value("POSITION"), 40960);
        return b.out;
    };
    double peakTrapezoid = 0, peakS = 0;
    const std::string trapezoid = runMove(0, &peakTrapezoid);
    const std::string s = runMove(1, &peakS);
    ASSERT_FALSE(trapezoid.empty());
    ASSERT_FALSE(s.empty());
    EXPECT_NEAR(std::stod(s), std::stod(trapezoid), 0.002); // 1.1 s both
    const auto landed = [](const std::string& out) { return std::stod(out.substr(out.find('\n') + 1)); };
    EXPECT_NEAR(landed(trapezoid), 40960, 10); // in position
    EXPECT_NEAR(landed(s), 40960, 10);
    EXPECT_NEAR(peakTrapezoid, 6000, 250);
    EXPECT_GT(peakS, 1.65 * 6000); // the 17 ms difference blunts the 100 ms triangle's peak a little
    EXPECT_LT(peakS, 2.05 * 6000);
}

} // namespace
} // namespace sc750_test

namespace sc750_test {
namespace {

// Registration (L1753-L1758): set REG.MODE, REG.FUNC/REG.DIST, arm with REG.FLAG = 0, poll REG.FLAG. A
// rising edge on INP7 while jogging latches REG.POS and moves REG.DIST past it, then stops.
TEST(Sc750Motion, RegistrationLatchesAndMovesRegDist) {
    Bench b("ENABLE = 1\nREG.MODE = 2\nREG.FUNC = 1\nREG.DIST = 4096\nREG.FLAG = 0\nRUN.SPEED = 300\nGO.VEL\n"
            "WHILE REG.FLAG = 0 : WEND\nWHILE MOVING : WEND\nWHILE IN.POSITION = 0 : WEND\n"
            "PRINT REG.FLAG; POSITION - REG.POS\n",
            false);
    b.drive.setInput(7, false);
    b.drive.vm().start();
    b.run(0.3);
    b.drive.setInput(7, true); // rising edge
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 3));
    ASSERT_EQ(b.out.substr(0, 3), " 3 "); // both registrations (mode 2: INP7 for both)
    EXPECT_NEAR(std::stod(b.out.substr(3)), 4096, b.value("IN.POS.LIMIT")); // in position REG.DIST past
    b.run(0.3);
    EXPECT_EQ(b.value("POSITION") - b.value("REG.POS"), 4096); // settled: exactly REG.DIST past
    // 0.3 s of a jog to 300 RPM whose first 0.03 s ramp at 10,000 RPM/s: 6144 - 307 counts of command; the
    // shaft (REG.POS latches POSITION) lags it by the following error, speed / (2 pi KPP) without KVFF
    const double lag = 300.0 / 60 * 4096 / (2 * 3.14159265 * b.value("KPP"));
    EXPECT_NEAR(b.value("REG.POS"), 0.3 * 300 / 60 * 4096 - 0.5 * 0.03 * 300 / 60 * 4096 - lag, 20);
}

} // namespace
} // namespace sc750_test
