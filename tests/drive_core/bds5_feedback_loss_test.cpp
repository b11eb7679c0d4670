// Feedback loss (ERR 17, L7201) from the simulator bench, and the outputs of §6.4 that show it: the fault
// disables the drive and sets FAULT, STATUS drops (the fail-safe brake engages), the relay (hardware
// watchdog OK) stays closed. Through SimulatorControls and the side channel's text form.
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

TEST(Bds5FeedbackLoss, BrokenResolverWiresAreErr17AndDisable) {
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("J 100\r", 200ms);
    auto& bench = *t.drive.controls();
    EXPECT_TRUE(bench.status().brakeReleased) << "enabled: STATUS releases the brake";
    EXPECT_TRUE(bench.status().relayClosed);
    bench.setFeedbackConnected(false);
    t.wait(5ms);
    const std::string out = t.type("\r"); // the held asynchronous message
    EXPECT_NE(out.find("\aERR 17"), std::string::npos) << out;
    EXPECT_NE(out.find("FEEDBACK LOSS"), std::string::npos) << out;
    EXPECT_EQ(value(t, "READY"), "0") << "severity 3 disables";
    EXPECT_EQ(value(t, "FAULT"), "1");
    EXPECT_FALSE(bench.status().brakeReleased) << "STATUS off: the brake holds";
    EXPECT_TRUE(bench.status().relayClosed) << "the relay is the hardware watchdog, still OK";
    EXPECT_FALSE(bench.status().feedbackConnected);
    t.type("EN\r", 5ms);
    EXPECT_NE(t.type("\r").find("\aERR 17"), std::string::npos) << "enabling faults again while broken";
    EXPECT_EQ(value(t, "READY"), "0");
    bench.setFeedbackConnected(true);
    t.type("EN\r", 5ms);
    t.type("\r");
    EXPECT_EQ(value(t, "READY"), "1") << "wires mended: EN works and clears FAULT";
    EXPECT_EQ(value(t, "FAULT"), "0");
}

TEST(Bds5FeedbackLoss, SideChannelFeedbackLine) {
    TestDrive t;
    t.type("EN\r");
    auto& bench = *t.drive.controls();
    EXPECT_EQ(drive_core::runSimulatorCommand(bench, "feedback off"), "OK");
    t.wait(5ms);
    const std::string status = drive_core::runSimulatorCommand(bench, "status");
    EXPECT_NE(status.find(" feedback=0"), std::string::npos) << status;
    EXPECT_NE(status.find(" fault=1"), std::string::npos) << status;
    EXPECT_NE(status.find(" relay=1"), std::string::npos) << status;
    EXPECT_NE(status.find(" brake_released=0"), std::string::npos) << status;
    EXPECT_EQ(drive_core::runSimulatorCommand(bench, "feedback on"), "OK");
    EXPECT_EQ(drive_core::runSimulatorCommand(bench, "feedback"), "ERROR wrong number of arguments for feedback");
    EXPECT_EQ(drive_core::runSimulatorCommand(bench, "feedback maybe"), "ERROR expected on or off");
}
