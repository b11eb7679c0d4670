// EXTLOOP (L3115-3133): the position loop closed on an encoder on the motor read through the external
// input: PE = PCMD - PEXT, ZPE zeroes PCMD - PEXT, NORM sets PFB and PEXT, EXTLOOP only when disabled.
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
} // namespace

TEST(Bds5Extloop, ClosesThePositionLoopOnTheExternalEncoder) {
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    EXPECT_NE(t.type("EXTLOOP ON\r").find("\aERR 51"), std::string::npos) << "only when disabled";
    t.type("DIS\r");
    t.type("EXTLOOP ON\r");
    t.type("EN\r");
    t.type("NORM 0\r");
    EXPECT_EQ(value(t, "PEXT"), "0") << "NORM sets PFB and PEXT together";
    t.type("MI 4096 500\r", 1500ms);
    EXPECT_EQ(value(t, "PCMD"), "4096");
    EXPECT_NEAR(number(t, "PEXT"), 4096, 2) << "the encoder on the motor counts the move";
    EXPECT_NEAR(number(t, "PFB"), 4096, 2);
    // Shift the encoder's count (PEXT is writable): the loop drives PEXT back to PCMD, moving the motor.
    t.type("PEXT=1000\r", 1500ms);
    EXPECT_NEAR(number(t, "PEXT"), 4096, 2) << "PE = PCMD - PEXT is what the loop closes";
    EXPECT_NEAR(number(t, "PFB"), 4096 + 3096, 3) << "the motor moved by the shift";
    EXPECT_LT(std::abs(number(t, "PE")), 3);
    t.type("DIS\r");
    t.type("PEXT=5000\r");
    t.type("EN\r");
    t.type("ZPE\r", 300ms);
    EXPECT_EQ(value(t, "PCMD"), value(t, "PEXT")) << "ZPE: PCMD := PEXT";
}
