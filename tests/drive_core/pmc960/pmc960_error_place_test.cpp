// Placing a program error (issue 19): a routine run with B<label> stops on #xx, and the controller tells only
// the code and, in SB&, the last label passed and the commands executed since (L1466-1474). The command that
// failed is found by following the program text from that label: straight on, through a comment line, two
// commands on one line, a return from a called routine — and not where the text does not lead there. The
// controller's own SB& is checked against the text for a routine that calls another.
#include "pmc960_test_drive.h"

#include "drive_core/pmc960/pmc960_error_place.h"

namespace pmc960_test {
namespace {

using drive_core::pmc960::commandsOf;
using drive_core::pmc960::placeProgramError;
using Lines = std::vector<std::string>;

constexpr int kNotEnabled = 0xB6;
constexpr int kLabelUndefined = 0xC2;

TEST(Pmc960ErrorPlace, CommandsAreCountedAsTheControllerCountsThem) {
    EXPECT_EQ(commandsOf("I2048+,"), Lines{"I2048+,"});
    EXPECT_EQ(commandsOf("G!V!"), (Lines{"G!", "V!"})); // a display character ends a command
    EXPECT_EQ(commandsOf("SB&"), Lines{"SB&"});
    EXPECT_TRUE(commandsOf("@H_Hello").empty());
    EXPECT_TRUE(commandsOf("...").empty()); // fillers
}

TEST(Pmc960ErrorPlace, StraightOnFromTheLabel) {
    const Lines program{"@H_Half_a_turn", "A4000", "I2048+,", "G!", "E"};
    const auto place = placeProgramError(program, 'H', 'H', 1, kNotEnabled); // SB& "H 1": A4000 ran
    ASSERT_TRUE(place);
    EXPECT_EQ(place->line, 2u);
    EXPECT_EQ(place->command, "I2048+,");
    EXPECT_EQ(place->routine, 'H');
    EXPECT_FALSE(place->afterReturn);
    EXPECT_FALSE(place->ambiguous);
}

TEST(Pmc960ErrorPlace, ACommentLineIsALabelTooButNotARoutine) {
    // @. sets SB's label to '.' and its count to 0 (L1036): the routine is still H.
    const Lines program{"@A", "A1", "@.x", "I1+", "E", "@H", "A4000", "@.note", "I2048+,", "E"};
    const auto place = placeProgramError(program, 'H', '.', 0, kNotEnabled);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->line, 8u); // the @. after H's line, not A's
    EXPECT_EQ(place->command, "I2048+,");
    EXPECT_EQ(place->routine, 'H');
    EXPECT_TRUE(place->ambiguous);
}

TEST(Pmc960ErrorPlace, TwoCommandsOnALine) {
    const auto place = placeProgramError({"@H", "G!V!", "I5+"}, 'H', 'H', 1, kNotEnabled);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->line, 1u);
    EXPECT_EQ(place->command, "V!");
}

TEST(Pmc960ErrorPlace, AConditionalBranchMayFallThrough) {
    const auto place = placeProgramError({"@H", "BT1", "I1+", "@T", "E"}, 'H', 'H', 1, kNotEnabled);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->command, "I1+");
}

TEST(Pmc960ErrorPlace, AfterAReturnTheCountGoesOnInTheCaller) {
    // FS runs S (SB: S 0), S's E returns without counting, and the count goes on in H after FS.
    const Lines program{"@H", "FS", "I2048+,", "E", "@S_Set_up", "V400", "E"};
    const auto place = placeProgramError(program, 'H', 'S', 1, kNotEnabled);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->line, 2u);
    EXPECT_EQ(place->command, "I2048+,");
    EXPECT_EQ(place->routine, 'H');
    EXPECT_TRUE(place->afterReturn);
}

TEST(Pmc960ErrorPlace, AMissingLabelIsTheJumpThatCountedItself) {
    const auto place = placeProgramError({"@H", "A1", "BZ", "E"}, 'H', 'H', 2, kLabelUndefined);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->command, "BZ");
}

TEST(Pmc960ErrorPlace, NotWhereTheTextDoesNotLead) {
    EXPECT_FALSE(placeProgramError({"@H", "BT", "I1+", "@T", "E"}, 'H', 'H', 1, kNotEnabled)); // B jumped
    EXPECT_FALSE(placeProgramError({"@H", "A1", "@T", "I1+"}, 'H', 'H', 1, kNotEnabled));      // T's label
    EXPECT_FALSE(placeProgramError({"@H", "A1"}, 'H', 'H', 3, kNotEnabled));                   // the end
    EXPECT_FALSE(placeProgramError({"@H", "A1"}, 'H', 'Q', 0, kNotEnabled));                   // no @Q
    EXPECT_FALSE(placeProgramError({"@H", "FS", "FS", "@S", "E"}, 'H', 'S', 0, kNotEnabled));  // two callers
}

TEST(Pmc960ErrorPlace, TheSamplesPositionRoutine) {
    // hello.mpl's P: D250, G!, Q. SB& "P 1" is G!.
    const Lines hello{"@H_Hello", "FS", "@T_Turn", "I+,", "LT2", "@P_Position", "D250", "G!", "Q"};
    const auto place = placeProgramError(hello, 'H', 'P', 1, kNotEnabled);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->line, 7u);
    EXPECT_EQ(place->command, "G!");
}

// The simulated controller runs a routine that calls another and is refused motion (#B6, the servo off):
// its SB& names the called routine's label with a count that the text leads from to the failing command.
TEST(Pmc960ErrorPlace, TheControllersSbLeadsToTheFailingCommand) {
    TestDrive t;
    const Lines program{"@H_Turn", "A4000", "FS", "V400", "I100+", "E", "@S_Set_up", "A3000", "E"};
    std::string text;
    for (const std::string& line : program) text += line + '\r';
    t.load(text);
    EXPECT_EQ(t.type("BH\r", 20ms), prompted("BH#B6"));
    const std::string sb = t.type("SB&");
    ASSERT_EQ(sb, prompted("SB&S 2")); // S passed, A3000 and V400 since
    const auto place = placeProgramError(program, 'H', 'S', 2, kNotEnabled);
    ASSERT_TRUE(place);
    EXPECT_EQ(place->line, 4u);
    EXPECT_EQ(place->command, "I100+");
    EXPECT_EQ(place->routine, 'H');
    EXPECT_EQ(t.type("SE&"), prompted("SE&B6"));
}

} // namespace
} // namespace pmc960_test
