// The editor's diagnostics come from the drive's own front end: the same errors at the same lines.
#include "drive_core/bds5/bds5_checker.h"

#include <gtest/gtest.h>

using drive_core::bds5::checkProgram;
using drive_core::bds5::Diagnostic;

namespace {
std::vector<int> codes(const std::vector<Diagnostic>& d) {
    std::vector<int> c;
    for (const Diagnostic& x : d) c.push_back(x.code);
    return c;
}
} // namespace

TEST(Bds5Checker, ACleanProgramHasNoDiagnostics) {
    EXPECT_TRUE(checkProgram({"10$ ;START", "P \"HELLO WORLD\"", "X1=X2*3", "? X1 GT 5 GOTO 10", "MI 4000 100",
                              "IF X1 EQ 0", "  J 0", "ENDIF", "B"})
                    .empty());
}

TEST(Bds5Checker, EachErrorAtItsLineAndEntry) {
    const auto d = checkProgram(
        {"1$", "FOO 3", "PROP 2", "P \"X", "X1 = (((1)))", "J 10;BAD", "GOTO 7", "PCMD=1", "VMAX=1", "P X1[Q]"});
    ASSERT_EQ(codes(d), (std::vector<int>{80, 83, 88, 94, 83, 70, 81, 111, 79}));
    EXPECT_EQ(d[0].line, 2);
    EXPECT_EQ(d[0].message, "INVALID INSTRUCTION");
    EXPECT_EQ(d[1].line, 3);
    EXPECT_EQ(d[1].entry, "2");
    EXPECT_EQ(d[1].column, 5);
    EXPECT_NE(d[4].message.find("space before it"), std::string::npos);
    EXPECT_EQ(d[5].line, 7);
}

TEST(Bds5Checker, ProgramWideLabelChecks) {
    const auto twice = checkProgram({"1$", "B", "1$", "B"});
    ASSERT_EQ(codes(twice), std::vector<int>{71});
    EXPECT_EQ(twice[0].line, 3);
    const auto errorNotLast = checkProgram({"ERROR$", "B", "2$", "B"});
    ASSERT_EQ(codes(errorNotLast), std::vector<int>{74});
    EXPECT_EQ(errorNotLast[0].line, 3);
}

TEST(Bds5Checker, StateDependentErrorsAreNotReported) {
    // Zero divide with X2 = 0, a full motion buffer, a disabled drive: only known when the line runs.
    EXPECT_TRUE(checkProgram({"X1=5/X2", "MI 100", "MI 100", "MI 100", "DIS", "J 10"}).empty());
}

TEST(Bds5Checker, TooLongAndTooManyEntries) {
    const auto d = checkProgram({"P " + std::string(90, '1'), "P 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15"});
    ASSERT_GE(d.size(), 2u);
    EXPECT_EQ(d[0].code, 0);
    EXPECT_EQ(d.back().code, 82);
    EXPECT_EQ(d.back().line, 2);
}

TEST(Bds5Checker, AlarmLabelsNeedASwitch) {
    EXPECT_EQ(codes(checkProgram({"A$ REMOTE ON", "END"})), std::vector<int>{89});
    EXPECT_EQ(codes(checkProgram({"B$ VMAX ON", "END"})), std::vector<int>{83});
    EXPECT_TRUE(checkProgram({"C$ I3 OFF", "END"}).empty());
}

TEST(Bds5Checker, ProgramOnlyRulesApply) {
    EXPECT_EQ(codes(checkProgram({"1$", "ED"})), std::vector<int>{53});
}

TEST(Bds5Checker, CommentWithoutABlankBeforeItIsNamed) { // L1355-1365: "J 10;BAD COMMENT" is wrong
    const auto d = checkProgram({"J 10;BAD COMMENT"});
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].code, 83);
    EXPECT_EQ(d[0].entry, "10;BAD");
    EXPECT_NE(d[0].message.find("space before it"), std::string::npos);
}
