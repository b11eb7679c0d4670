// The ServoBASIC Plus VM on the simulated SC750: QuickBASIC semantics, PRINT/INPUT formatting, control
// flow, PAUSE/TIME/WHEN timing, interrupts, run-time errors. Simulated time throughout.
#include "sc750_bench.h"

namespace sc750_test {
namespace {

TEST(Sc750Vm, PrintFormatsNumbersLikeQuickBasic) {
    Bench b("DIM f AS FLOAT\nf = 0.5\nPRINT 5; -3; f; \"a\"\nPRINT 1.5E+10\nPRINT \"x\", \"y\"\nPRINT 10 / 4;\nPRINT "
            "\"!\"\n");
    b.run(0.1);
    EXPECT_EQ(b.out, " 5 -3  .5 a\r\n 1.5E+10 \r\nx             y\r\n 2.5 !\r\n");
}

TEST(Sc750Vm, IntegersRoundHalfToEvenAndTrueIsMinusOne) {
    Bench b("DIM i, j, t AS INTEGER\nDIM f AS DOUBLE\ni = 2.5\nj = 3.5\nt = (1 = 1)\nf = 7 / 2\n"
            "PRINT i; j; t; f; 7 MOD 3; NOT 0; 6 AND 3; 6 OR 3; 6 XOR 3; 2 ^ 10; -2 ^ 2; 2 + 3 * 5\n");
    b.run(0.1);
    EXPECT_EQ(b.out, " 2  4 -1  3.5  1 -1  2  7  5  1024 -4  17 \r\n");
}

TEST(Sc750Vm, DoubleIsSinglePrecision) {
    Bench b("DIM d AS DOUBLE\nd = 1 / 3\nPRINT d\n");
    b.run(0.1);
    EXPECT_EQ(b.out, " .3333333 \r\n");
}

TEST(Sc750Vm, StringFunctionsFollowTheManual) {
    Bench b("DIM s$, e AS STRING\ns$ = \"  Servo  \"\n"
            "PRINT \"[\"; LTRIM$(s$); \"]\"; LEN(s$); ASC(e); ASC(\"A\")\n"
            "PRINT MID$(\"PN01-12.50\", 6); MID$(\"abc\", 2, 1); LEFT$(\"abc\", 2); RIGHT$(\"abc\", 2)\n"
            "PRINT UCASE$(\"pn\"); LCASE$(\"AB\"); CHR$(65); HEX$(255); STR$(7); SPACE$(2); STRING$(3, \"*\")\n"
            "PRINT INSTR(\"hello\", \"l\"); INSTR(4, \"hello\", \"l\"); VAL(\".2\"); VAL(\"01\"); VAL(\"x\")\n");
    b.run(0.1);
    EXPECT_EQ(b.out, "[Servo] 9  0  65 \r\n12.50babbc\r\nPNabAFF 7  ***\r\n 3  4  .2  1  0 \r\n");
}

TEST(Sc750Vm, ControlFlowForWhileGosubSubSwap) {
    Bench b("DIM i, n, a, c AS INTEGER\nDIM x(3) AS INTEGER\n"
            "FOR i = 1 TO 3 : x(i) = i * i : NEXT i\n"
            "FOR i = 10 TO 1 STEP -4\nPRINT i;\nNEXT\nPRINT\n"
            "WHILE n < 3 : n = n + 1 : WEND\n"
            "a = 1 : c = 2\nSWAP a, c\nGOSUB Show\nCALL Twice\nPRINT x(3); n; a; c\nEND\n"
            "Show:\nPRINT \"gosub\"\nRETURN\n"
            "SUB Twice\nn = n * 2\nIF n > 5 THEN GOTO Done\nn = 0\nDone:\nEND SUB\n");
    b.run(0.1);
    EXPECT_EQ(b.out, " 10  6  2 \r\ngosub\r\n 9  6  2  1 \r\n");
    EXPECT_EQ(b.frames, "\x01"
                        "e14CA\r"); // the end event: line 14, the END of the main program
    EXPECT_EQ(b.drive.vm().state(), Vm::State::Ended);
}

TEST(Sc750Vm, IfElseIfChainsAndSingleLineIf) {
    Bench b("DIM k AS INTEGER\nFOR k = 1 TO 4\nIF k = 1 THEN\nPRINT \"one\"\nELSE IF k = 2 THEN\nPRINT \"two\"\n"
            "ELSE IF k = 3 THEN\nPRINT \"three\"\nELSE\nPRINT \"many\"\nEND IF\nNEXT k\n"
            "IF k > 4 THEN PRINT \"done\" ELSE PRINT \"not\"\n");
    b.run(0.1);
    EXPECT_EQ(b.out, "one\r\ntwo\r\nthree\r\nmany\r\ndone\r\n");
}

TEST(Sc750Vm, LoopAgainExamplePrintsForever) { // manual §4.1.6, L1133-L1137
    Bench b("Loop_Again:\nPRINT \"All work and no play\"\nGOTO Loop_Again\n");
    b.run(0.05);
    EXPECT_GT(b.out.size(), 10 * std::string("All work and no play\r\n").size());
    EXPECT_TRUE(b.drive.decimalPoint()); // running: the display's decimal point is lit
}

TEST(Sc750Vm, TimeWaitExamplePrintsAfterFiveSeconds) { // manual §4.4.3.3, L2052-L2059
    Bench b("TIME = 0\nwait_loop:\nIF TIME > 5.0 THEN\n    PRINT TIME\nELSE GOTO wait_loop\nEND IF\n");
    b.run(4.9);
    EXPECT_EQ(b.out, "");
    b.run(0.2);
    ASSERT_FALSE(b.out.empty());
    EXPECT_NEAR(std::stod(b.out), 5.0, 0.002);
    EXPECT_EQ(b.drive.vm().state(), Vm::State::Ended);
}

TEST(Sc750Vm, PauseWaitsPauseTimeSeconds) {
    Bench b("PAUSE.TIME = 1.00\nPAUSE\nPRINT TIME\n");
    b.run(0.99);
    EXPECT_EQ(b.out, "");
    b.run(0.02);
    EXPECT_NEAR(std::stod(b.out), 1.0, 0.001);
}

TEST(Sc750Vm, WhenActsWithinOnePollingPeriodAndLatches) {
    Bench b("TIME = 0\nWHEN INP3 = 0, OUT1 = 0\nPRINT \"fired\"\n");
    b.run(0.5);
    EXPECT_EQ(b.out, "");
    EXPECT_FALSE(b.drive.output(1));
    const double t0 = b.value("TIME");
    b.drive.setInput(3, false);
    b.drive.step(drive_core::Microseconds(427));
    EXPECT_TRUE(b.drive.output(1)); // OUT1 = 0: transistor on
    EXPECT_NEAR(b.value("WHEN.TIME"), t0, 0.000427 * 2);
    b.run(0.01);
    EXPECT_EQ(b.out, "fired\r\n");
}

TEST(Sc750Vm, InputEchoesAndRedoesFromStart) {
    Bench b("DIM q AS INTEGER\nDIM s AS STRING\nINPUT \"Number\"; q\nINPUT \"Name\", s\nPRINT q * 2; s\n");
    b.run(0.01);
    EXPECT_EQ(b.out, "Number? ");
    b.type("abc\r");
    b.run(0.01);
    EXPECT_EQ(b.out, "Number? abc\r\n?Redo from start\r\nNumber? ");
    b.out.clear();
    b.type("21\r");
    b.run(0.01);
    b.type("Servo\r");
    b.run(0.01);
    EXPECT_EQ(b.out, "21\r\nNameServo\r\n 42 Servo\r\n");
}

TEST(Sc750Vm, InputInterruptIsTakenOnceAndDisablesItself) {
    Bench b("DIM n AS INTEGER\nINTR.I5LO = 1\nLoop1:\nGOTO Loop1\nEND\n"
            "INTERRUPT I5LO\nn = n + 1\nPRINT \"low\"; INTR.I5LO\nEND INTERRUPT\n");
    b.run(0.1);
    b.drive.setInput(5, false);
    b.run(0.1);
    EXPECT_EQ(b.out, "low 0 \r\n");
    EXPECT_EQ(std::get<std::int32_t>(b.user("N")), 1);
    EXPECT_TRUE(b.drive.vm().running());
}

TEST(Sc750Vm, InterruptDuringPauseResumesThePause) {
    Bench b("INTR.CHAR = 1\nPAUSE.TIME = 1\nPAUSE\nPRINT \"after\"\nEND\n"
            "INTERRUPT CHAR\nPRINT \"key \"; INKEY$\nEND INTERRUPT\n");
    b.run(0.3);
    b.type("k");
    b.run(0.3);
    EXPECT_EQ(b.out, "key k\r\n");
    b.run(0.5);
    EXPECT_EQ(b.out, "key k\r\nafter\r\n");
}

TEST(Sc750Vm, RestartLeavesTheInterruptAndRestartsMain) {
    Bench b("DIM n AS INTEGER\nn = n + 1\nPRINT \"main\"; n\nINTR.CHAR = 1\nHere:\nGOTO Here\nEND\n"
            "INTERRUPT CHAR\nPRINT \"isr \"; INKEY$\nRESTART\nEND INTERRUPT\n");
    b.run(0.05);
    b.type("x");
    b.run(0.05);
    EXPECT_EQ(b.out, "main 1 \r\nisr x\r\nmain 2 \r\n");
}

TEST(Sc750Vm, LevelInterruptFiresAgainOnceReenabled) {
    Bench b("DIM n AS INTEGER\nINTR.I2LO = 1\nHere:\nIF n < 3 THEN INTR.I2LO = 1\nGOTO Here\nEND\n"
            "INTERRUPT I2LO\nn = n + 1\nEND INTERRUPT\n");
    b.run(0.05);
    b.drive.setInput(2, false);
    b.run(0.05);
    EXPECT_EQ(std::get<std::int32_t>(b.user("N")), 3);
}

TEST(Sc750Vm, RunTimeErrorShowsF4AndStops) {
    Bench b("DIM a(2) AS INTEGER\nDIM i AS INTEGER\ni = 5\na(i) = 1\nPRINT \"never\"\n");
    b.run(0.05);
    EXPECT_EQ(b.drive.vm().state(), Vm::State::Error);
    EXPECT_EQ(b.value("FAULTCODE"), 244);
    EXPECT_EQ(b.drive.vm().currentLine(), 4);
    EXPECT_EQ(b.out.find("never"), std::string::npos);
}

TEST(Sc750Vm, BreakpointStopsBeforeTheLineAndContinues) {
    Bench b("DIM a AS INTEGER\na = 1\na = 2\na = 3\n", false);
    ASSERT_TRUE(b.drive.vm().addBreakpoint(3));
    EXPECT_FALSE(b.drive.vm().addBreakpoint(1)); // a DIM is not executable
    b.drive.vm().start();
    b.run(0.01);
    EXPECT_EQ(b.drive.vm().state(), Vm::State::AtBreakpoint);
    EXPECT_EQ(b.drive.vm().currentLine(), 3);
    EXPECT_EQ(std::get<std::int32_t>(b.user("A")), 1);
    b.drive.vm().resume();
    b.run(0.01);
    EXPECT_EQ(b.drive.vm().state(), Vm::State::Ended);
    EXPECT_EQ(std::get<std::int32_t>(b.user("A")), 3);
}

TEST(Sc750Vm, AtMostTenBreakpoints) {
    std::string program;
    for (int i = 0; i < 12; ++i) program += "PRINT " + std::to_string(i) + "\n";
    Bench b(program, false);
    for (int line = 1; line <= 10; ++line) EXPECT_TRUE(b.drive.vm().addBreakpoint(line));
    EXPECT_FALSE(b.drive.vm().addBreakpoint(11));
}

} // namespace
} // namespace sc750_test

namespace sc750_test {
namespace {

TEST(Sc750Vm, AutostartRunsAtPowerUpAndNonVolatileVariablesSurvive) { // L2814-L2829, L996-L1001
    Bench b("PARAMS START\nAUTOSTART = 1\nPARAMS END\nDIM NV boots AS INTEGER\nDIM scratch AS INTEGER\n"
            "boots = boots + 1\nscratch = scratch + 1\nPRINT boots; scratch\n",
            false);
    b.run(0.05);
    EXPECT_EQ(b.out, ""); // downloading does not start it
    b.drive.powerCycle();
    b.run(0.05);
    b.drive.powerCycle();
    b.run(0.05);
    EXPECT_EQ(b.out, " 1  1 \r\n 2  1 \r\n");
    EXPECT_EQ(b.value("ENABLE"), 0); // ENABLE is 0 after every power-up (L1500)
}

TEST(Sc750Vm, DisableInterruptWhenTheHardwareEnableDrops) {
    Bench b("ENABLE = 1\nINTR.DISABLE = 1\nHere:\nGOTO Here\nEND\nINTERRUPT DISABLE\nPRINT \"disabled\"; "
            "ENABLED; FAULTCODE\nEND INTERRUPT\n");
    b.run(0.05);
    EXPECT_EQ(b.value("FAULTCODE"), 8); // no fault, enabled
    b.drive.setEnableInput(false);
    b.run(0.05);
    EXPECT_EQ(b.out, "disabled 0  0 \r\n");
}

} // namespace
} // namespace sc750_test
