// Recognising BDS5 prompts and error lines in the byte stream.
#include "serialport/bds5_protocol.h"

#include <gtest/gtest.h>

using namespace serialport;

TEST(Bds5Protocol, PromptsOnlyCountAfterCrLf) {
    EXPECT_EQ(trailingPrompt("X1=5\r\n-->"), QStringLiteral("-->"));
    EXPECT_FALSE(trailingPrompt("P \"A-->\"")); // a PRINT may contain '>' (§2.10 rule 6)
    EXPECT_FALSE(trailingPrompt("\r\n--> "));
    EXPECT_EQ(trailingPrompt("\r\n==>"), QStringLiteral("==>"));
    EXPECT_EQ(trailingPrompt("\r\nA->"), QStringLiteral("A->"));
    EXPECT_EQ(trailingPrompt("\r\ns-*>"), QStringLiteral("s-*>"));
}

TEST(Bds5Protocol, ModesOfPrompts) {
    EXPECT_EQ(modeOfPrompt("-->"), Bds5Mode::Interactive);
    EXPECT_EQ(modeOfPrompt("==>"), Bds5Mode::Monitor);
    EXPECT_EQ(modeOfPrompt("e->"), Bds5Mode::Editor);
    EXPECT_EQ(modeOfPrompt("l->"), Bds5Mode::ProgramLoad);
    EXPECT_EQ(modeOfPrompt("A->"), Bds5Mode::Interactive);
    EXPECT_EQ(modeOfPrompt("A=>"), Bds5Mode::Monitor);
    EXPECT_EQ(modeOfPrompt("Al>"), Bds5Mode::ProgramLoad);
    EXPECT_EQ(modeOfPrompt("s-->"), Bds5Mode::SingleStep);
}

TEST(Bds5Protocol, ErrorLineFromProgram) {
    const auto e = parseErrorLine("\aERR 83 LINE 2 '2'                      BAD OR OUT OF RANGE");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, 83);
    EXPECT_EQ(e->programLine, 2);
    EXPECT_EQ(e->entry, QStringLiteral("2"));
    EXPECT_EQ(e->message, QStringLiteral("BAD OR OUT OF RANGE"));
}

TEST(Bds5Protocol, AsynchronousErrorLine) {
    const auto e = parseErrorLine("\aERR 17 FEEDBACK LOSS");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, 17);
    EXPECT_EQ(e->entry, QString());
    EXPECT_EQ(e->message, QStringLiteral("FEEDBACK LOSS"));
    EXPECT_FALSE(parseErrorLine("ERROR MSG WAITING--COMMAND IGNORED"));
}

// With DEP on, the drive cuts an error line to 40 characters (L6104), which can leave no message at all
// ("ERR 83 '9001'" and padding): the entry stays the entry, and the message is the manual's (L7380).
TEST(Bds5Protocol, ErrorLineCutByDepKeepsItsEntry) {
    const auto e = parseErrorLine("\aERR 83 '9001'                           ");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, 83);
    EXPECT_EQ(e->entry, QStringLiteral("9001"));
    EXPECT_EQ(e->message, QStringLiteral("BAD OR OUT OF RANGE"));
}

// A lost prompt is noticed as soon as the drive's own command time allows, not after seconds.
TEST(Bds5Protocol, SilenceBudgetFollowsTheCommandsTime) {
    EXPECT_LE(bds5CommandSilenceMs("X1=5", Bds5Mode::ProgramLoad), 200);
    EXPECT_LE(bds5CommandSilenceMs("P X1", Bds5Mode::Interactive), 500);
    EXPECT_GE(bds5CommandSilenceMs("EN", Bds5Mode::Interactive), 3000);
    EXPECT_GE(bds5CommandSilenceMs("tune 30 2", Bds5Mode::Interactive), 20000);
    EXPECT_GE(bds5CommandSilenceMs("10$", Bds5Mode::Interactive), 3000);
    EXPECT_GE(bds5CommandSilenceMs("W 200", Bds5Mode::Interactive), 3000);
}
