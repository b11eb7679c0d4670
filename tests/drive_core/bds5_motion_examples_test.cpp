// The manual's motion examples reaching their stated outcomes on the simulated motor: registration
// (examples/bds5/10), clamping (09), profile regulation (16, 17), the regulated dwell (55), the gearbox
// phase adjust (15) and the cam test (68). Each asserts what the terminal shows.
#include "bds5_test_drive.h"

#include "drive_core/simulator_controls.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace bds5_test;

namespace {
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return out.substr(start, out.find("\r\n", start) - start);
}
int number(TestDrive& t, const std::string& name) {
    return std::stoi(value(t, name));
}
} // namespace

// L2771-2780: J 2000, capture the registration mark, JT PCAP+4000 0 stops 4000 counts past it. Unity
// feed-forward (KF 16384): PCAP is where the motor was, and with KF 0 the command runs ~6000 counts ahead
// of the motor at 2000 RPM, already past PCAP+4000 (ERR 42).
TEST(Bds5MotionExamples, Registration10StopsFourThousandCountsPastTheMark) {
    TestDrive t;
    t.drive.controls()->setHomeSwitchPosition_rev(2); // the mark: rising edge at 2 - 1/64 rev = 8128
    t.download({"10$", "PLIM OFF", "KF=16384", "EN", "CAPDIR 1", "CAP ON", "J 2000", "TIL CAP EQ 0", "JT PCAP+4000 0",
                "W 0", "D 300", "P PCAP", "P PCMD-PCAP", "P PFB-PCAP", "B"});
    EXPECT_EQ(t.type("RUN 10\r", 3000ms), "RUN 10\r\n        8128\r\n        4000\r\n        4000\r\n-->");
}

// L2788-2799: the same with JT PCAP+4000 100: the speed is just reaching 100 RPM 4000 counts past the mark.
TEST(Bds5MotionExamples, Registration10ChangesSpeedAtTheMarkPlusFourThousand) {
    TestDrive t;
    t.drive.controls()->setHomeSwitchPosition_rev(2);
    t.download({"11$", "PLIM OFF", "KF=16384", "EN", "CAPDIR 1", "CAP ON", "J 2000", "TIL CAP EQ 0", "JT PCAP+4000 100",
                "W 3", "P PCMD-PCAP", "P VCMD", "B"});
    const std::string out = t.type("RUN 11\r", 2000ms);
    ASSERT_EQ(count(out, "\r\n"), 3) << out;
    const int past = std::stoi(out.substr(out.find("\r\n") + 2));
    EXPECT_GE(past, 4000) << "segment 3 begins at the position";
    EXPECT_LE(past, 4000 + 2 * 7) << "within the W's own 2 ms at 100 RPM (7 counts/ms)";
    EXPECT_NE(out.find("         100\r\n-->"), std::string::npos) << out;
}

// L2674-2700 with '?' for the OCR's block IF: no part in the way, the move reaches 100000.
TEST(Bds5MotionExamples, Clamping09WithoutAPartReachesTheEnd) {
    TestDrive t;
    t.download({"9$", "PLIM OFF", "KF=16384", "EN", "PECLAMP=1000", "CLAMP ON", "MA 100000 400", "W 0",
                "? PCMD EQ 100000 P \"PART NOT FOUND\"", "B"});
    EXPECT_EQ(t.type("RUN 9\r", 20000ms), "RUN 9\r\nPART NOT FOUND\r\n-->");
}

// A part in the way (the shaft held by a load it cannot move at ILIM): PE passes PECLAMP, the profile
// stops (SEG 0), PCMD stays short of 100000 and PE stays near PECLAMP (L2665-2672).
TEST(Bds5MotionExamples, Clamping09StopsAtThePartAndHoldsAtPeclamp) {
    TestDrive t;
    t.download({"9$", "PLIM OFF", "KF=16384", "EN", "PECLAMP=1000", "CLAMP ON", "MA 100000 400", "W 0",
                "? PCMD EQ 100000 P \"PART NOT FOUND\"", "P \"CLAMPED\"", "B"});
    t.type("ILIM=5\r");
    t.drive.controls()->setLoadInertia_kgm2(1e4); // the part: the shaft barely moves
    EXPECT_EQ(t.type("RUN 9\r", 3000ms), "RUN 9\r\nCLAMPED\r\n-->");
    EXPECT_EQ(value(t, "SEG"), "0");
    EXPECT_LT(number(t, "PCMD"), 100000);
    EXPECT_NEAR(number(t, "PE"), 1000, 60) << "PE stays at about PECLAMP";
    t.wait(1000ms);
    EXPECT_NEAR(number(t, "PE"), 1000, 60) << "held against the stop at ILIM";
    t.type("ZPE\r");
    EXPECT_EQ(value(t, "PE"), "0") << "ZPE before new motion (L2670)";
}

// L3089-3113: REGKHZ 780 with MI 4096 400 and REGKHZ 1560 with MI 4096 800 are the same move at
// 780 kHz (the same 400 RPM traverse; the ramps, scaled in time, differ by a few ms); at half the external
// frequency the move takes twice as long; above REGKHZ it runs as specified, never faster.
TEST(Bds5MotionExamples, Regulation16And17AreTheSameMove) {
    struct Run {
        int ms = -1;
        int traverse_rpm = 0;
    };
    const auto regulatedMove = [](int regkhz, int rpm, double master_hz) {
        TestDrive t;
        t.type("PLIM OFF\r");
        t.type("EN\r");
        t.type("REG ON\r");
        t.type("REGKHZ=" + std::to_string(regkhz) + "\r");
        t.drive.controls()->setMasterFrequency_Hz(master_hz);
        t.drive.receive("MI 4096 " + std::to_string(rpm) + "\r");
        Run run;
        for (int ms = 1; ms <= 10000 && run.ms < 0; ++ms) {
            t.drive.step(std::chrono::milliseconds(1));
            if (ms == 60) run.traverse_rpm = t.drive.state().variables.read("VCMD").value_or(0);
            if (t.drive.state().variables.read("SEG").value_or(-1) == 0) run.ms = ms;
        }
        t.wait(200ms);
        EXPECT_EQ(value(t, "PCMD"), "4096") << "the distance is unchanged";
        return run;
    };
    const Run example1 = regulatedMove(780, 400, 780e3);
    const Run example2 = regulatedMove(1560, 800, 780e3);
    EXPECT_EQ(example1.traverse_rpm, 400);
    EXPECT_EQ(example2.traverse_rpm, 400) << "800 RPM at half of REGKHZ";
    EXPECT_NEAR(example1.ms, 154, 3) << "one revolution at 400 RPM (27307 counts/s) with 4 ms ramps";
    EXPECT_NEAR(example2.ms, example1.ms, 14) << "the same move but for the time-scaled ramps";
    EXPECT_NEAR(regulatedMove(780, 400, 390e3).ms, 2 * example1.ms, 4) << "half the frequency: twice the time";
    EXPECT_NEAR(regulatedMove(780, 400, 2e6).ms, example1.ms, 2) << "never faster than specified";
}

TEST(Bds5MotionExamples, RegulationWithoutExternalInputDoesNotMove) { // Hint L5990: VEXT must be > 0
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("REG ON\r");
    t.type("MI 4096 400\r", 1000ms);
    EXPECT_EQ(value(t, "PCMD"), "0");
    EXPECT_EQ(value(t, "SEG"), "1") << "the profile is commanded but does not advance";
}

TEST(Bds5MotionExamples, BackwardRegulationBeyondThirtyThousandCountsIsErr64) { // L7334
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("REG ON\r");
    t.type("REGKHZ=100\r");
    t.drive.controls()->setMasterFrequency_Hz(100e3);
    t.type("MI 40960 100\r", 100ms);
    t.drive.controls()->setMasterFrequency_Hz(-100e3); // counting back: the profile halts
    const int halted = number(t, "PCMD");
    t.wait(200ms);
    EXPECT_NEAR(number(t, "PCMD"), halted, 10) << "halted while counting back";
    EXPECT_EQ(value(t, "READY"), "1") << "25000 counts back is allowed";
    t.wait(200ms);
    EXPECT_NE(t.type("\r").find("\aERR 64"), std::string::npos) << "beyond 30000 counts back";
    EXPECT_EQ(value(t, "READY"), "0") << "severity 3: disabled";
}

// L5827-5839: RD 2000 at REGKHZ 100 lasts 2 s at 100 kHz and 4 s at 50 kHz; REG need not be on.
TEST(Bds5MotionExamples, RegulatedDwell55LastsAsLongAsTheExternalInputSays) {
    for (const double hz : {100e3, 50e3}) {
        TestDrive t;
        t.download({"45$", "REGKHZ 100", "RD 2000", "P \"DELAY COMPLETE\"", "B"});
        t.drive.controls()->setMasterFrequency_Hz(hz);
        const int seconds = hz == 100e3 ? 2 : 4;
        EXPECT_EQ(t.type("RUN 45\r", std::chrono::milliseconds(seconds * 1000 - 100)), "RUN 45\r\n") << hz;
        EXPECT_EQ(t.wait(200ms), "DELAY COMPLETE\r\n-->") << hz;
    }
}

// L3008-3020: with GEAR on, MI 1028 10 shifts the phase by 1028 counts while the motor follows the master.
TEST(Bds5MotionExamples, GearboxPhaseAdjust15) {
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("GEARI=1\r");
    t.type("GEARO=1\r");
    t.type("EN\r");
    t.type("GEAR ON\r");
    const auto phase = [&] { // PCMD - PEXT with the master standing still
        t.drive.controls()->setMasterFrequency_Hz(0);
        return number(t, "PCMD") - number(t, "PEXT");
    };
    t.drive.controls()->setMasterFrequency_Hz(4096); // one master revolution a second
    t.wait(1000ms);
    const int before = phase();
    t.drive.controls()->setMasterFrequency_Hz(4096);
    t.type("MI 1028 10\r", 3000ms); // 1028 counts at 10 RPM: about 1.5 s
    EXPECT_EQ(value(t, "GEAR"), "1") << "the system remains in gearbox through the adjustment";
    EXPECT_LT(std::abs(number(t, "PE")), 200) << "the motor follows (KF 0: a following error)";
    const int after = phase();
    EXPECT_EQ(after - before, 1028) << "the phase moved by the MI's distance";
}

// L2702-2712, clamping as homing: a slow jog at low ILIM goes on until it meets the stop; SEG 0 says it
// has clamped. (The simulated stop is a load the motor cannot move at ILIM.)
TEST(Bds5MotionExamples, ClampingAJogRunsUntilTheStop) {
    for (const bool stop : {false, true}) {
        TestDrive t;
        t.type("PLIM OFF\r");
        t.type("EN\r");
        t.type("PECLAMP=300\r");
        t.type("CLAMP ON\r");
        t.type("ILIM=5\r");
        if (stop) t.drive.controls()->setLoadInertia_kgm2(1e4);
        t.type("J 20\r", 2000ms);
        if (!stop) {
            EXPECT_EQ(value(t, "SEG"), "2") << "no stop: the jog goes on";
            continue;
        }
        EXPECT_EQ(value(t, "SEG"), "0") << "clamped";
        EXPECT_NEAR(number(t, "PE"), 300, 30);
    }
}
