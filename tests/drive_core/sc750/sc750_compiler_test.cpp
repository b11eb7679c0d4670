// The ServoBASIC Plus compiler: every statement compiles to the expected form, every error path stops at
// the first error with its line, column, near-text and message; .BIN round trip and integrity; size limits.
#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_compiler.h"
#include "drive_core/sc750/sc750_lexer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace {

using namespace drive_core::sc750;

struct ErrorCase {
    const char* source;
    int line;
    int column;
    const char* near;
    const char* message; // a part of the message
};

class CompileErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(CompileErrors, StopAtTheFirstErrorWithItsPlace) {
    const ErrorCase& c = GetParam();
    const CompileResult r = compile(c.source);
    ASSERT_FALSE(r.ok()) << c.source;
    EXPECT_EQ(r.error->line, c.line) << r.error->text();
    EXPECT_EQ(r.error->column, c.column) << r.error->text();
    EXPECT_EQ(r.error->near, c.near) << r.error->text();
    EXPECT_NE(r.error->message.find(c.message), std::string::npos) << r.error->text();
}

// clang-format off
INSTANTIATE_TEST_SUITE_P(Sc750, CompileErrors, ::testing::Values(
    ErrorCase{"x = 1\n", 1, 1, "x", "x is not declared: DIM it before use"},
    ErrorCase{"DIM a AS INTEGER\nPRINT b\n", 2, 7, "b", "b is not declared"},
    ErrorCase{"10 PRINT 1\n", 1, 1, "10", "line numbers are not allowed"},
    ErrorCase{"PRINT \"abc\n", 1, 7, "\"abc", "string has no closing quote"},
    ErrorCase{"PRINT 1 # 2\n", 1, 9, "#", "unexpected character"},
    ErrorCase{"DIM 2x AS INTEGER\n", 1, 5, "2x", "a name must begin with a letter"},
    ErrorCase{"DIM a234567890123456789012345678901234567890 AS INTEGER\n", 1, 5,
              "a234567890123456789012345678901234567890", "longer than 39"},
    ErrorCase{"DIM a AS INTEGER\nDIM a AS FLOAT\n", 2, 5, "a", "declared twice"},
    ErrorCase{"DIM my.var AS INTEGER\n", 1, 5, "my.var", "may not contain '.'"},
    ErrorCase{"DIM POSITION AS INTEGER\n", 1, 5, "POSITION", "predefined name"},
    ErrorCase{"DIM IF AS INTEGER\n", 1, 5, "IF", "reserved word"},
    ErrorCase{"DIM a AS REAL\n", 1, 10, "REAL", "expected INTEGER, LONG, SINGLE, DOUBLE, FLOAT or STRING"},
    ErrorCase{"DIM s$ AS INTEGER\n", 1, 5, "s$", "must be a STRING"},
    ErrorCase{"DIM a AS INTEGER\nDIM NV b AS INTEGER\n", 2, 5, "NV", "non-volatile DIMs must come before"},
    ErrorCase{"PRINT 1\nDIM a AS INTEGER\n", 2, 1, "DIM", "DIM must come before the first executable statement"},
    ErrorCase{"PARAMS START\nKVP = 0.1\nFOO = 3\nPARAMS END\n", 3, 1, "FOO", "FOO is not a set-up parameter"},
    ErrorCase{"PARAMS START\nBLKTYPE = 7\nPARAMS END\n", 2, 11, "7", "value out of range for BLKTYPE"},
    ErrorCase{"PARAMS START\nKVP = x\nPARAMS END\n", 2, 7, "x", "a PARAMS value must be a number"},
    ErrorCase{"PRINT 1\nPARAMS START\n", 2, 1, "PARAMS", "PARAMS section must be at the start"},
    ErrorCase{"POSITION = 5\n", 1, 1, "POSITION", "POSITION is read-only"},
    ErrorCase{"VELOCITY[3] = 5\n", 1, 1, "VELOCITY", "read-only in a program"},
    ErrorCase{"DIM s AS STRING\ns = 5\n", 2, 1, "s", "a number cannot be assigned to a STRING"},
    ErrorCase{"DIM i AS INTEGER\ni = \"x\"\n", 2, 1, "i", "a string cannot be assigned to a number"},
    ErrorCase{"DIM i AS INTEGER\ni = \"a\" + 1\n", 2, 9, "+", "between a string and a number"},
    ErrorCase{"DIM i AS INTEGER\ni = \"a\" * \"b\"\n", 2, 9, "*", "cannot take strings"},
    ErrorCase{"DIM i AS INTEGER\ni = LEN(5)\n", 2, 9, "5", "LEN needs a string here"},
    ErrorCase{"DIM i AS INTEGER\ni = SQR(\"4\")\n", 2, 9, "\"4\"", "SQR needs a number here"},
    ErrorCase{"DIM s AS STRING\ns = MID$(\"abc\")\n", 2, 5, "MID$", "MID$ takes MID$(s$, start[, n])"},
    ErrorCase{"DIM a(3) AS INTEGER\na = 1\n", 2, 1, "a", "a is an array"},
    ErrorCase{"DIM a AS INTEGER\na(1) = 1\n", 2, 2, "(", "a is not an array"},
    ErrorCase{"GOTO Nowhere\n", 1, 6, "Nowhere", "label NOWHERE is not defined"},
    ErrorCase{"L1:\nL1:\n", 2, 1, "L1", "label L1 is defined twice"},
    ErrorCase{"CALL Missing\n", 1, 6, "Missing", "SUB MISSING is not defined"},
    ErrorCase{"IF 1 THEN\nPRINT 1\n", 1, 1, "IF", "IF without END IF"},
    ErrorCase{"END IF\n", 1, 1, "END", "END IF without IF"},
    ErrorCase{"ELSE\n", 1, 1, "ELSE", "ELSE without IF"},
    ErrorCase{"IF 1 THEN\nELSE\nELSE\nEND IF\n", 3, 1, "ELSE", "second ELSE"},
    ErrorCase{"IF 1\nEND IF\n", 1, 5, "", "THEN after the IF condition"},
    ErrorCase{"DIM i AS INTEGER\nFOR i = 1 TO 3\nPRINT i\n", 2, 1, "FOR", "FOR without NEXT"},
    ErrorCase{"DIM i, j AS INTEGER\nFOR i = 1 TO 3\nNEXT j\n", 3, 6, "j", "does not match"},
    ErrorCase{"DIM s AS STRING\nFOR s = 1 TO 3\nNEXT\n", 2, 1, "FOR", "numeric user variable"},
    ErrorCase{"NEXT\n", 1, 1, "NEXT", "NEXT without FOR"},
    ErrorCase{"WHILE 1\nPRINT 1\n", 1, 1, "WHILE", "WHILE without WEND"},
    ErrorCase{"WEND\n", 1, 1, "WEND", "WEND without WHILE"},
    ErrorCase{"PRINT 1 2\n", 1, 9, "2", "expected ; or , between PRINT items"},
    ErrorCase{"DIM a AS INTEGER\nINPUT \"x\" a\n", 2, 11, "a", "expected ; or , after the INPUT prompt"},
    ErrorCase{"WHEN VELOCITY > 3, GO.VEL\n", 1, 6, "VELOCITY", "a WHEN condition is INPn"},
    ErrorCase{"WHEN INP1 = 2, GO.VEL\n", 1, 13, "2", "compares with 0 or 1"},
    ErrorCase{"WHEN POSITION = 3, GO.VEL\n", 1, 15, "=", "expected > or <"},
    ErrorCase{"WHEN INP1 = 0 GO.VEL\n", 1, 15, "GO.VEL", ", between the WHEN condition and its action"},
    ErrorCase{"WHEN INP1 = 0, PRINT\n", 1, 16, "PRINT", "a WHEN action is"},
    ErrorCase{"WHEN INP1 = 0, OUT2 = 5\n", 1, 23, "5", "sets 0 or 1"},
    ErrorCase{"CONTINUE\n", 1, 1, "CONTINUE", "only as a WHEN action"},
    ErrorCase{"TMRSET(1, LATCH, 1, OUT1=1, INP1=1)\n", 1, 11, "LATCH", "expected LEVEL or PULSE"},
    ErrorCase{"TMRSET(1, LEVEL, 1, OUT13=1, INP1=1)\n", 1, 21, "OUT13", "OUT number out of range 1-12"},
    ErrorCase{"TMRSET(1, PULSE, 1, OUT1=1, INP17=1)\n", 1, 29, "INP17", "INP number out of range 1-16"},
    ErrorCase{"RESTART\n", 1, 1, "RESTART", "only in an INTERRUPT routine"},
    ErrorCase{"END\nINTERRUPT BOGUS\nEND INTERRUPT\n", 2, 11, "BOGUS", "unknown interrupt source"},
    ErrorCase{"END\nINTERRUPT CHAR\nEND INTERRUPT\nINTERRUPT CHAR\nEND INTERRUPT\n", 4, 11, "CHAR", "defined twice"},
    ErrorCase{"END\nINTERRUPT CHAR\nEND INTERRUPT\nSUB A\nEND SUB\n", 4, 1, "SUB", "SUBs must come before"},
    ErrorCase{"END\nSUB A\nPRINT 1\n", 2, 1, "SUB", "SUB A has no END SUB"},
    ErrorCase{"END\nSUB A\nEND SUB\nSUB A\nEND SUB\n", 4, 5, "A", "SUB A is defined twice"},
    ErrorCase{"SUB A\nEND SUB\n", 1, 1, "SUB", "must come after the main program's END"},
    ErrorCase{"END\nSUB A\nGOTO Out\nEND SUB\nOut:\n", 3, 6, "Out", "GOTO OUT leaves its SUB"},
    ErrorCase{"PRINT (1 + 2\n", 1, 13, "", "to close the parenthesis"},
    ErrorCase{"PRINT 1 +\n", 1, 10, "", "expression expected at end of line"},
    ErrorCase{"DIM a, b AS INTEGER\nSWAP a\n", 2, 7, "", ", between the two variables"},
    ErrorCase{"DIM a AS INTEGER\nDIM s AS STRING\nSWAP a, s\n", 3, 1, "SWAP", "same type"},
    ErrorCase{"IF \"a\" THEN PRINT 1\n", 1, 4, "\"a\"", "a condition cannot be a string"},
    ErrorCase{"PRINT 1 : : DIM\n", 1, 13, "DIM", "DIM must come before"},
    ErrorCase{"PARAMS START\n5 = 1\nPARAMS END\n", 2, 1, "5", "expected a set-up parameter or PARAMS END"},
    ErrorCase{"DIM a(4096) AS INTEGER\n", 1, 7, "4096", "array too large (upper bound at most 4095)"},
    ErrorCase{"DIM a(n) AS INTEGER\n", 1, 7, "n", "an array size must be an integer constant"},
    ErrorCase{"DIM 5 AS INTEGER\n", 1, 5, "5", "expected a variable name"},
    ErrorCase{"END\nINTERRUPT CHAR\nPRINT 1\n", 2, 1, "INTERRUPT", "INTERRUPT CHAR has no END INTERRUPT"},
    ErrorCase{"END\nINTERRUPT CHAR\nEND INTERRUPT\nHere:\n", 4, 1, "Here",
              "only INTERRUPT routines may follow the interrupt routines"},
    ErrorCase{"END\nSUB 5\nEND SUB\n", 2, 5, "5", "expected a SUB name"},
    ErrorCase{"CALL 5\n", 1, 6, "5", "expected a SUB name"},
    ErrorCase{"GOTO 5\n", 1, 6, "5", "expected a label"},
    ErrorCase{"= 5\n", 1, 1, "=", "expected a statement"},
    ErrorCase{"GO.VEL 5\n", 1, 8, "5", "unexpected '5' after the statement"},
    ErrorCase{"END SUB\n", 1, 1, "END", "END SUB without SUB"},
    ErrorCase{"IF 1 THEN\nELSE\nELSE IF 1 THEN\nEND IF\n", 3, 1, "ELSE", "ELSE IF after ELSE"},
    ErrorCase{"DIM i AS INTEGER\nFOR i = 1 TO \"x\"\nNEXT\n", 2, 14, "\"x\"", "FOR needs numbers"},
    ErrorCase{"DIM i AS INTEGER\nFOR i = 1 TO 3 STEP \"x\"\nNEXT\n", 2, 21, "\"x\"", "FOR needs numbers"},
    // SWAP writes both: another axis's variable is refused where it is named (SWAP never reaches PacLAN)
    ErrorCase{"SWAP RUN.SPEED, RUN.SPEED[3]\n", 1, 17, "RUN.SPEED", "another axis's RUN.SPEED is read-only"},
    ErrorCase{"SWAP 1, 2\n", 1, 6, "1", "expected a variable"},
    ErrorCase{"DIM s AS STRING\ns = LEFT$(3, 1)\n", 2, 11, "3", "LEFT$ needs a string here"},
    ErrorCase{"DIM s AS STRING\ns = UCASE$(\"a\") + STR$(\"b\")\n", 2, 24, "\"b\"", "STR$ needs a number here"},
    ErrorCase{"DIM i AS INTEGER\ni = -\"a\"\n", 2, 5, "-", "needs a number"},
    ErrorCase{"TMRSET(1, LEVEL, 1, INP1=1, OUT1=1)\n", 1, 21, "INP1", "expected OUTn = 0|1"},
    ErrorCase{"TMRSET(1, LEVEL, 1, OUT1=2, INP1=1)\n", 1, 26, "2", "expected 0 or 1"},
    ErrorCase{"TMRSET(1, LEVEL, 1, OUT1=1, INP1=1, POUT2=3)\n", 1, 43, "3", "expected 0 or 1"},
    ErrorCase{"DIM a(3) AS INTEGER\nPRINT a\n", 2, 7, "a", "a is an array: give an index in ( )"},
    ErrorCase{"PRINT 1 + THEN\n", 1, 11, "THEN", "unexpected THEN"},
    ErrorCase{"END\nLoop1:\nGOTO Loop1\nSUB A\nGOTO Loop1\nEND SUB\n", 5, 6, "Loop1", "GOTO LOOP1 leaves its SUB or routine"}
));
// clang-format on

TEST(Sc750Compiler, LinesLongerThan255AreRejected) {
    const CompileResult r = compile("PRINT \"" + std::string(260, 'x') + "\"\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->line, 1);
    EXPECT_EQ(r.error->column, 256);
    EXPECT_EQ(r.error->message, "line longer than 255 characters");
}

TEST(Sc750Compiler, ErrorTextCarriesLineColumnAndNearText) {
    const CompileResult r = compile("DIM a AS INTEGER\n\n  a = b\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->text(), "LINE 3 COL 7 NEAR 'b': b is not declared: DIM it before use");
}

TEST(Sc750Compiler, EveryStatementCompiles) {
    const char* program = R"(PARAMS START
KVP = 0.087086
BLKTYPE = 2
PARAMS END
DIM NV Count AS LONG
DIM a, b AS INTEGER
DIM f AS SINGLE
DIM g AS DOUBLE
DIM s$, t AS STRING
DIM arr(10) AS FLOAT
REM a comment
' another one
LET a = 1 : b = -a
f = 2.5E-3 : g = .25
s$ = "x" + CHR$(65)
arr(2) = f * 2
IF a THEN b = 2 ELSE b = 3
IF a = 1 THEN
  PRINT "one"
ELSEIF a = 2 THEN
  PRINT "two"
ELSE
  PRINT "other"
ENDIF
FOR a = 1 TO 10 STEP 2 : NEXT a
WHILE b < 5 : b = b + 1 : WEND
GOSUB Routine
CALL Helper
SWAP a, b
PRINT a; b, f
INPUT "Value"; g
INPUT t
CLS
BEEP
ENABLE = 1
GO.VEL : GO.INCR : GO.ABS : GO.HOME : UPD.MOVE : ABORT.MOTION
PAUSE
WHEN INP1 = 0, CONTINUE
WHEN POS.COMMAND > 4096, OUT3 = 0
WHEN POSITION < -4096, RATIO = 2
WHEN ENCPOS > 100, GO.INCR
WHEN ANALOG.IN < 1.5, PAUSE
TMRSET(1, LEVEL, 0.5, OUT1=0, INP2=1)
TMRSET(2, PULSE, 0.1, OUT2=1, INP3=0, POUT4=1)
TMRSET(3, PULSE, 0.1, OUT2=1, INP3=0, )
TMENABLE1 = 1
INTR.CHAR = 1 : INTR.I3HI = 1 : INTR.POS.ERROR = 1
x1 = STATUS[3]
LANINT(1)[2] = 5
LANINTERRUPT[2]
STOP
END
Routine:
RETURN
SUB Helper
  IF a > 100 THEN GOTO Done
  a = a + 1
Done:
END SUB
INTERRUPT CHAR
  PRINT INKEY$
END INTERRUPT
INTERRUPT I3HI
  RESTART Routine
END INTERRUPT
)";
    const CompileResult r = compile(program);
    // x1 is deliberately undeclared: the first error wins, at its place
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->line, 48) << r.error->text();
    std::string fixed(program);
    fixed.replace(fixed.find("x1 = STATUS[3]"), 14, "a = STATUS[3] ");
    const CompileResult ok = compile(fixed);
    ASSERT_TRUE(ok.ok()) << ok.error->text();
    EXPECT_EQ(ok.program.params.size(), 2u);
    EXPECT_GE(ok.program.interrupts[2], 0); // CHAR
    EXPECT_TRUE(ok.program.variables[0].nonVolatile);
    EXPECT_EQ(ok.program.variables[3].type, ValueType::Float); // SINGLE
    EXPECT_EQ(ok.program.variables[4].type, ValueType::Float); // DOUBLE is float32 too
    EXPECT_EQ(ok.program.variables[7].count, 11);              // arr(10): 0..10
}

TEST(Sc750Compiler, KeywordsAndNamesAreCaseInsensitive) {
    const CompileResult r = compile("dim Speed as float\nSPEED = 3\nwhile speed > 0 : Speed = speed - 1 : wend\n");
    EXPECT_TRUE(r.ok()) << r.error->text();
}

TEST(Sc750Compiler, BinRoundTripsAndDetectsDamage) {
    const CompileResult r = compile("DIM s AS STRING\nDIM a(4) AS INTEGER\ns = \"hi\"\nPRINT s; a(2)\nEND\n"
                                    "INTERRUPT FAULT\nRESTART\nEND INTERRUPT\n");
    ASSERT_TRUE(r.ok());
    BinReadResult back = readBin(r.bin);
    ASSERT_EQ(back.status, BinStatus::Ok) << back.message;
    EXPECT_EQ(writeBin(*back.program), r.bin);
    EXPECT_EQ(back.program->lineAt(back.program->addressOfLine(4)), 4);
    auto damaged = r.bin;
    damaged[damaged.size() / 2] ^= 0x40;
    EXPECT_EQ(readBin(damaged).status, BinStatus::BadChecksum);
    auto old = r.bin;
    old[8] = 9; // version
    EXPECT_EQ(readBin(old).status, BinStatus::BadVersion);
    EXPECT_EQ(readBin(std::vector<std::uint8_t>(r.bin.begin(), r.bin.begin() + 20)).status, BinStatus::TooShort);
}

TEST(Sc750Compiler, SizeLimitsOfStandardAndTurboModels) {
    std::string program = "DIM a AS INTEGER\n";
    for (int i = 0; i < 1500; ++i) program += "a = a + " + std::to_string(i) + "\n"; // 6 instr = 30 bytes each
    const CompileResult standard = compile(program);
    ASSERT_FALSE(standard.ok());
    EXPECT_NE(standard.error->message.find("a standard SC750 holds 25,000"), std::string::npos);
    const CompileResult turbo = compile(program, CompileOptions{true});
    EXPECT_TRUE(turbo.ok()) << turbo.error->text();
    EXPECT_GT(turbo.program.codeBytes(), 25000);
    const CompileResult data = compile("DIM s(100) AS STRING\nEND\n", CompileOptions{true});
    ASSERT_FALSE(data.ok());
    EXPECT_NE(data.error->message.find("too much data"), std::string::npos);
}

TEST(Sc750Compiler, TurboCodeLimitIsReportedAtTheMainProgramsEnd) { // L2648
    std::string program = "DIM a AS INTEGER\n";
    for (int i = 0; i < 3000; ++i) program += "a = a + " + std::to_string(i) + "\n"; // 20 bytes each
    program += "  END\nEND\nSUB Never\nEND SUB\n";
    const CompileResult r = compile(program, CompileOptions{true});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->line, 3002);
    EXPECT_EQ(r.error->column, 3);
    EXPECT_EQ(r.error->near, "END");
    EXPECT_NE(r.error->message.find("bytes of code, a turbo SC750 holds 57,216"), std::string::npos) << r.error->text();
}

} // namespace

namespace {

// Robustness with a fixed seed: damaged versions of the manual's examples (bytes dropped, swapped or
// replaced, as OCR does) never crash the compiler; whatever compiles also round-trips through .BIN.
TEST(Sc750Compiler, DamagedSourcesNeverCrashTheCompiler) {
    const char* names[] = {"repaired/04-part-num.bas", "repaired/05-seekhome.bas", "repaired/06-simple-seekhome.bas",
                           "03-time-wait.bas"};
    std::uint32_t seed = 12345;
    auto random = [&seed](std::uint32_t n) {
        seed = seed * 1664525u + 1013904223u;
        return (seed >> 8) % n;
    };
    const char alphabet[] = "\"'():;,=<>+-*/^$.[]\r\n 0123456789ABCDEFIFENDTHEN";
    int compiled = 0;
    for (const char* name : names) {
        std::ifstream in(std::string(SC750_EXAMPLES_DIR) + "/" + name, std::ios::binary);
        const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_FALSE(original.empty()) << name;
        for (int round = 0; round < 250; ++round) {
            std::string s = original;
            for (int k = 0, n = 1 + int(random(4)); k < n; ++k) {
                const std::size_t at = random(std::uint32_t(s.size()));
                switch (random(3)) {
                case 0: s.erase(at, 1 + random(8)); break;
                case 1: s[at] = alphabet[random(sizeof alphabet - 1)]; break;
                default: s.insert(at, 1, alphabet[random(sizeof alphabet - 1)]); break;
                }
            }
            const CompileResult r = compile(s);
            if (!r.ok()) {
                EXPECT_GT(r.error->line, 0);
                EXPECT_GT(r.error->column, 0);
                continue;
            }
            ++compiled;
            EXPECT_EQ(readBin(r.bin).status, BinStatus::Ok);
        }
    }
    RecordProperty("compiled", compiled);
}

} // namespace

namespace {

TEST(Sc750Compiler, DeepNestingIsAnErrorNotACrash) {
    std::string program;
    for (int i = 0; i < 150; ++i) program += "WHILE 1\n";
    for (int i = 0; i < 150; ++i) program += "WEND\n";
    const CompileResult r = compile(program);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->message, "nested too deeply");
}

TEST(Sc750Compiler, ABinWithAnOperandOutOfRangeIsRefused) {
    CompileResult r = compile("DIM a AS INTEGER\na = 1\n");
    ASSERT_TRUE(r.ok());
    for (Instruction& i : r.program.code)
        if (i.op == Op::StoreV) i.arg = 7; // no variable 7: a crafted image with a valid CRC
    EXPECT_EQ(readBin(writeBin(r.program)).status, BinStatus::Malformed);
}

} // namespace
