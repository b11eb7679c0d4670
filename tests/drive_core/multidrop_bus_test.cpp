// MultidropBus (issue 21): BDS5 axes A-D on one line, as the manual's multidrop section has them (L5416-5469,
// L10013-10038): all asleep at power-up, one woken by '\' + its ID answers alone, each keeps its own
// variables, a broadcast reaches every axis and none answers it; and the buses make() refuses.
#include "multidrop_bus_wire.h"

#include <gtest/gtest.h>

#include <chrono>

using drive_core::DriveFamily;
using drive_core::MultidropBus;
using namespace std::chrono_literals;

namespace {
using multidrop_test::type;

std::unique_ptr<MultidropBus> fourAxes() {
    std::string why;
    auto bus = MultidropBus::make(DriveFamily::Bds5, {"A", "B", "C", "D"}, why);
    EXPECT_TRUE(bus) << why;
    bus->powerUp();
    // Each axis signs on into its own UART, asleep: not on the line, but it takes the UART's time (L5428).
    for (int i = 0; i < 200; ++i) bus->step(1ms);
    EXPECT_EQ(bus->takeTransmitted(), "");
    return bus;
}
} // namespace

TEST(MultidropBus, AllAsleepAtPowerUpAndOneAnswersWhenCalled) {
    auto bus = fourAxes();
    EXPECT_EQ(type(*bus, ""), "") << "a multidrop drive signs on asleep: nothing on the line";
    EXPECT_EQ(type(*bus, "\r"), "");
    EXPECT_EQ(type(*bus, "\\B"), "\r\nB->") << "B alone answers, its ID first in the prompt (Table 4.17)";
    EXPECT_EQ(type(*bus, "X1=5\r"), "X1=5\r\nB->");
    EXPECT_EQ(type(*bus, "\\A"), "\r\nA->");
    EXPECT_EQ(type(*bus, "P X1\r"), "P X1\r\n           0\r\nA->") << "A is another drive";
    EXPECT_EQ(type(*bus, "\\B"), "\r\nB->");
    EXPECT_EQ(type(*bus, "P X1\r"), "P X1\r\n           5\r\nB->");
}

TEST(MultidropBus, ABroadcastReachesEveryAxisAndNoneAnswers) {
    auto bus = fourAxes();
    EXPECT_EQ(type(*bus, "\\\\*X2=7\r"), "") << "'\\' puts all to sleep, '\\*' broadcasts (L10017-10019)";
    for (const char* id : {"A", "B", "C", "D"}) {
        EXPECT_EQ(type(*bus, std::string("\\") + id), std::string("\r\n") + id + "->");
        EXPECT_EQ(type(*bus, "P X2\r"), std::string("P X2\r\n           7\r\n") + id + "->");
    }
}

TEST(MultidropBus, TheBenchReachesTheAxisChosen) {
    auto bus = fourAxes();
    EXPECT_TRUE(bus->setBenchAxis("C"));
    EXPECT_EQ(bus->benchAxis(), 2u);
    bus->setInput(1, true);
    EXPECT_TRUE(bus->axis(2).input(1));
    EXPECT_FALSE(bus->axis(0).input(1));
    EXPECT_FALSE(bus->setBenchAxis("Q"));
}

TEST(MultidropBus, WhatCannotBeABus) {
    std::string why;
    EXPECT_FALSE(MultidropBus::make(DriveFamily::Bds5, {"A", "a"}, why));
    EXPECT_NE(why.find("not a BDS5 axis ID"), std::string::npos) << why;
    EXPECT_FALSE(MultidropBus::make(DriveFamily::Bds5, {"A", "B", "A"}, why));
    EXPECT_NE(why.find("twice"), std::string::npos) << why;
    std::vector<std::string> many;
    for (char c = '0'; c <= '9'; ++c) many.emplace_back(1, c);
    for (char c = 'A'; c <= 'Z'; ++c) many.emplace_back(1, c);
    EXPECT_FALSE(MultidropBus::make(DriveFamily::Bds5, many, why)) << "36 IDs, but a line carries 32 axes (L10013)";
    many.resize(32);
    EXPECT_TRUE(MultidropBus::make(DriveFamily::Bds5, many, why)) << why;
}
