// The manual's example programs (spec §10), repaired as the digest's INDEX says, downloaded with >BDS and
// run: the drive prints what the manual prints. Motion examples run on the simulated motor and loops, so
// PFB trails PCMD by the following error. Where the manual leaves the count of a repeated line open, it is
// held between bounds worked out in the test from the manual's figures (9600 baud, Appendix F's times).
#include "bds5_test_drive.h"

#include <fstream>
#include <regex>
#include <sstream>

using namespace bds5_test;

namespace {

// Reads an example and repairs the OCR damage every example shares.
std::vector<std::string> example(const std::string& file,
                                 const std::vector<std::pair<std::string, std::string>>& fixes = {}) {
    std::ifstream in(std::string(SERVODESK_EXAMPLES_DIR) + "/" + file);
    EXPECT_TRUE(in) << file;
    std::stringstream text;
    text << in.rdbuf();
    std::string all = text.str();
    for (const auto& [from, to] : fixes) { // example-specific repairs first (wrapped strings span lines)
        const auto at = all.find(from);
        EXPECT_NE(at, std::string::npos) << file << ": " << from;
        if (at != std::string::npos) all.replace(at, from.size(), to);
    }
    std::vector<std::string> lines;
    std::stringstream stream(all);
    static const std::regex label(R"(^(\d+|POWER-UP|VARIABLE|BACKGROUND|AUTO|MANUAL|ERROR|A|B|C)S(\s|$))");
    for (std::string line; std::getline(stream, line);) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        for (std::size_t at; (at = line.find("\\$")) != std::string::npos;) line.replace(at, 2, "$");
        for (char& c : line) c = c == '\t' ? ' ' : c;
        line = std::regex_replace(line, label, "$1$$$2"); // "1S" -> "1$", "VARIABLES" -> "VARIABLE$"
        if (line.empty() || line.starts_with(".....")) continue;
        lines.push_back(line);
    }
    return lines;
}

} // namespace

TEST(Bds5Examples, IndirectUserVariables01) { // L1594-1628
    TestDrive t;
    std::string out;
    for (const std::string& line : example("01-indirect-user-vars.bds")) out += t.type(line + "\r");
    EXPECT_NE(out.find("P X(X10)   ;PRINT WHAT X10 POINTS\r\n         100\r\n"), std::string::npos) << out;
    EXPECT_NE(out.find("P X(X10)   ;PRINT WHAT X10 POINTS\r\n        1000\r\n"), std::string::npos) << out;
}

TEST(Bds5Examples, MathPrecedenceAndRounding02) { // L1707-1749
    TestDrive t;
    std::string out;
    for (const std::string& line : example("02-math-precedence-rounding.bds")) out += t.type(line + "\r");
    for (const char* v :
         {"           7\r\n", "           9\r\n", "         280\r\n", "         159\r\n", "         148\r\n"})
        EXPECT_NE(out.find(v), std::string::npos) << v;
    EXPECT_EQ(t.type("P X3\r"), "P X3\r\n         600\r\n-->");
    EXPECT_EQ(out.find("ERR"), std::string::npos) << out;
}

TEST(Bds5Examples, LogicalAndOr03) { // L1763-1780; "112" is OCR for "1!2"
    TestDrive t;
    std::string out;
    for (const std::string& line : example("03-logical-and-or.bds", {{"P 112", "P 1!2"}})) out += t.type(line + "\r");
    EXPECT_EQ(out, "P 1!2 ;THIS IS 3\r\n           3\r\n-->P 1&2 ;THIS IS 0\r\n           0\r\n-->");
}

TEST(Bds5Examples, HelloWorld20) { // L3436-3462: the first Motion Link session
    TestDrive t;
    t.download(example("20-hello-world.bds"));
    EXPECT_EQ(t.type("RUN 10\r", 50ms), "RUN 10\r\nHELLO WORLD\r\n-->");
}

TEST(Bds5Examples, Goto21AndGosub22) { // L3770-3821
    TestDrive t;
    t.download(example("21-goto-demo.bds"));
    EXPECT_EQ(t.type("RUN 2\r", 100ms), "RUN 2\r\nAT LABEL 2\r\nAT LABEL 3\r\n-->");
    t.download(example("22-gosub-demo.bds"));
    EXPECT_EQ(t.type("RUN 4\r", 100ms), "RUN 4\r\nEXECUTING SUBROUTINE 5\r\nRETURNED FROM SUBROUTINE 5\r\n-->");
}

TEST(Bds5Examples, NestedIf29) { // L4074-4088, and the trace of L5688-5699
    TestDrive t;
    t.download(example("29-nested-if-55.bds"));
    t.type("X1=1\r");
    t.type("X2=1\r");
    EXPECT_EQ(t.type("RUN 55\r", 100ms), "RUN 55\r\nBOTH X1 AND X2 > 0\r\n-->");
}

TEST(Bds5Examples, Refresh7) { // L4367-4369: RS overwrites one line with CR only
    TestDrive t;
    t.download(example("33-refresh-7.bds"));
    const std::string out = t.type("RUN 7\r", 300ms);
    // The manual gives no count; the port bounds it. A line is 35 characters ("VELOCITY FEEDBACK=", VFB in 12
    // columns, " OFF", CR): 36.5 ms at 9600 baud, 10 bits a character (8N1). RS waits for the previous line
    // to leave (L4637), then 7$, RS and GOTO take 1.0 + 3.8 + 1.6 ms (Appendix F, L7739-7774; at most 60 %
    // more, L7735): a line starts every 36.5 to 47.7 ms (a millisecond for the port to be seen free) after
    // the 7-character echo of RUN 7 (7.3 ms). Started within the 300 ms, and finished by type(): at most
    // 1 + (300 - 7.3) / 36.5 = 9, at least 1 + (300 - 16) / 47.7 = 6.
    const int lines = count(out, "VELOCITY FEEDBACK=           0 OFF\r");
    EXPECT_GE(lines, 6) << out;
    EXPECT_LE(lines, 9) << out;
    EXPECT_EQ(count(out, "\r\n"), 1) << "only the echo of RUN 7 ends with a line feed";
    t.type("\x18");
}

TEST(Bds5Examples, InputDecimal35) { // L4428-4435
    TestDrive t;
    t.download(example("35-input-decimal-44.bds"));
    EXPECT_EQ(t.type("RUN 44\r", 50ms), "RUN 44\r\nENTER NEW POSITION: ");
    EXPECT_EQ(t.type("1.234\r", 100ms), "1.234\r\nNEW POSITION =        1.234\r\nACTUALLY, X1=         1234\r\n-->");
}

TEST(Bds5Examples, Hold38) { // L4466-4470
    TestDrive t;
    t.download(example("38-hold-29.bds"));
    EXPECT_EQ(t.type("RUN 29\r", 200ms), "RUN 29\r\nTURN I1 ON\r\n");
    t.drive.setInput(1, true);
    EXPECT_EQ(t.wait(50ms), "I1 IS NOW ON\r\n-->");
}

TEST(Bds5Examples, Dwell39) { // L4491-4509; "G$" is OCR for "6$"
    TestDrive t;
    t.download(example("39-dwell-6.bds", {{"G$", "6$"}}));
    EXPECT_EQ(t.type("RUN 6\r", 100ms), "RUN 6\r\nBEGIN 5 SECOND DWELL\r\n");
    EXPECT_EQ(t.wait(4800ms), "");
    EXPECT_EQ(t.wait(200ms), "END 5 SECOND DWELL\r\n-->");
}

TEST(Bds5Examples, PreExecutionIdle41) { // L4645-4687 (timing on the ideal follower)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.download(example("41-pre-execution-idle.bds"));
    // MI 10000 10: 10000 counts at 10 RPM (683 counts/s) take 14.6 s each.
    const std::string out = t.type("RUN 1\r", 31000ms);
    const auto second = out.find("SECOND MOVE PROCESSED");
    const auto third = out.find("THIRD MOVE PROCESSED");
    ASSERT_NE(second, std::string::npos) << out;
    ASSERT_NE(third, std::string::npos) << out;
    EXPECT_EQ(out.find("FIRST MOVE PROCESSED\r\n"), out.find("\r\n") + 2) << out;
    // The manual prints "..." for the count. While the third MI waits for the first move to end, the
    // background prints every 250 ms (D 250) plus its lines' times: BACKGROUND$ 1.0, P 3.5 (Appendix F), D
    // and END untimed there, taken at most its slowest line, 5.8 ms; all up to 60 % more (L7735): 250 to
    // 275.8 ms. The wait lasts the first move, 10000 counts at 10 RPM = 682.7 counts/s (4096 counts a turn,
    // L1386): 14.648 s, less at most 78 ms before it (the main task printing FIRST and SECOND, 22 and 23
    // characters at 9600 baud, and its lines), plus at most 15 ms after it (the third MI and P). Prints: at
    // most 1 + 14663 / 250 = 59, at least 1 + 14570 / 275.8 = 53.
    const int idled = count(out.substr(second, third - second), "UPPER TASK IDLED");
    EXPECT_GE(idled, 53) << out;
    EXPECT_LE(idled, 59) << out;
}

TEST(Bds5Examples, PostExecutionIdle42) { // L4700-4750
    TestDrive t;
    t.type("PLIM OFF\r");
    t.download(example("42-post-execution-idle.bds"));
    const std::string out = t.type("RUN 1\r", 16000ms); // MI 10000 10: 14.6 s
    const auto moved = out.find("MOVE PROCESSED");
    const auto stopped = out.find("ALL MOTION STOPPED");
    ASSERT_NE(stopped, std::string::npos) << out;
    // As in PreExecutionIdle41: W 0 idles the main task for the 14.648 s move, the background prints every
    // 250 to 275.8 ms: at most 1 + 14663 / 250 = 59 prints, at least 1 + 14570 / 275.8 = 53.
    const int idled = count(out.substr(moved, stopped - moved), "UPPER TASK IDLED");
    EXPECT_GE(idled, 53) << out;
    EXPECT_LE(idled, 59) << out;
    EXPECT_TRUE(out.ends_with("ALL MOTION STOPPED\r\n-->")) << out;
}

TEST(Bds5Examples, AlarmA43) { // L4783-4790
    TestDrive t;
    t.download(example("43-alarm-a.bds"));
    t.type("O1 ON\r");
    t.type("EN\r");
    t.type("RUN\r", 20ms);
    t.drive.setInput(1, true);
    EXPECT_EQ(t.wait(30ms), "-->");
    EXPECT_EQ(t.type("PS OUT\r"), "PS OUT\r\n           0 OFF\r\n-->") << "outputs off, drive disabled";
}

TEST(Bds5Examples, AlarmBPrinting44) { // L4802-4811; "O = 0" is OCR for "OUT = 0"
    TestDrive t;
    t.download(example("44-alarm-b-printing.bds", {{"O = 0", "OUT = 0"}}));
    t.type("RUN\r", 20ms);
    t.drive.setDedicatedInput("HOME", true);
    EXPECT_EQ(t.wait(50ms), "MESSAGE\r\n-->");
}

TEST(Bds5Examples, VariableInputTask45) { // L4848-4858: ^V prints X1, asks X2, prints a larger X1
    TestDrive t;
    t.download(example("45-variable-input-task.bds"));
    EXPECT_EQ(t.type("RUN 10\r", 200ms), "RUN 10\r\n");
    const std::string asked = t.type("\x16", 100ms);
    EXPECT_TRUE(asked.starts_with("X1 IS")) << asked;
    EXPECT_TRUE(asked.ends_with("INPUT NEW VALUE OF X2")) << asked;
    const int before = std::stoi(asked.substr(5, 12));
    const std::string after = t.type("7\r", 100ms);
    const auto at = after.find("X1 IS NOW ");
    ASSERT_NE(at, std::string::npos) << after;
    EXPECT_GT(std::stoi(after.substr(at + 10, 12)), before) << "the main loop ran while INPUT waited";
    EXPECT_EQ(t.type("P X2\r"), "P X2\r\n           7\r\n-->");
}

TEST(Bds5Examples, VariableInputProfiles46) { // L4865-4880: moves go on while VARIABLE$ asks
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("X1=100\r");
    t.type("X2=100\r");
    t.download(example("46-variable-input-profiles-v1.bds"));
    t.type("RUN 20\r", 100ms);
    EXPECT_EQ(t.type("\x16", 50ms), "INPUT NEW DISTANCE");
    t.type("-50\r", 50ms);
    t.type("200\r", 200ms);
    t.type("\x18");
    EXPECT_EQ(t.type("P X1 X2\r"), "P X1 X2\r\n         -50         200\r\n-->");
}

TEST(Bds5Examples, PowerUp48) { // L4934-4944
    TestDrive t;
    t.download(example("48-power-up.bds"));
    t.type("X1=0\r");
    t.drive.powerUp();
    const std::string out = t.wait(100ms);
    EXPECT_NE(out.find(std::string(drive_core::bds5::kSignOn) + "\r\nEXECUTING POWER-UP LABEL\r\n-->"),
              std::string::npos)
        << out;
    EXPECT_EQ(t.type("P X1\r"), "P X1\r\n           1\r\n-->");
}

TEST(Bds5Examples, Background49) { // L5006-5015
    TestDrive t;
    t.download(example("49-background.bds"));
    const std::string out = t.type("RUN\r", 1600ms);
    EXPECT_EQ(count(out, "EXECUTING BACKGROUND\r\n"), 4) << out;
    EXPECT_EQ(t.type("\x18"), "-->");
}

TEST(Bds5Examples, MultidropWakeUp50) { // L5433-5440
    TestDrive t;
    std::string out;
    for (const std::string& line : example("50-multidrop-wakeup.bds"))
        out += t.type(line.starts_with("\\") ? line.substr(0, 2) : line + "\r"); // "\A" has no CR
    EXPECT_NE(out.find("A->P \"THIS IS AXIS\" ADDR\r\nTHIS IS AXIS          65\r\nA->"), std::string::npos) << out;
    EXPECT_TRUE(out.ends_with("-->")) << "single-drop again";
}

TEST(Bds5Examples, Timers53And54) { // L5790-5814
    TestDrive t;
    t.download(example("53-timer-8.bds", {{"1\nSECOND DELAY\"", "1 SECOND DELAY\""}}));
    const std::string out = t.type("RUN 8\r", 1200ms);
    // The manual gives no count. TIL prints while TMR1 counts its 1000 ms down (L5790-5800); each line is
    // 28 characters, 29.2 ms at 9600 baud (8N1), and the next waits for it to leave (L4637), then TIL takes
    // 2.6 ms (Appendix F; at most 60 % more, L7735) and a millisecond for the port to be seen free: a line
    // every 29.2 to 34.3 ms, the first after RUN 8's echo (7.3 ms) and 8$, TMR1= and TIL (at most 16.8 ms).
    // At most 1 + (1000 - 7.3) / 29.2 = 35 lines, at least 1 + (1000 - 16.8) / 34.3 = 29.
    const int waiting = count(out, "WAITING FOR 1 SECOND DELAY\r\n");
    EXPECT_GE(waiting, 29) << out;
    EXPECT_LE(waiting, 35) << out;
    EXPECT_TRUE(out.ends_with("-->"));
    t.download(example("54-timer-9.bds"));
    EXPECT_EQ(t.type("RUN 9\r", 950ms), "RUN 9\r\n3 SECONDS\r\n");
    EXPECT_EQ(t.wait(100ms), "2 SECONDS\r\n");
    EXPECT_EQ(t.wait(1000ms), "1 SECOND\r\n");
    EXPECT_EQ(t.wait(1000ms), "-->");
}

TEST(Bds5Examples, SegmentWait56And58) { // L5857-5893 (ideal follower)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.download(example("56-seg-wait-46a.bds", {{"MOTION IN\nPROGRESS\"", "MOTION IN PROGRESS\""}}));
    const std::string out = t.type("RUN 46\r", 2000ms);
    // The manual gives no count. MA 10000 1000 from 0 with ACC = DEC = 100000 RPM/s (L1519, L1528), the
    // average rate of any S-curve (L2293): 1000 RPM = 68267 counts/s (4096 counts a turn) is reached in
    // 10 ms over 341 counts, so 10 + 136.5 + 10 = 156.5 ms of motion.
    // Each line is 20 characters, 20.8 ms at 9600 baud (8N1); the next waits for it (L4637), then TIL's
    // 2.6 ms (Appendix F, up to 60 % more) and a millisecond: a line every 20.8 to 26.0 ms, the first at most
    // ~15 ms into the move. At most 1 + 156.5 / 20.8 = 8 lines, at least 1 + (156.5 - 15) / 26.0 = 6.
    const int lines = count(out, "MOTION IN PROGRESS\r\n");
    EXPECT_GE(lines, 6) << out;
    EXPECT_LE(lines, 8) << out;
    EXPECT_TRUE(out.ends_with("-->")) << out;
    t.download(example("58-seg-3-output-47.bds"));
    t.type("RUN 47\r", 3000ms);
    EXPECT_TRUE(t.drive.output(1)) << "O1 came on with the deceleration";
}

TEST(Bds5Examples, JogJtSequence60) { // L5937-5946: the equivalent of macro example 1
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("ACC=20000\r");
    t.type("DEC=20000\r");
    std::vector<std::string> program{"1$"};
    for (const std::string& line : example("60-jog-jt-sequence.bds")) program.push_back(line);
    program.push_back("W 0");
    program.push_back("D 500"); // the motor settles on the command (following error)
    program.push_back("P PFB");
    program.push_back("B");
    t.download(program);
    EXPECT_EQ(t.type("RUN 1\r", 2500ms), "RUN 1\r\n       11000\r\n-->");
}

TEST(Bds5Examples, ErrorDemo62) { // L6069-6086
    TestDrive t;
    t.download(example("62-error-demo-11.bds"));
    const std::string entry = "ERR 83 LINE 2 '2'";
    EXPECT_EQ(t.type("RUN 11\r", 50ms),
              "RUN 11\r\n\r\n\n\a" + entry + std::string(40 - entry.size(), ' ') + "BAD OR OUT OF RANGE\r\n-->");
}

TEST(Bds5Examples, Record65) { // L6387-6391; "405\$;" also lacks the space before its comment
    TestDrive t;
    t.type("PLIM OFF\r");
    t.download(example("65-record-405.bds", {{"405\\$;", "405$ ;"}}));
    EXPECT_EQ(t.type("RUN 405\r", 700ms), "RUN 405\r\n-->");
    const std::string out = t.type("PLAY\r");
    EXPECT_EQ(count(out, "\r\n"), 1 + 1 + 500);
    EXPECT_NE(out.find("        1000\r\n"), std::string::npos) << "VFB reached the 1000 RPM jog";
}
