// Electronic camming (v3.0, L9358-9569) with the manual's cam test program (examples/bds5/68, OCR fixed:
// ";1$" -> "1$", ";xi = 100" -> "X1 = 100", ";2$" -> "2$"): a triangle table in X100-X227 cycled by VOFF
// 20 RPM; PCAM follows the table with 256 interpolated steps per point and the motor follows PCAM.
#include "bds5_test_drive.h"

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
// The triangle of the test program: 0, 100, ... 6400 at X164, then down by 100 to 100 at X227.
double triangle(int pcmd) {
    const double point = double(pcmd) / 256;
    return point <= 64 ? point * 100 : (128 - point) * 100;
}

void loadCamTest(TestDrive& t) {
    t.download({"1$", "X1 = 100", "2$", "X(X1) = (X1-100)*100", "X1 = X1+1", "? X1 LE 164 GOTO 2", "3$",
                "X(X1) = X164-(X1-164)*100", "X1 = X1+1", "? X1 LE 227 GOTO 3", "4$", "PLIM OFF", "GEAR OFF", "EN",
                "NORM 0 CAM", "GEAR ON", "VOFF 20", "B"});
}
} // namespace

TEST(Bds5Cam, TestProgram68CyclesThroughTheTriangleTable) {
    TestDrive t;
    loadCamTest(t);
    EXPECT_EQ(t.type("RUN 1\r", 2000ms), "RUN 1\r\n-->");
    EXPECT_EQ(value(t, "X164"), "6400");
    EXPECT_EQ(value(t, "X227"), "100");
    EXPECT_EQ(value(t, "CAM"), "1");
    for (int i = 0; i < 4; ++i) { // up the triangle, over its top and down again: 20 RPM ~ 1365 counts/s
        t.wait(5000ms);
        const auto& vars = t.drive.state().variables; // both at the same instant
        const int pcmd = vars.read("PCMD").value_or(-1);
        const int pcam = vars.read("PCAM").value_or(-1);
        EXPECT_NEAR(pcam, triangle(pcmd), 1) << "PCAM interpolated from the table at PCMD " << pcmd;
        EXPECT_LT(std::abs(vars.read("PE").value_or(99)), 60) << "the motor follows PCAM (PE = PCAM - PFB)";
    }
    EXPECT_GT(number(t, "PCMD"), 16384) << "past the top of the triangle after ~21 s";
    t.wait(6000ms); // one cycle is 32768 counts, ~24 s: PCMD rolls over
    EXPECT_LT(number(t, "PCMD"), 8000) << "PCMD is rotary with 32768 counts a cycle";
}

TEST(Bds5Cam, ProfilesAreRefusedAndDisablingEndsCamming) { // L9470-9476
    TestDrive t;
    loadCamTest(t);
    t.type("RUN 1\r", 2000ms);
    EXPECT_NE(t.type("MI 1000\r").find("\aERR"), std::string::npos) << "MI is not allowed while camming";
    EXPECT_NE(t.type("J 10\r").find("\aERR"), std::string::npos) << "J is not allowed while camming";
    t.type("DIS\r");
    EXPECT_EQ(value(t, "CAM"), "0") << "disabling turns camming off";
}

TEST(Bds5Cam, NormCamNeedsAnEnabledDriveAndGearOff) { // L9430-9460
    TestDrive t;
    EXPECT_NE(t.type("NORM 0 CAM\r").find("\aERR 50"), std::string::npos);
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("GEAR ON\r");
    EXPECT_NE(t.type("NORM 0 CAM\r").find("\aERR 56"), std::string::npos);
    t.type("GEAR OFF\r");
    t.type("X100=500\r");
    t.type("X101=756\r");
    EXPECT_EQ(t.type("NORM 128 CAM\r"), "NORM 128 CAM\r\n-->");
    EXPECT_EQ(value(t, "PCAM"), "628") << "halfway between X100 and X101";
    EXPECT_EQ(value(t, "PFB"), "628") << "PFB := PCAM, PE = 0";
    EXPECT_EQ(value(t, "PCMD"), "128");
    t.type("NORM 0\r");
    EXPECT_EQ(value(t, "CAM"), "0") << "NORM without CAM ends camming";
}

TEST(Bds5Cam, SoftwareOvertravelWhileCammingDisables) { // L9472: ERR 23 disables when camming
    TestDrive t;
    t.type("X100=0\r");
    for (int i = 101; i <= 227; ++i) t.type("X" + std::to_string(i) + "=5000\r");
    t.type("PMAX=1000\r");
    t.type("EN\r");
    t.type("NORM 0 CAM\r"); // PLIM stays on
    t.type("GEAR ON\r");
    t.type("VOFF 20\r", 400ms); // PCAM climbs from 0 toward 5000 over the first 256 counts of PCMD
    EXPECT_NE(t.type("\r").find("\aERR 23"), std::string::npos);
    EXPECT_EQ(value(t, "READY"), "0") << "disabled, not only stopped";
    EXPECT_EQ(value(t, "CAM"), "0") << "re-normalise after a disabling error";
}
