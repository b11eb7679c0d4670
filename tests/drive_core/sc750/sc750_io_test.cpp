// The simulated SC750's analog input and output, encoder output, directional inhibits, over-travel and
// position-error interrupts, and software timers, as a program and the bench see them. Simulated time.
#include "drive_core/simulator_controls.h"
#include "sc750_bench.h"

namespace sc750_test {
namespace {

using drive_core::runSimulatorCommand;

// The value of key=… in the bench's status line.
std::string statusField(Sc750Drive& drive, const std::string& key) {
    const std::string line = runSimulatorCommand(drive, "status");
    const auto at = line.find(" " + key + "=");
    if (at == std::string::npos) return "<none>";
    const auto start = at + key.size() + 2;
    return line.substr(start, line.find(' ', start) - start);
}

TEST(Sc750Io, AnalogInputFollowsTheBenchThroughAdf0AndAdOffset) { // L2177-L2181
    Bench b("DIM v AS FLOAT\nHere:\nv = ANALOG.IN\nGOTO Here\n");
    EXPECT_EQ(runSimulatorCommand(b.drive, "analog-in 3.25"), "OK");
    EXPECT_EQ(runSimulatorCommand(b.drive, "analog-in volts"), "ERROR expected a number");
    EXPECT_EQ(runSimulatorCommand(b.drive, "analog-in"), "ERROR wrong number of arguments for analog-in");
    b.run(0.05);
    EXPECT_NEAR(std::get<float>(b.user("V")), 3.25, 1e-4);
    EXPECT_EQ(statusField(b.drive, "analog_in_v"), "3.25");
    b.drive.setAnalogInput_V(-20); // beyond the ±12 V range: the converter saturates
    b.run(0.05);
    EXPECT_NEAR(b.value("ANALOG.IN"), -12, 1e-4);
    b.drive.setAnalogInput_V(2);
    ASSERT_EQ(b.drive.writeNamed("AD.OFFSET", "0.5"), "");
    ASSERT_EQ(b.drive.writeNamed("ADF0", "10"), ""); // 10 Hz corner: one tick moves it only 2.6 %
    b.drive.step(drive_core::Microseconds(427));
    EXPECT_LT(b.value("ANALOG.IN"), -11);
    b.run(1.0);
    EXPECT_NEAR(b.value("ANALOG.IN"), 2.5, 1e-3);
}

TEST(Sc750Io, WhenAnalogInStopsAMove) { // a WHEN source (L2003)
    Bench b("ENABLE = 1\nGO.VEL\nWHEN ANALOG.IN > 4.5, GO.VEL\nPRINT \"latched\"; WHEN.ANALOG.IN > 4.5\n");
    ASSERT_EQ(b.drive.writeNamed("RUN.SPEED", "600"), "");
    b.run(0.2);
    EXPECT_EQ(b.out, "");
    b.drive.setAnalogInput_V(5);
    b.run(0.05);
    EXPECT_EQ(b.out, "latched-1 \r\n");
}

TEST(Sc750Io, AnalogOutFollowsAnalogOutWhenDacmapIsZeroAndIgnoresDmgain) { // L2173
    Bench b("DACMAP = 0\nDMGAIN = 3\nANALOG.OUT = -2.5\n");
    b.run(0.05);
    EXPECT_NEAR(b.value("DACMON"), -2.5, 1e-4);
    EXPECT_EQ(statusField(b.drive, "analog_out_v"), "-2.5");
}

TEST(Sc750Io, DacmapVelocityIsOneVoltPerKrpmTimesDmgainAndClamps) { // L2147-L2171
    Bench b("DACMAP = 1\nDMGAIN = 2\nENABLE = 1\nRUN.SPEED = 1500\nGO.VEL\n");
    b.run(0.5);
    EXPECT_NEAR(b.value("DACMON"), 3.0, 1e-3); // 1.5 kRPM x 1 V/kRPM x 2
    ASSERT_EQ(b.drive.writeNamed("RUN.SPEED", "4000"), "");
    b.drive.realTimeCall(6); // UPD.MOVE
    b.run(0.5);
    EXPECT_NEAR(b.value("DACMON"), 5.0, 1e-3); // 8 V clamps at +5 V
    ASSERT_EQ(b.drive.writeNamed("DACMAP", "2"), "");
    EXPECT_EQ(b.value("DMGAIN"), 1); // reset by the DACMAP write
    b.run(0.05);
    EXPECT_NEAR(b.value("DACMON"), 4.0, 1e-3); // VEL.CMD 4 kRPM at gain 1
}

TEST(Sc750Io, DacmapPositionRollsOverAtFiveVolts) { // 40 V/rev, L2163-L2167
    Bench b("DACMAP = 7\nENABLE = 1\nINDEX.DIST = 256\nGO.INCR\n");
    b.run(0.5);
    EXPECT_NEAR(b.value("DACMON"), 2.5, 1e-3); // 1/16 rev
    ASSERT_EQ(b.drive.writeNamed("INDEX.DIST", "460"), "");
    b.drive.realTimeCall(2); // 716 counts = 6.99 V -> rolls over to -3.01 V
    b.run(0.5);
    EXPECT_NEAR(b.value("DACMON"), 716.0 / 4096 * 40 - 10, 1e-3);
}

TEST(Sc750Io, EncoderOutputEmitsFourCountsPerLine) { // ENC.OUT, L1675-L1685
    Bench b("ENABLE = 1\nINDEX.DIST = 8192\nGO.INCR\n");
    b.run(1.0);
    EXPECT_EQ(statusField(b.drive, "enc_out_counts"), "0"); // ENC.OUT = 0: the port is an input
    ASSERT_EQ(b.drive.writeNamed("ENC.OUT", "512"), "");
    ASSERT_EQ(b.drive.writeNamed("INDEX.DIST", "-4096"), "");
    b.drive.realTimeCall(2);
    b.run(1.0);
    EXPECT_EQ(statusField(b.drive, "enc_out_counts"), "-2048"); // one CCW rev of a 512-line encoder
}

TEST(Sc750Io, CwInhibitHoldsTheShaftRaisesCwinhAndPosError) { // L1484, L1853, L1861
    Bench b("ENABLE = 1\nINTR.CWINH = 1\nINTR.POS.ERROR = 1\nRUN.SPEED = 600\nGO.VEL\nHere:\nGOTO Here\nEND\n"
            "INTERRUPT CWINH\nPRINT \"cwinh\"\nEND INTERRUPT\n"
            "INTERRUPT POS.ERROR\nPRINT \"poserr\"; POS.ERROR > POS.ERROR.MOVING\nABORT.MOTION\nEND INTERRUPT\n");
    b.run(0.2);
    EXPECT_GT(b.value("POS.ERROR"), 0); // the following error at 600 RPM, well below POS.ERROR.MOVING
    EXPECT_LT(b.value("POS.ERROR"), 0.25 * b.value("POS.ERROR.MOVING"));
    EXPECT_EQ(runSimulatorCommand(b.drive, "limits on off"), "OK"); // INH+ active
    b.run(0.01);
    EXPECT_EQ(b.out, "cwinh\r\n");
    const double held = b.value("POSITION");
    b.run(0.5); // 600 RPM = 40,960 counts/s of command runs on; the shaft brakes to rest in 60 ms
    EXPECT_NEAR(b.value("POSITION"), held, 1300);
    EXPECT_EQ(b.out, "cwinh\r\nposerr-1 \r\n");
    EXPECT_EQ(b.value("INTR.POS.ERROR"), 0);
    EXPECT_NEAR(b.value("VELOCITY"), 0, 0.5);
    EXPECT_EQ(b.value("IN.POSITION"), 0);
    EXPECT_EQ(statusField(b.drive, "limit_pos"), "1");
    runSimulatorCommand(b.drive, "limits off off");
    b.run(0.5);
    EXPECT_EQ(b.value("POS.ERROR"), 0); // released, the position loop closes the error
    EXPECT_EQ(b.value("IN.POSITION"), 1);
}

TEST(Sc750Io, CcwInhibitDoesNotHoldClockwiseMotion) {
    Bench b("ENABLE = 1\nINTR.CCWINH = 1\nINDEX.DIST = 4096\nGO.INCR\nHere:\nGOTO Here\nEND\n"
            "INTERRUPT CCWINH\nPRINT \"ccwinh\"\nEND INTERRUPT\n");
    b.drive.setLimitSwitches(false, true);
    b.run(1.0);
    EXPECT_EQ(b.out, "ccwinh\r\n");
    EXPECT_EQ(b.value("POSITION"), 4096); // after the profile, the shaft settled on the target
    EXPECT_EQ(b.value("POS.ERROR"), 0);
}

TEST(Sc750Io, OverTravelInterruptsWhenPositionPassesTheLimits) { // L1845, L1854
    Bench b("ENABLE = 1\nCW.OT.LIMIT = 2000\nCCW.OT.LIMIT = -1000\nINTR.CWOT = 1\nINTR.CCWOT = 1\n"
            "TARGET.POS = 3000\nGO.ABS\nHere:\nGOTO Here\nEND\n"
            "INTERRUPT CCWOT\nPRINT \"ccwot\"; POSITION < -1000\nEND INTERRUPT\n"
            "INTERRUPT CWOT\nPRINT \"cwot\"; POSITION > 2000\nTARGET.POS = -3000\nGO.ABS\nEND INTERRUPT\n");
    b.run(2.0);
    EXPECT_EQ(b.out, "cwot-1 \r\nccwot-1 \r\n");
    EXPECT_EQ(b.value("POSITION"), -3000); // the interrupts only report: the limits stop nothing
}

TEST(Sc750Io, PacLanInterruptIsNeverAssertedOnOneAxis) {
    Bench b("INTR.PACLAN = 1\nPAUSE.TIME = 0.2\nPAUSE\nPRINT INTR.PACLAN\nEND\nINTERRUPT PACLAN\nPRINT \"lan\"\nEND "
            "INTERRUPT\n");
    b.run(0.5);
    EXPECT_EQ(b.out, " 1 \r\n");
}

TEST(Sc750Io, LevelTimerSwitchesItsOutputAfterTheDelay) { // TMRSET LEVEL, L2202-L2236
    Bench b("TMRSET(1, LEVEL, 0.1, OUT3=0, INP4=0)\nTMENABLE1 = 1\n");
    b.run(0.05);
    EXPECT_FALSE(b.drive.output(3));
    b.drive.setInput(4, false); // trigger: INP4 reaches 0
    b.run(0.09);
    EXPECT_FALSE(b.drive.output(3));
    EXPECT_EQ(b.value("TMOUT_1"), 0);
    b.run(0.02);
    EXPECT_TRUE(b.drive.output(3)); // OUT3 = 0: the transistor is on
    EXPECT_EQ(b.value("TMOUT_1"), 1);
    b.run(0.5);
    EXPECT_TRUE(b.drive.output(3)); // a LEVEL timer holds its output
}

TEST(Sc750Io, PulseTimerHoldsItsOutputForTheDuration) {
    Bench b("TMRSET(2, PULSE, 0.05, OUT5=0, INP6=0)\nTMENABLE2 = 1\n");
    b.run(0.05);
    b.drive.setInput(6, false);
    b.run(0.002);
    EXPECT_TRUE(b.drive.output(5));
    EXPECT_EQ(b.value("TMOUT_2"), 1);
    b.run(0.045);
    EXPECT_TRUE(b.drive.output(5));
    b.run(0.005);
    EXPECT_FALSE(b.drive.output(5));
    EXPECT_EQ(b.value("TMOUT_2"), 0);
    b.drive.setInput(6, true);
    b.run(0.01);
    b.drive.setInput(6, false); // re-armed while TMENABLE2 = 1
    b.run(0.002);
    EXPECT_TRUE(b.drive.output(5));
}

TEST(Sc750Io, DisabledTimerIgnoresItsInput) {
    Bench b("TMRSET(1, LEVEL, 0, OUT1=0, INP2=0)\n");
    b.drive.setInput(2, false);
    b.run(0.1);
    EXPECT_FALSE(b.drive.output(1));
}

} // namespace
} // namespace sc750_test
