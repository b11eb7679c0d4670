// The bench's electronic line shaft (issue 21): one BDS5 axis's encoder output wired to another's master
// input, so the follower's gearbox (GEAR ON, GEARI/GEARO, L2970-3000) follows a real moving master axis.
#include "multidrop_bus_wire.h"

#include "drive_core/bds5/bds5_drive.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

using namespace std::chrono_literals;
using drive_core::DriveFamily;
using drive_core::MultidropBus;
using multidrop_test::poweredUp;
using multidrop_test::type;

namespace {
// The number P prints on the awake axis ("P PFB\r\n        1234\r\nB->").
long long printed(MultidropBus& bus, const std::string& name) {
    const std::string answer = type(bus, "P " + name + "\r");
    const std::size_t start = answer.find("\r\n") + 2;
    return std::stoll(answer.substr(start, answer.find("\r\n", start) - start));
}
} // namespace

TEST(MultidropLineShaft, TheFollowersGearboxCountsWhatTheMasterTurned) {
    auto bus = poweredUp(DriveFamily::Bds5, {"A", "B"});
    ASSERT_TRUE(bus);
    type(*bus, "\\B");
    for (const char* line : {"PLIM OFF\r", "GEARI=1\r", "GEARO=1\r", "EN\r", "GEAR ON\r"}) type(*bus, line);
    const long long followerStart = printed(*bus, "PCMD");
    std::string why;
    ASSERT_TRUE(bus->setLineShaft("A", "B", why)) << why;

    type(*bus, "\\A");
    for (const char* line : {"PLIM OFF\r", "EN\r"}) type(*bus, line);
    const long long masterStart = printed(*bus, "PFB");
    type(*bus, "MI 8192 600\r"); // two revolutions of the master at 600 RPM: done in well under a second
    for (int i = 0; i < 3000; ++i) bus->step(1ms);
    bus->takeTransmitted();
    const long long masterTurned = printed(*bus, "PFB") - masterStart;
    EXPECT_NEAR(double(masterTurned), 8192, 4) << "the master moved";

    type(*bus, "\\B");
    const double expected = double(masterTurned) / 4096.0 * MultidropBus::kLineShaftCountsPerRev; // GEARI = GEARO
    EXPECT_NEAR(double(printed(*bus, "PCMD") - followerStart), expected, 1.0)
        << "every count the master's encoder output sent reached the follower";
    for (int i = 0; i < 1000; ++i) bus->step(1ms);
    bus->takeTransmitted();
    EXPECT_NEAR(double(printed(*bus, "PFB")), double(printed(*bus, "PCMD")), 2.0) << "and its motor followed";
}

TEST(MultidropLineShaft, RefusesWhatCannotBeWired) {
    auto bus = poweredUp(DriveFamily::Bds5, {"A", "B"});
    ASSERT_TRUE(bus);
    std::string why;
    EXPECT_FALSE(bus->setLineShaft("A", "C", why));
    EXPECT_EQ(why, "no axis C on this line");
    EXPECT_FALSE(bus->setLineShaft("A", "A", why));
    EXPECT_EQ(why, "an axis cannot follow itself");
    EXPECT_TRUE(bus->setLineShaft("A", "B", why));
    bus->clearLineShafts();
    EXPECT_EQ(bus->axis(1).controls()->status().masterFrequency_Hz, 0) << "unwired, the follower's input is still";
}
