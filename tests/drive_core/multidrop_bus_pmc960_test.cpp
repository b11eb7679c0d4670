// MultidropBus of PMC-960s (issue 21), as the attention-character section has them (L2537-2568): THI is each
// axis's ID; all listen at power-up (pmc960/DECISIONS.md), <attn> ID makes one the talker and only it echoes,
// prompts and answers polls, each keeps its own registers, selecting another silences the first, each finds
// the baud rate (autobaud) on its own; and the ID lists make() refuses.
#include "multidrop_bus_wire.h"

using drive_core::DriveFamily;
using drive_core::MultidropBus;
using multidrop_test::type;

namespace {
const std::string kAttn = "\x1d";

std::unique_ptr<MultidropBus> twoAxes() {
    return multidrop_test::poweredUp(DriveFamily::Pmc960, {"A", "B"});
}
} // namespace

TEST(MultidropBusPmc960, AllListenAtPowerUpAndTheSelectedOneTalks) {
    auto bus = twoAxes();
    EXPECT_EQ(type(*bus, "\r"), "") << "listeners act only on <attn> ID (L2559)";
    EXPECT_EQ(type(*bus, kAttn + "B"), "") << "a selection is not answered";
    EXPECT_EQ(type(*bus, "\r"), "\r\nB}") << "B alone prompts, with its THI ID";
    EXPECT_EQ(type(*bus, kAttn + "A\r"), "\r\nA}");
}

TEST(MultidropBusPmc960, EachAxisKeepsItsOwnRegisters) {
    auto bus = twoAxes();
    EXPECT_EQ(type(*bus, kAttn + "AA3500\r"), "A3500\r\nA}");
    EXPECT_EQ(type(*bus, kAttn + "BA?"), "A?4000\r\nB}") << "B is another drive";
    EXPECT_EQ(type(*bus, kAttn + "AA?"), "A?3500\r\nA}");
}

TEST(MultidropBusPmc960, SelectingAnotherSilencesTheFirst) {
    auto bus = twoAxes();
    // A's echo and answer are still in its UART when B is selected: A's drivers go off (L2555), and what
    // it had not sent never reaches the line; B says nothing until spoken to.
    EXPECT_EQ(type(*bus, kAttn + "AA?" + kAttn + "B"), "");
    EXPECT_EQ(type(*bus, "\r"), "\r\nB}");
    EXPECT_EQ(type(*bus, kAttn + "=\r"), "") << "no axis has ID '=' now: every axis listens";
}

TEST(MultidropBusPmc960, PollsReachTheTalkerAlone) {
    auto bus = twoAxes();
    EXPECT_EQ(type(*bus, kAttn + "g"), "") << "no talker: no answer";
    EXPECT_EQ(type(*bus, kAttn + "B" + kAttn + "g"), "0\r") << "one reply, B's (L2543)";
    type(*bus, "\r");
    const std::string block = "V200\r";
    type(*bus, kAttn + "h" + block);
    int sum = 0;
    for (char c : block) sum += c;
    EXPECT_EQ(type(*bus, kAttn + "h"), std::to_string(sum) + "\r") << "B's checksum (digest 4.8)";
    EXPECT_EQ(type(*bus, kAttn + "A" + kAttn + "h"), "0\r") << "A, a listener then, counted nothing";
}

TEST(MultidropBusPmc960, EachAxisAutobaudsOnItsOwnAndKeepsItsIdOverAPowerCycle) {
    auto bus = twoAxes();
    EXPECT_EQ(type(*bus, kAttn + "ASW1\rTHB0\r"), "SW1\r\nA}THB0\r\nA}") << "A: autobaud from the next power-up";
    bus->powerUp();
    EXPECT_EQ(type(*bus, ""), "") << "both listen again";
    EXPECT_EQ(type(*bus, kAttn + "BA?"), "A?4000\r\nB}") << "B has its baud rate";
    EXPECT_EQ(type(*bus, kAttn + "AA?"), "") << "A waits for a CR to find the baud rate (L843)";
    EXPECT_EQ(type(*bus, "\r"), "\r\nA}");
    EXPECT_EQ(type(*bus, "A?"), "A?4000\r\nA}");
}

TEST(MultidropBusPmc960, ASoftwareResetKeepsTheTalker) {
    auto bus = twoAxes();
    const std::string answer = type(*bus, kAttn + "AN*\r");
    EXPECT_EQ(answer.substr(answer.size() - 4), "\r\nA}") << answer;
    EXPECT_EQ(type(*bus, "A?"), "A?4000\r\nA}");
}

TEST(MultidropBusPmc960, TheBenchReachesTheAxisChosen) {
    auto bus = twoAxes();
    EXPECT_TRUE(bus->setBenchAxis("B"));
    bus->setInput(1, true);
    EXPECT_TRUE(bus->axis(1).input(1));
    EXPECT_FALSE(bus->axis(0).input(1));
    EXPECT_FALSE(bus->setBenchAxis("a"));
}

TEST(MultidropBusPmc960, WhatCannotBeABus) {
    std::string why;
    for (const char* bad : {"a", "AB", " ", "[", ""}) {
        EXPECT_FALSE(MultidropBus::make(DriveFamily::Pmc960, {"A", bad}, why)) << bad;
        EXPECT_NE(why.find("is not a PMC-960 axis ID"), std::string::npos) << why;
        EXPECT_NE(why.find("L1918"), std::string::npos) << why;
    }
    EXPECT_FALSE(MultidropBus::make(DriveFamily::Pmc960, {"A", "B", "A"}, why));
    EXPECT_NE(why.find("axis ID A is on the bus twice"), std::string::npos) << why;
    std::vector<std::string> many;
    for (char c = '0'; c <= '9'; ++c) many.emplace_back(1, c);
    for (char c = 'A'; c <= 'Z'; ++c) many.emplace_back(1, c);
    EXPECT_FALSE(MultidropBus::make(DriveFamily::Pmc960, many, why));
    many.resize(32);
    EXPECT_TRUE(MultidropBus::make(DriveFamily::Pmc960, many, why)) << why;
}
