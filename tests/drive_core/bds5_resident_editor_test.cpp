// The BDS5 resident editor through the serial line: ED, the e-> i-> f-> c-> prompts and every editor
// command, byte for byte as the manual's §4.3.2 examples show them (L3466-3720, L6656-6673).
#include "bds5_test_drive.h"

#include <gtest/gtest.h>

#include <vector>

using drive_core::bds5::Bds5Drive;
using drive_core::bds5::Bds5DriveMode;
using namespace std::chrono_literals;

namespace {

const std::string kTestLine = ";TEST LINE FOR LEARNING ABOUT THE EDITOR"; // L3545-3562

// An error line as the drive prints it after a command: CR LF LF, BEL, message at column 40.
std::string errorLine(const std::string& head, const std::string& message) {
    return "\r\n\n\a" + head + std::string(40 - head.size(), ' ') + message + "\r\n";
}

class Bds5Editor : public ::testing::Test, public bds5_test::TestDrive {
protected:
    // A line typed at any prompt: the drive echoes it and CR LF, then the editor answers.
    std::string enter(const std::string& line) { return type(line + "\r"); }
    void edit() { ASSERT_EQ(enter("ED"), "ED\r\ne->"); }
};

} // namespace

TEST_F(Bds5Editor, EdShowsTheEditorPromptAndEscReturnsToInteractive) {
    EXPECT_EQ(enter("ED"), "ED\r\ne->"); // L3470-3480
    EXPECT_EQ(drive.mode(), Bds5DriveMode::Editor);
    EXPECT_EQ(type("\x1b"), "\r\n-->"); // L3482
    EXPECT_EQ(drive.mode(), Bds5DriveMode::Interactive);
}

TEST_F(Bds5Editor, ManualInsertExampleThenPrintLineOne) { // L3530-3562
    download({"10$", "B"});
    edit();
    EXPECT_EQ(enter("P BEG      ;GO TO THE BEGINNING OF THE PROGRAM"),
              "P BEG      ;GO TO THE BEGINNING OF THE PROGRAM\r\n1 10$\r\ne->");
    EXPECT_EQ(enter("I          ;ENTER THE INSERT MODE"), "I          ;ENTER THE INSERT MODE\r\ni->");
    EXPECT_EQ(enter(kTestLine), kTestLine + "\r\ni->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("P 1"), "P 1\r\n1 " + kTestLine + "\r\ne->");
    EXPECT_EQ(enter("P BEG END"), "P BEG END\r\n1 " + kTestLine + "\r\n2 10$\r\n3 B\r\ne->");
}

TEST_F(Bds5Editor, InsertAtLineNumberAndFollowingLinesFollowIt) { // L3564-3570
    download({"1", "2", "3", "4", "5", "6"});
    edit();
    EXPECT_EQ(enter("I 5"), "I 5\r\ni->");
    EXPECT_EQ(enter("NEW5"), "NEW5\r\ni->");
    EXPECT_EQ(enter("NEW6"), "NEW6\r\ni->");
    EXPECT_EQ(enter(""), "\r\ne->"); // an empty line leaves insert mode (L3530)
    EXPECT_EQ(enter("P 4 7"), "P 4 7\r\n4 4\r\n5 NEW5\r\n6 NEW6\r\n7 5\r\ne->");
    EXPECT_EQ(enter("I 9"), "I 9\r\ni->"); // one past the last line appends
    EXPECT_EQ(enter("LAST"), "LAST\r\ni->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("P END"), "P END\r\n9 LAST\r\ne->");
    EXPECT_EQ(enter("I 11"), "I 11\r\nBAD ENTRY\r\ne->");
}

TEST_F(Bds5Editor, InsertIntoAnEmptyProgramAndKeepTheCaseTyped) {
    edit();
    EXPECT_EQ(enter("i"), "i\r\ni->");
    EXPECT_EQ(enter("p \"lower\" ;note"), "p \"lower\" ;note\r\ni->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("P 1"), "P 1\r\n1 p \"lower\" ;note\r\ne->");
}

TEST_F(Bds5Editor, PrintCurrentRangesAndBadEntries) { // L3484-3510
    download({"A", "B", "C"});
    edit();
    EXPECT_EQ(enter("P"), "P\r\n1 A\r\ne->"); // ED starts on line 1
    EXPECT_EQ(enter("P 2 3"), "P 2 3\r\n2 B\r\n3 C\r\ne->");
    EXPECT_EQ(enter("P"), "P\r\n3 C\r\ne->"); // the last line printed is current
    EXPECT_EQ(enter("P 100"), "P 100\r\nBAD ENTRY\r\ne->");
    EXPECT_EQ(enter("P 3 1"), "P 3 1\r\nBAD ENTRY\r\ne->");
    EXPECT_EQ(enter("P X"), "P X\r\nBAD ENTRY\r\ne->");
    EXPECT_EQ(enter("p 2"), "p 2\r\n2 B\r\ne->"); // editor commands in either case
    EXPECT_EQ(enter("FOO"), "FOO\r\nBAD ENTRY\r\ne->");
}

TEST_F(Bds5Editor, EmptyLineGoesDownOneLineAndPrintsIt) { // L3512-3514
    download({"A", "B"});
    edit();
    EXPECT_EQ(enter(""), "\r\n2 B\r\ne->");
    EXPECT_EQ(enter(""), "\r\ne->");   // past the last line: nothing to print
    EXPECT_EQ(enter("I"), "I\r\ni->"); // ... and I appends there
    EXPECT_EQ(enter("C"), "C\r\ni->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("P BEG END"), "P BEG END\r\n1 A\r\n2 B\r\n3 C\r\ne->");
}

TEST_F(Bds5Editor, ManualFindExample) { // L3572-3614
    download({kTestLine, "10$", "P \"EDITOR\"", "B"});
    edit();
    EXPECT_EQ(enter("P BEG      ;USE P TO GO TO"), "P BEG      ;USE P TO GO TO\r\n1 " + kTestLine + "\r\ne->");
    EXPECT_EQ(enter("F          ;TOP AND SEARCH"), "F          ;TOP AND SEARCH\r\nFIND WHAT?\r\nf->");
    EXPECT_EQ(enter("EDITOR"), "EDITOR\r\n1 " + kTestLine + "\r\ne->"); // finds line 1
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT? EDITOR?\r\nf->");
    EXPECT_EQ(enter(""), "\r\n3 P \"EDITOR\"\r\ne->"); // the default finds the next line
    EXPECT_EQ(enter("P"), "P\r\n3 P \"EDITOR\"\r\ne->");
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT? EDITOR?\r\nf->");
    EXPECT_EQ(enter(""), "\r\nNOT FOUND\r\ne->");
    EXPECT_EQ(enter("P"), "P\r\n3 P \"EDITOR\"\r\ne->"); // not found: the current line stays
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT? EDITOR?\r\nf->");
    EXPECT_EQ(enter("b"), "b\r\n4 B\r\ne->"); // a new string; found without regard to case
}

TEST_F(Bds5Editor, ManualChangeExample) { // L3616-3662
    download({kTestLine});
    edit();
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT?\r\nf->");
    EXPECT_EQ(enter("EDITOR"), "EDITOR\r\n1 " + kTestLine + "\r\ne->");
    EXPECT_EQ(enter("P 1"), "P 1\r\n1 " + kTestLine + "\r\ne->");
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT? \"EDITOR\"?\r\nc->");
    EXPECT_EQ(enter(""), "\r\nCHANGE TO WHAT?\r\nc->");
    EXPECT_EQ(enter("BDS5 EDITOR"), "BDS5 EDITOR\r\n1 ;TEST LINE FOR LEARNING ABOUT THE BDS5 EDITOR\r\ne->");
    EXPECT_EQ(drive.state().program.line(1), ";TEST LINE FOR LEARNING ABOUT THE BDS5 EDITOR");
}

TEST_F(Bds5Editor, FindAndChangeStepThroughMemoryWithTheirDefaults) { // L3664
    download({"X1=1", "P X1", "X1=2", "B"});
    edit();
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT?\r\nc->");
    EXPECT_EQ(enter("X1"), "X1\r\nCHANGE TO WHAT?\r\nc->");
    EXPECT_EQ(enter("X7"), "X7\r\n1 X7=1\r\ne->");
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT? X1?\r\nf->");
    EXPECT_EQ(enter(""), "\r\n2 P X1\r\ne->");
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT? \"X1\"?\r\nc->");
    EXPECT_EQ(enter(""), "\r\nCHANGE TO WHAT? \"X7\"?\r\nc->");
    EXPECT_EQ(enter(""), "\r\n2 P X7\r\ne->");
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT? X1?\r\nf->");
    EXPECT_EQ(enter(""), "\r\n3 X1=2\r\ne->");
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT? \"X1\"?\r\nc->");
    EXPECT_EQ(enter("=2"), "=2\r\nCHANGE TO WHAT? \"X7\"?\r\nc->"); // a new string becomes F's default too
    EXPECT_EQ(enter("=3"), "=3\r\n3 X1=3\r\ne->");
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT? =2?\r\nf->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
}

TEST_F(Bds5Editor, ChangeSearchesOnlyTheCurrentLine) {
    download({"A", "B"});
    edit();
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT?\r\nc->");
    EXPECT_EQ(enter("B"), "B\r\nNOT FOUND\r\ne->");
    EXPECT_EQ(drive.state().program.line(2), "B");
}

TEST_F(Bds5Editor, DeleteCurrentLineOneLineAndARange) { // L3673-3692
    download({"1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13"});
    edit();
    EXPECT_EQ(enter("DEL 5 10 ;DELETE LINES"), "DEL 5 10 ;DELETE LINES\r\ne->");
    EXPECT_EQ(enter("P"), "P\r\n5 11\r\ne->"); // the line after the deleted ones is current
    EXPECT_EQ(enter("DEL 6 ;DELETE LINE 6"), "DEL 6 ;DELETE LINE 6\r\ne->");
    EXPECT_EQ(enter("P 1 ;POINT AT THE FIRST LINE"), "P 1 ;POINT AT THE FIRST LINE\r\n1 1\r\ne->");
    EXPECT_EQ(enter("DEL ;DELETE CURRENT"), "DEL ;DELETE CURRENT\r\ne->");
    EXPECT_EQ(enter("P BEG END"), "P BEG END\r\n1 2\r\n2 3\r\n3 4\r\n4 11\r\n5 13\r\ne->");
    EXPECT_EQ(enter("DEL 9"), "DEL 9\r\nBAD ENTRY\r\ne->");
    EXPECT_EQ(enter("del beg end"), "del beg end\r\ne->");
    EXPECT_EQ(drive.state().program.lineCount(), 0);
    EXPECT_EQ(enter("DEL"), "DEL\r\nBAD ENTRY\r\ne->");
}

TEST_F(Bds5Editor, SizeShowsPerCentOfProgramMemoryLeft) { // L3694-3706
    edit();
    EXPECT_EQ(enter("SIZE"), "SIZE\r\n100 % LEFT\r\ne->");
    EXPECT_EQ(type("\x1b"), "\r\n-->");
    // 5,600 of 16,000 characters used (70 lines of 79 characters plus their CR): the manual's 65 %.
    download(std::vector<std::string>(70, std::string(79, 'X')));
    edit();
    EXPECT_EQ(enter("SIZE"), "SIZE\r\n65 % LEFT\r\ne->");
}

TEST_F(Bds5Editor, FullProgramMemoryRefusesTheInsertedLineWithErr86) {
    download(std::vector<std::string>(200, std::string(79, 'X'))); // exactly 16,000 characters
    edit();
    EXPECT_EQ(enter("SIZE"), "SIZE\r\n0 % LEFT\r\ne->");
    EXPECT_EQ(enter("I"), "I\r\ni->");
    EXPECT_EQ(enter("B"), "B\r\n" + errorLine("ERR 86 'I'", "USER PROGRAM FULL") + "e->");
    EXPECT_EQ(drive.state().program.lineCount(), 200);
}

TEST_F(Bds5Editor, NewClearsTheProgramAndThePassword) { // L3708-3720
    download({"A", "B"});
    edit();
    EXPECT_EQ(enter("PASS"), "PASS\r\nNEW PASSWORD?\r\ne->");
    EXPECT_EQ(enter("KEY"), "KEY\r\ne->");
    EXPECT_EQ(enter("NEW"), "NEW\r\ne->");
    EXPECT_EQ(drive.state().program.lineCount(), 0);
    EXPECT_EQ(drive.state().program.password(), "");
    EXPECT_EQ(enter("P"), "P\r\nBAD ENTRY\r\ne->");
}

TEST_F(Bds5Editor, PasswordBlocksChangesAndLoadButNotListing) { // L3516-3526, ERR 110 (L10621)
    download({"10$", "P \"EDITOR\"", "B"});
    edit();
    EXPECT_EQ(enter("PASS"), "PASS\r\nNEW PASSWORD?\r\ne->");
    EXPECT_EQ(enter("secret"), "secret\r\ne->");
    EXPECT_EQ(drive.state().program.password(), "SECRET");
    EXPECT_EQ(enter("P 2"), "P 2\r\n2 P \"EDITOR\"\r\ne->");
    EXPECT_EQ(enter("I"), "I\r\n" + errorLine("ERR 110 'I'", "EDIT PASSWORD") + "e->");
    EXPECT_EQ(enter("DEL"), "DEL\r\n" + errorLine("ERR 110 'DEL'", "EDIT PASSWORD") + "e->");
    EXPECT_EQ(enter("C"), "C\r\n" + errorLine("ERR 110 'C'", "EDIT PASSWORD") + "e->");
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT?\r\nf->"); // finding changes nothing
    EXPECT_EQ(enter("B"), "B\r\n3 B\r\ne->");
    EXPECT_EQ(type("\x1b"), "\r\n-->");
    EXPECT_EQ(enter("<BDS"), "<BDS\r\n10$\r\nP \"EDITOR\"\r\nB\r\n-->");
    EXPECT_EQ(enter(">BDS"), ">BDS\r\n" + errorLine("ERR 110 '>BDS'", "EDIT PASSWORD") + "-->");
    EXPECT_EQ(enter(">BDS secret"), ">BDS secret\r\nl->");
    EXPECT_EQ(type("\x1b"), "\r\n-->");
    EXPECT_EQ(drive.state().program.lineCount(), 3);
}

TEST_F(Bds5Editor, PassAsksForTheOldPasswordBeforeChangingIt) {
    edit();
    EXPECT_EQ(enter("PASS"), "PASS\r\nNEW PASSWORD?\r\ne->");
    EXPECT_EQ(enter("TOOLONG"), "TOOLONG\r\nBAD ENTRY\r\ne->"); // six characters at most
    EXPECT_EQ(drive.state().program.password(), "");
    EXPECT_EQ(enter("PASS"), "PASS\r\nNEW PASSWORD?\r\ne->");
    EXPECT_EQ(enter("ABC123"), "ABC123\r\ne->");
    EXPECT_EQ(enter("PASS"), "PASS\r\nOLD PASSWORD?\r\ne->");
    EXPECT_EQ(enter("WRONG"), "WRONG\r\n" + errorLine("ERR 110 'PASS'", "EDIT PASSWORD") + "e->");
    EXPECT_EQ(enter("PASS"), "PASS\r\nOLD PASSWORD?\r\ne->");
    EXPECT_EQ(enter("abc123"), "abc123\r\nNEW PASSWORD?\r\ne->");
    EXPECT_EQ(enter(""), "\r\ne->"); // an empty line: no password protection (L3526)
    EXPECT_EQ(drive.state().program.password(), "");
    EXPECT_EQ(enter("I"), "I\r\ni->");
}

TEST_F(Bds5Editor, EscapeAbortsEverySubModeWithoutChangingAnything) {
    download({"EDITOR"});
    edit();
    EXPECT_EQ(enter("I"), "I\r\ni->");
    EXPECT_EQ(type("HALF"), "HALF");
    EXPECT_EQ(type("\x1b"), "\r\ne->"); // a half-typed line is dropped
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT?\r\nf->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("F"), "F\r\nFIND WHAT?\r\nf->"); // no default: the aborted F set none
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT?\r\nc->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT?\r\nc->");
    EXPECT_EQ(enter("EDIT"), "EDIT\r\nCHANGE TO WHAT?\r\nc->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("PASS"), "PASS\r\nNEW PASSWORD?\r\ne->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(type("\x1b"), "\r\n-->");
    EXPECT_EQ(drive.state().program.lines(), std::vector<std::string>{"EDITOR"});
    EXPECT_EQ(drive.state().program.password(), "");
}

TEST_F(Bds5Editor, RoundTripEditListAndRun) {
    edit();
    EXPECT_EQ(enter("I"), "I\r\ni->");
    for (const std::string l : {"10$ ;GREETING", "P \"HELLO\"", "B"}) EXPECT_EQ(enter(l), l + "\r\ni->");
    EXPECT_EQ(type("\x1b"), "\r\ne->");
    EXPECT_EQ(enter("P 2"), "P 2\r\n2 P \"HELLO\"\r\ne->");
    EXPECT_EQ(enter("C"), "C\r\nCHANGE WHAT?\r\nc->");
    EXPECT_EQ(enter("HELLO"), "HELLO\r\nCHANGE TO WHAT?\r\nc->");
    EXPECT_EQ(enter("HELLO WORLD"), "HELLO WORLD\r\n2 P \"HELLO WORLD\"\r\ne->");
    EXPECT_EQ(type("\x1b"), "\r\n-->");
    EXPECT_EQ(enter("<BDS"), "<BDS\r\n10$ ;GREETING\r\nP \"HELLO WORLD\"\r\nB\r\n-->");
    EXPECT_EQ(type("RUN 10\r", 20ms), "RUN 10\r\nHELLO WORLD\r\n-->");
}

TEST_F(Bds5Editor, RefusedChangeReportsItsErrorCodeForTheHistoryOnce) {
    drive_core::bds5::Bds5Program program;
    program.setPassword("KEY");
    drive_core::bds5::Bds5ResidentEditor editor(program);
    EXPECT_EQ(editor.enter().output, "e->");
    EXPECT_EQ(editor.line("P").output, "BAD ENTRY\r\ne->");
    EXPECT_EQ(editor.takeError(), std::nullopt);
    EXPECT_FALSE(editor.line("I").exited);
    EXPECT_EQ(editor.takeError(), 110);
    EXPECT_EQ(editor.takeError(), std::nullopt);
    EXPECT_EQ(editor.prompt(), "e->");
    EXPECT_TRUE(editor.escape().exited);
}
