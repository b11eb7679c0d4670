// Every complete example program of the SC750 manual compiles (the repaired versions where OCR broke
// them, digest §8), and so do the fragments once declared and wrapped into a program.
#include "drive_core/sc750/sc750_compiler.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using drive_core::sc750::compile;

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::filesystem::path kExamples = SC750_EXAMPLES_DIR;

class ManualExample : public ::testing::TestWithParam<const char*> {};

TEST_P(ManualExample, Compiles) {
    const auto result = compile(readFile(kExamples / GetParam()));
    ASSERT_TRUE(result.ok()) << GetParam() << ": " << result.error->text();
    EXPECT_FALSE(result.bin.empty());
    EXPECT_FALSE(result.program.lines.empty());
}

INSTANTIATE_TEST_SUITE_P(Sc750, ManualExample,
                         ::testing::Values("repaired/01-boilerplate.bas", "02-loop-again.bas", "03-time-wait.bas",
                                           "repaired/04-part-num.bas", "repaired/05-seekhome.bas",
                                           "repaired/06-simple-seekhome.bas"));

TEST(Sc750Examples, DamagedOriginalsFailWithALineNumber) {
    // The unrepaired PART_NUM listing lost the ' of its first comment line (L2864).
    const auto result = compile(readFile(kExamples / "04-part-num.bas"));
    ASSERT_FALSE(result.ok());
    EXPECT_GT(result.error->line, 0);
    EXPECT_GT(result.error->column, 0);
}

// The fragments, declared and wrapped into complete programs.
TEST(Sc750Examples, FragmentsCompileInsideAProgram) {
    const char* programs[] = {
        // f02 gearing phase correction (L1657-L1664)
        "ACCEL.GEAR = 1200\nDECEL.GEAR = 1200\nGEARERROR = 0\nWHEN INP1=0, CONTINUE\nGEARING = 1\n"
        "WHILE GEARLOCK=0 : WEND\nINDEX.DIST= GEARERROR\nGO.INCR\nEND\n",
        // f04 fault interrupt (L1916-L1928)
        "DIM dummy_variable AS STRING\nINTR.FAULT = 1\nEND\nINTERRUPT FAULT\nPrint \"The controller has faulted\"\n"
        "Print \"The fault code is \", FAULTCODE\nPrint \"Correct the fault and press fault reset\"\n"
        "Input \"Press any key to continue\", dummy_variable\nRESTART\nEND INTERRUPT\n",
        // f05 WHEN GO.VEL (L2025-L2030)
        "RUN.SPEED = 1000\nGO.VEL\nRUN.SPEED = 500\nWHEN INP3 = 0, GO.VEL\nEND\n",
        // f06 PAUSE (L2038-L2044)
        "PAUSE.TIME = 1.00\nPAUSE\nEND\n",
        // f07 PacLAN status (L2347-L2354), the split string rejoined
        "IF STATUS[3] = 1 THEN\nPRINT \"Axis 3 is connected to PacLAN\"\nELSE\n"
        "PRINT \"Axis 3 is not connected to PacLAN\"\nEND IF\nEND\n",
        // f08 PacLAN interrupt (L2366-L2370)
        "INTR.PACLAN = 1\nEND\nINTERRUPT PACLAN\nPRINT \"PacLAN interrupt from axis \"; AXIS.INTR\nEND INTERRUPT\n",
        // f01 line format (L1024-L1031), its comment rejoined: `\` comments and ENDIF
        "DIM PEAK_VEL AS FLOAT \\ DECLARE USERVERS\nDIM Value1 AS FLOAT\nIF VELOCITY > 0 THEN \\ PEAK DETECT\n"
        "  IF VELOCITY > PEAK_VEL THEN\n    PEAK_VEL = VELOCITY\n  ENDIF\nELSE\nENDIF\nEND\n",
        // one-line snippets (L1612, L1685, L1891-L1893, L2125, L2294, L2300)
        "DIM x AS FLOAT\nENC.IN = 1000\nENC.OUT = 512\nINTR.I3HI = 1\nINTR.CHAR =1\nINTR.I1LO = 0\nPWM12 = 57\n"
        "x = VELOCITY[ 3 ]\nTARGET.POS = 3 * TARGET.POS[ 9 ]\nx = LANINT(2)[3]\nLANFLT(1)[4] = "
        "x\nLANINTERRUPT[5]\nEND\n",
        // operator examples (L1094-L1117)
        "DIM Value1, A AS INTEGER\nA = 2^16 : A = - 3 : A = 4.21*3 : A = 10.5/2 : A = 5 MOD 2 : A = 27 + 8\n"
        "WHILE Value1 > 1 XOR ENCPOS = 102400\nWEND\nIF A = 2 AND Value1 <> 3 OR Value1 >= 4 THEN GOTO L1\nL1:\nEND\n",
    };
    for (const char* program : programs) {
        const auto result = compile(program);
        EXPECT_TRUE(result.ok()) << program << "\n" << (result.error ? result.error->text() : "");
    }
}

} // namespace
