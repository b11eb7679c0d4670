// Position capture on the HOME input and trip points, on the simulated motor (L2615-2657, L2237-2275):
// the manual's fast homing program finds the switch edge to the count, and TRIP1/TRIP2 follow PFB.
#include "bds5_test_drive.h"

#include "drive_core/simulator_controls.h"

#include <gtest/gtest.h>

using namespace bds5_test;

namespace {
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return out.substr(start, out.find("\r\n", start) - start);
}
} // namespace

// The HOME switch closes 1/64 revolution either side of 0.25 rev, so its rising edge coming from 0 is at
// 0.25 - 1/64 rev = 960 counts; captured at 500 RPM (34 counts a millisecond) it is still exact.
TEST(Bds5Capture, FastHomingCapturesTheSwitchEdge) { // L2640-2652
    TestDrive t;
    t.drive.controls()->setHomeSwitchPosition_rev(0.25);
    t.download({"1$", "PLIM OFF", "EN", "CAPDIR=1", "CAP ON", "J 500", "TIL CAP EQ 0", "J 0", "W 0", "MA PCAP 20",
                "W 0", "D 300", "P PCAP", "P PFB", "B"});
    const std::string out = t.type("RUN 1\r", 3000ms);
    EXPECT_EQ(out, "RUN 1\r\n         960\r\n         960\r\n-->") << "PCAP, then the motor back on it";
}

TEST(Bds5Capture, CapdirZeroCapturesTheFallingEdgeAndWritingItDisarms) {
    TestDrive t;
    t.drive.controls()->setHomeSwitchPosition_rev(0.25);
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("CAP ON\r");
    t.type("CAPDIR=0\r");
    EXPECT_EQ(value(t, "CAP"), "0") << "writing CAPDIR turns CAP off";
    t.type("CAP ON\r");
    t.type("J 100\r", 500ms); // 100 RPM: 0.25 rev + 1/64 is passed after about 0.17 s
    EXPECT_EQ(value(t, "CAP"), "0");
    EXPECT_EQ(value(t, "PCAP"), "1088") << "the falling edge: 0.25 + 1/64 rev";
}

TEST(Bds5Capture, BenchHomeInputCapturesAtTheTick) {
    TestDrive t;
    t.type("NORM 5000\r");
    t.type("CAP ON\r");
    t.drive.controls()->setHomeSwitch(true);
    t.wait(2ms);
    EXPECT_EQ(value(t, "CAP"), "0");
    EXPECT_EQ(value(t, "PCAP"), "5000");
}

TEST(Bds5TripPoints, TripSwitchesFollowPfb) { // TRIP1 = PFB >= PTRIP1
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("PTRIP1=1000\r");
    t.type("PTRIP2=5000\r");
    t.type("EN\r", 5ms);
    EXPECT_EQ(value(t, "TRIP1"), "0");
    t.type("MI 2000 100\r", 1500ms);
    EXPECT_EQ(value(t, "TRIP1"), "1");
    EXPECT_EQ(value(t, "TRIP2"), "0");
}
