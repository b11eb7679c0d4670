// The BDS5 expression rules of Table 3.3 and the manual's worked examples (L1707-1780).
#include "drive_core/bds5/bds5_expression.h"
#include "drive_core/bds5/bds5_printer.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace drive_core::bds5;

namespace {
std::map<std::string, std::int32_t> vars{{"X1", 20}, {"X2", 30}, {"X10", 2}};
VariableReader reader = [](std::string_view name) -> std::optional<std::int32_t> {
    const auto it = vars.find(std::string(name));
    if (it == vars.end()) return std::nullopt;
    return it->second;
};
std::int32_t value(std::string_view e) {
    const auto r = evaluate(e, reader);
    EXPECT_EQ(r.error, 0) << e;
    return r.value;
}
int error(std::string_view e) {
    return evaluate(e, reader).error;
}
} // namespace

TEST(Bds5Expression, ManualExamples) {
    EXPECT_EQ(value("1+2*3"), 7);
    EXPECT_EQ(value("(1+2)*3"), 9);
    EXPECT_EQ(value("(7+3)*(28+22)"), 500);
    EXPECT_EQ(value("X1*X2"), 600);
    EXPECT_EQ(value("53/100*280"), 280);
    EXPECT_EQ(value("280/100*53"), 159);
    EXPECT_EQ(value("280*53/100"), 148);
    EXPECT_EQ(value("1!2"), 3);
    EXPECT_EQ(value("1&2"), 0);
    EXPECT_EQ(value("25H"), 37);
}

TEST(Bds5Expression, HexMustStartWithADigit) {
    EXPECT_EQ(value("0FFH"), 255);
    EXPECT_EQ(error("FFH"), 80);
}

TEST(Bds5Expression, SwitchConstants) {
    EXPECT_EQ(value("ON"), 1);
    EXPECT_EQ(value("Y+N"), 1);
    EXPECT_EQ(value("OFF"), 0);
}

TEST(Bds5Expression, DivisionRoundsToNearestAwayFromZeroOnHalves) {
    EXPECT_EQ(value("5/2"), 3);
    EXPECT_EQ(value("-5/2"), -3);
    EXPECT_EQ(value("7/3"), 2);
    EXPECT_EQ(value("-7/3"), -2);
}

TEST(Bds5Expression, ErrorsAsTheDriveReportsThem) {
    EXPECT_EQ(error("1/0"), 92);
    EXPECT_EQ(error("2147483647+1"), 93);
    EXPECT_EQ(error("100000*100000/100000"), 93) << "intermediate overflow";
    EXPECT_EQ(error("((((1))))"), 94);
    EXPECT_EQ(error("(1+2"), 95);
    EXPECT_EQ(error("1+2)"), 95);
    EXPECT_EQ(error("X(X1+300)"), 85);
}

TEST(Bds5Expression, IndirectUserVariable) {
    EXPECT_EQ(value("X(X10)"), 30);
}

TEST(Bds5Printer, FormatsOfTheManual) {
    EXPECT_EQ(formatValue(1962, "5"), " 1962");
    EXPECT_EQ(formatValue(1962, "3"), "XXX");
    EXPECT_EQ(formatValue(1962, "5.3"), "1.962");
    EXPECT_EQ(formatValue(1962, "5.3.1"), "  1.9");
    EXPECT_EQ(formatValue(123456, ".4"), "     12.3456");
    EXPECT_EQ(formatValue(123456, ".4.2"), "       12.34");
    EXPECT_EQ(formatValue(65280, "H"), "    FF00H");
    EXPECT_EQ(formatValue(256 * 256 * 256 * 65 + 256 * 256 * 65 + 256 * 65 + 65, "C"), "AAAA");
    EXPECT_EQ(formatValue(65, "C"), "A");
    EXPECT_EQ(formatValue(1, "S"), " ON");
    EXPECT_FALSE(formatValue(1, "Q"));
}

TEST(Bds5Printer, ControlCharactersInText) {
    EXPECT_EQ(expandControlCharacters("^G"), "\a");
    EXPECT_EQ(expandControlCharacters("^1"), "^1");
}
