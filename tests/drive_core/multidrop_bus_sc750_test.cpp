// MultidropBus of SC750s (issue 21), as Appendix C has them (L3676-3734): all logged off at power-up, "/nnn"
// logs one on and only it answers Motion Dialogue's frames, each keeps its own variables, logging on another
// silences the first; and the address lists make() refuses. Frames as on the wire (sc750/PROTOCOL.md).
#include "drive_core/sc750/sc750_frame.h"
#include "multidrop_bus_wire.h"

using drive_core::DriveFamily;
using drive_core::MultidropBus;
using drive_core::sc750::encodeFrame;
using multidrop_test::type;

namespace {
std::unique_ptr<MultidropBus> threeAxes() {
    return multidrop_test::poweredUp(DriveFamily::Sc750, {"1", "2", "17"});
}

std::string read(const std::string& name) {
    return encodeFrame('G', name);
}

std::string value(const std::string& name, const std::string& text) {
    return encodeFrame('G', name + "=" + text);
}
} // namespace

TEST(MultidropBusSc750, AllLoggedOffAtPowerUpAndOneAnswersWhenLoggedOn) {
    auto bus = threeAxes();
    EXPECT_EQ(type(*bus, encodeFrame('?', "")), "") << "no unit is logged on: none may transmit (L3712)";
    EXPECT_EQ(type(*bus, "/2"), "") << "a logon is not answered";
    EXPECT_EQ(type(*bus, read("AXIS.ADDR")), value("AXIS.ADDR", "2")) << "2 alone answers";
    EXPECT_EQ(type(*bus, "/017" + read("AXIS.ADDR")), value("AXIS.ADDR", "17"));
    EXPECT_EQ(type(*bus, "/1," + read("LOGGEDON")), value("LOGGEDON", "1")) << "ended by a non-digit (L3706)";
    EXPECT_EQ(type(*bus, encodeFrame('V', "")), encodeFrame('V', "752,2.8,1,1"));
}

TEST(MultidropBusSc750, EachAxisKeepsItsOwnVariables) {
    auto bus = threeAxes();
    EXPECT_EQ(type(*bus, "/1" + encodeFrame('P', "RUN.SPEED=500")), encodeFrame('P', "RUN.SPEED=500"));
    EXPECT_EQ(type(*bus, "/2" + read("RUN.SPEED")), value("RUN.SPEED", "1000")) << "2 is another drive";
    EXPECT_EQ(type(*bus, "/1" + read("RUN.SPEED")), value("RUN.SPEED", "500"));
}

TEST(MultidropBusSc750, LoggingOnAnotherSilencesTheFirst) {
    auto bus = threeAxes();
    EXPECT_EQ(type(*bus, "/1" + read("LOGGEDON")), value("LOGGEDON", "1"));
    // 1's answer is still in its UART when 2 is logged on: 1 turns its transmitter off (L3714), and the
    // line carries nothing. (Three digits end a logon; one or two wait for the next byte, L3712.)
    EXPECT_EQ(type(*bus, read("AXIS.ADDR") + "/002"), "");
    EXPECT_EQ(type(*bus, read("LOGGEDON")), value("LOGGEDON", "1")) << "2 answers, and 2 alone";
    EXPECT_EQ(type(*bus, "/1" + read("LOGGEDON")), value("LOGGEDON", "1"));
    EXPECT_EQ(type(*bus, "/3" + read("LOGGEDON")), "") << "no unit 3: every transmitter is off";
}

TEST(MultidropBusSc750, ASlashInsideAFrameIsNoLogon) {
    auto bus = threeAxes();
    type(*bus, "/1");
    // The logged-off units skip the frame for 1, so its "/2" does not log 2 on (PROTOCOL.md 2).
    const std::string answer = type(*bus, encodeFrame('P', "RUN.SPEED=/2"));
    EXPECT_EQ(answer.substr(0, 2), "\x01!") << "1 refuses the value, and 1 alone answers: " << answer;
    EXPECT_EQ(type(*bus, read("AXIS.ADDR")), value("AXIS.ADDR", "1"));
}

TEST(MultidropBusSc750, TheBenchReachesTheAxisChosen) {
    auto bus = threeAxes();
    EXPECT_TRUE(bus->setBenchAxis("17"));
    bus->setInput(3, false);
    EXPECT_EQ(type(*bus, "/17" + read("INP3")), value("INP3", "0"));
    EXPECT_EQ(type(*bus, "/1" + read("INP3")), value("INP3", "1"));
    EXPECT_FALSE(bus->setBenchAxis("3"));
}

TEST(MultidropBusSc750, WhatCannotBeABus) {
    std::string why;
    for (const char* bad : {"255", "256", "07", "-1", "A", "", "1000"}) {
        EXPECT_FALSE(MultidropBus::make(DriveFamily::Sc750, {"1", bad}, why)) << bad;
        EXPECT_NE(why.find("is not an SC750 multidrop address"), std::string::npos) << why;
        EXPECT_NE(why.find("L3708"), std::string::npos) << why;
    }
    EXPECT_FALSE(MultidropBus::make(DriveFamily::Sc750, {"0", "254", "0"}, why));
    EXPECT_NE(why.find("axis ID 0 is on the bus twice"), std::string::npos) << why;
    std::vector<std::string> many;
    for (int a = 0; a < 33; ++a) many.push_back(std::to_string(a * 7));
    EXPECT_FALSE(MultidropBus::make(DriveFamily::Sc750, many, why)) << "1 to 32 units on a line (L3682)";
    EXPECT_NE(why.find("1 to 32 axes"), std::string::npos) << why;
    many.resize(32);
    EXPECT_TRUE(MultidropBus::make(DriveFamily::Sc750, many, why)) << why;
}
