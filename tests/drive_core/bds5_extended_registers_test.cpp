// The v3.0.0 extended user registers (BDS5 UPGRADE NOTICE, L9276, L9295-9297, L9308-9309, L9321): EXTDX on gives
// X251-X750, readable, writable and usable in programs, and makes PC-SCOPE (RECORD/PLAY) and the real time
// trace (TRECORD/TPLAY) unavailable; EXTDX off leaves X1-X250 only. Driven through the drive's serial port
// as a terminal would; the choices the notice leaves open are DECISIONS.md 10-16.
#include "bds5_test_drive.h"

#include "drive_core/bds5/bds5_checker.h"

using namespace bds5_test;

namespace {

// What the terminal shows for an error of a typed (or RUN) line: the echo, CR LF LF BEL, the entry the
// drive quotes, the message from column 40 (L6036-6060), the prompt. Messages are App. D's.
std::string refused(const std::string& echo, const std::string& entry, const std::string& message) {
    return echo + "\r\n\r\n\n\a" + entry + std::string(40 - entry.size(), ' ') + message + "\r\n-->";
}

// P of one value: right-justified in 12 columns (L4191-4358).
std::string printed(const std::string& line, const std::string& value) {
    return line + "\r\n" + std::string(12 - value.size(), ' ') + value + "\r\n-->";
}

const std::string kInvalid = "INVALID INSTRUCTION";      // ERR 80 (L7368-7370)
const std::string kBadIndirection = "BAD INDIRECTION";   // ERR 85 (L7388-7394)
const std::string kNotAtThisLevel = "NOT AT THIS LEVEL"; // ERR 63 (L7330-7332)

} // namespace

TEST(Bds5ExtendedRegisters, WithExtdxOffOnlyX1ToX250Exist) { // EXTDX=0 by default (L9289-9293)
    TestDrive t;
    EXPECT_EQ(t.type("P EXTDX\r"), printed("P EXTDX", "0"));
    EXPECT_EQ(t.type("X250=5\r"), "X250=5\r\n-->");
    EXPECT_EQ(t.type("X251=5\r"), refused("X251=5", "ERR 80 'X251'", kInvalid));
    EXPECT_EQ(t.type("P X251\r"), refused("P X251", "ERR 80 'X251'", kInvalid));
    EXPECT_EQ(t.type("X750 1\r"), refused("X750 1", "ERR 80 'X750'", kInvalid));
    EXPECT_EQ(t.type("P X1+X300\r"), refused("P X1+X300", "ERR 80 'X1+X300'", kInvalid));
    // X(Xn) pointing past the registers that exist is the manual's own ERR 85 example (L7390-7394).
    t.type("X1=251\r");
    EXPECT_EQ(t.type("P X(X1)\r"), refused("P X(X1)", "ERR 85 'X(X1)'", kBadIndirection));
    EXPECT_EQ(t.type("X(X1)=3\r"), refused("X(X1)=3", "ERR 85 'X(X1)'", kBadIndirection));
    t.type("X1=250\r");
    EXPECT_EQ(t.type("X(X1)=3\r"), "X(X1)=3\r\n-->");
    EXPECT_EQ(t.type("P X250\r"), printed("P X250", "3"));
}

TEST(Bds5ExtendedRegisters, WithExtdxOnX251ToX750AreUserRegisters) {
    TestDrive t;
    EXPECT_EQ(t.type("EXTDX=1\r"), "EXTDX=1\r\n-->");
    EXPECT_EQ(t.type("P X251\r"), printed("P X251", "0"));
    EXPECT_EQ(t.type("X251=-123456789\r"), "X251=-123456789\r\n-->"); // Long, as X1-X250 (L7680)
    EXPECT_EQ(t.type("P X251\r"), printed("P X251", "-123456789"));
    EXPECT_EQ(t.type("X750 2147483647\r"), "X750 2147483647\r\n-->");
    EXPECT_EQ(t.type("P X750\r"), printed("P X750", "2147483647"));
    EXPECT_EQ(t.type("X500=X250+7\r"), "X500=X250+7\r\n-->");
    EXPECT_EQ(t.type("P X500\r"), printed("P X500", "7"));
    // Nothing past X750: "up to 750 user registers" (L9276, L9321).
    EXPECT_EQ(t.type("X751=1\r"), refused("X751=1", "ERR 80 'X751'", kInvalid));
    // Indirection reaches the extended registers, and stops after X750.
    t.type("X1=600\r");
    EXPECT_EQ(t.type("X(X1)=42\r"), "X(X1)=42\r\n-->");
    EXPECT_EQ(t.type("P X600\r"), printed("P X600", "42"));
    EXPECT_EQ(t.type("P X(X1)\r"), printed("P X(X1)", "42"));
    t.type("X1=751\r");
    EXPECT_EQ(t.type("P X(X1)\r"), refused("P X(X1)", "ERR 85 'X(X1)'", kBadIndirection));
}

TEST(Bds5ExtendedRegisters, ProgramsUseThemOnlyWhileExtdxIsOn) {
    TestDrive t;
    t.download({"1$", "X300=X1+5", "X(X2)=X300*2", "P X300 X750", "B"});
    t.type("X1=10\r");
    t.type("X2=750\r");
    EXPECT_EQ(t.type("RUN 1\r", 50ms), refused("RUN 1", "ERR 80 LINE 2 'X300'", kInvalid));
    t.type("EXTDX=1\r");
    // X300 = 10 + 5 = 15; X750 = 2 x 15 = 30; P prints each in 12 columns.
    EXPECT_EQ(t.type("RUN 1\r", 50ms), "RUN 1\r\n          15          30\r\n-->");
}

TEST(Bds5ExtendedRegisters, InputCanFillAnExtendedRegister) { // INPUT (L4380-4436)
    TestDrive t;
    t.download({"1$", "INPUT \"N \" X300", "B"});
    EXPECT_EQ(t.type("RUN 1\r", 50ms), refused("RUN 1", "ERR 80 LINE 2 'X300'", kInvalid));
    t.type("EXTDX ON\r");
    EXPECT_EQ(t.type("RUN 1\r", 50ms), "RUN 1\r\nN ");
    EXPECT_TRUE(t.type("42\r", 50ms).ends_with("-->"));
    EXPECT_EQ(t.type("P X300\r"), printed("P X300", "42"));
}

// "While the extra 500 user registers are enabled, the PC-SCOPE and PC-TRACE commands will be unavailable"
// (L9295-9297, L9309): RECORD, PLAY, TRECORD and TPLAY answer ERR 63 (DECISIONS.md 11).
TEST(Bds5ExtendedRegisters, RecordPlayAndTraceAreUnavailableWhileExtdxIsOn) {
    TestDrive t;
    t.type("EXTDX=1\r");
    EXPECT_EQ(t.type("RECORD 10 1 X1\r"), refused("RECORD 10 1 X1", "ERR 63 'RECORD 10 1 X1'", kNotAtThisLevel));
    EXPECT_EQ(t.type("PLAY\r"), refused("PLAY", "ERR 63 'PLAY'", kNotAtThisLevel));
    EXPECT_EQ(t.type("TRECORD START\r"), refused("TRECORD START", "ERR 63 'TRECORD START'", kNotAtThisLevel));
    EXPECT_EQ(t.type("TPLAY\r"), refused("TPLAY", "ERR 63 'TPLAY'", kNotAtThisLevel));
    t.type("EXTDX=0\r");
    EXPECT_EQ(t.type("RECORD 2 1 X1\r"), "RECORD 2 1 X1\r\n-->");
    // With EXTDX off an extended register is no variable: RECORD refuses it by name, as any unknown one.
    EXPECT_EQ(t.type("RECORD 2 1 X251\r"), refused("RECORD 2 1 X251", "ERR 80 'X251'", kInvalid));
}

// The registers take the buffers' memory (DECISIONS.md 12): switching EXTDX discards the recording and the
// trace, and the extended registers start from 0.
TEST(Bds5ExtendedRegisters, SwitchingExtdxDiscardsTheRecordingAndStartsTheRegistersAtZero) {
    TestDrive t;
    t.type("X1=5\r");
    t.type("RECORD 2 1 X1\r");
    t.wait(10ms);
    const std::string row = "           5\r\n";
    ASSERT_EQ(t.type("PLAY\r"), "PLAY\r\nRECORD 2 1 X1\r\n" + row + row + "-->");
    t.type("EXTDX=1\r");
    t.type("X251=9\r");
    t.type("EXTDX=0\r");
    const std::string play = t.type("PLAY\r");
    EXPECT_NE(play.find("\aERR 65 'PLAY'"), std::string::npos) << play; // RECORD NOT READY (L7338-7340)
    EXPECT_NE(play.find("RECORD NOT READY"), std::string::npos) << play;
    t.type("EXTDX=1\r");
    EXPECT_EQ(t.type("P X251\r"), printed("P X251", "0"));
    // Writing the value EXTDX already has changes nothing.
    t.type("X251=9\r");
    t.type("EXTDX=1\r");
    EXPECT_EQ(t.type("P X251\r"), printed("P X251", "9"));
}

TEST(Bds5ExtendedRegisters, SwitchingExtdxDiscardsTheTrace) {
    TestDrive t;
    t.download({"5$", "X1=1", "B"});
    t.type("TRECORD START\r");
    t.type("RUN 5\r", 20ms);
    ASSERT_EQ(t.type("TPLAY 1\r"), "TPLAY 1\r\n#1 LINE 1 t... 5$\r\n-->");
    t.type("EXTDX=1\r");
    t.type("EXTDX=0\r");
    EXPECT_EQ(t.type("TPLAY\r"), "TPLAY\r\n-->") << "the trace buffer was the registers' memory";
    t.type("RUN 5\r", 20ms);
    EXPECT_EQ(t.type("TPLAY\r"), "TPLAY\r\n-->") << "tracing stopped with it";
}

// All user variables live in non-volatile RAM (L1488) and EXTDX "is remembered on Power-up" (L9309).
TEST(Bds5ExtendedRegisters, ExtdxAndTheRegistersSurvivePowerUp) {
    TestDrive t;
    t.type("EXTDX=1\r");
    t.type("X700=42\r");
    t.drive.powerUp();
    t.wait(100ms);
    EXPECT_EQ(t.type("P EXTDX\r"), printed("P EXTDX", "1"));
    EXPECT_EQ(t.type("P X700\r"), printed("P X700", "42"));
}

// CLEARX "will clear all user registers and user flags to zero ... (X1-X750 & XS1-XS50)" (L9308).
TEST(Bds5ExtendedRegisters, ClearxClearsX1ToX750AndXs1ToXs50) {
    TestDrive t;
    t.type("EXTDX=1\r");
    for (const char* line : {"X1=1", "X250=2", "X251=3", "X750=4", "XS1=1", "XS50=1"}) t.type(line + std::string("\r"));
    EXPECT_EQ(t.type("CLEARX\r"), "CLEARX\r\n-->");
    for (const char* name : {"X1", "X250", "X251", "X750", "XS1", "XS50"})
        EXPECT_EQ(t.type("P " + std::string(name) + "\r"), printed("P " + std::string(name), "0")) << name;
}

// RAND's register is "<user reg>=1-250" (L9310), which the notice does not widen (DECISIONS.md 14).
TEST(Bds5ExtendedRegisters, RandStoresOnlyInX1ToX250) {
    TestDrive t;
    t.type("EXTDX=1\r");
    EXPECT_EQ(t.type("RAND X250 1 1\r"), "RAND X250 1 1\r\n-->");
    EXPECT_EQ(t.type("P X250\r"), printed("P X250", "1")); // the only number between 1 and 1
    EXPECT_EQ(t.type("RAND X251 1 1\r"), refused("RAND X251 1 1", "ERR 83 'X251'", "BAD OR OUT OF RANGE"));
}

// A DUMP sent back restores the extended registers: EXTDX is listed before the X lines (DECISIONS.md 15).
TEST(Bds5ExtendedRegisters, DumpListsThemAfterExtdxAndRestoresThem) {
    TestDrive fresh;
    const std::string plain = fresh.type("DUMP\r");
    EXPECT_NE(plain.find("\r\nX250 0\r\n"), std::string::npos);
    EXPECT_EQ(plain.find("\r\nX251 "), std::string::npos) << "no extended registers while EXTDX is off";

    TestDrive from;
    for (const char* line : {"EXTDX=1", "X251=7", "X750=-3"}) from.type(line + std::string("\r"));
    const std::string dump = from.type("DUMP\r");
    const auto extdx = dump.find("\r\nEXTDX 1\r\n");
    ASSERT_NE(extdx, std::string::npos);
    EXPECT_LT(extdx, dump.find("\r\nX1 0\r\n"));
    EXPECT_LT(dump.find("\r\nX250 0\r\n"), dump.find("\r\nX251 7\r\n"));
    EXPECT_NE(dump.find("\r\nX750 -3\r\n"), std::string::npos);

    TestDrive to;
    std::size_t start = dump.find("\r\n") + 2;
    for (std::size_t end; (end = dump.find("\r\n", start)) != std::string::npos; start = end + 2) {
        const std::string line = dump.substr(start, end - start);
        if (line.empty() || line == "-->") continue;
        const std::string answer = to.type(line + "\r");
        EXPECT_EQ(answer.find("\aERR"), std::string::npos) << line << " -> " << answer;
    }
    EXPECT_EQ(to.type("P X251 X750\r"), "P X251 X750\r\n           7          -3\r\n-->");
}

// The editor cannot know the drive's EXTDX: X251-X750 and RECORD pass, what fails either way does not.
TEST(Bds5ExtendedRegisters, TheEditorFlagsOnlyWhatFailsWithExtdxOnAndOff) {
    using drive_core::bds5::checkProgram;
    EXPECT_TRUE(
        checkProgram({"1$", "X600=X250+1", "P X750", "RECORD 10 1 X1", "EXTDX=1", "RECORD 10 1 X1", "B"}).empty());
    const auto d = checkProgram({"1$", "X751=1", "RAND X300 1 2", "B"});
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].line, 2);
    EXPECT_EQ(d[0].code, 80);
    EXPECT_EQ(d[0].entry, "X751");
    EXPECT_EQ(d[1].line, 3);
    EXPECT_EQ(d[1].code, 83);
}
