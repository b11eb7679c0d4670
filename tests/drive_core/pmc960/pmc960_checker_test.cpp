// The PMC-960 program checker: what the controller would refuse in its program buffer, at the line and column
// of the character it refuses, with the controller's own #xx code (7.22). Every expected position below is
// worked out from the manual's syntax (Lnnn): the controller reads a program one character at a time and
// refuses the first character it cannot take; a value checked at its <cr> is refused at the column after the
// line's last character. The manual's examples check clean, but for example 18's P commands, SCI-only (#C6).
#include "drive_core/pmc960/pmc960_checker.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using drive_core::pmc960::checkProgram;
using drive_core::pmc960::Diagnostic;

namespace {

// "line:column:#code" for each diagnostic, so a failure shows all of them.
std::vector<std::string> where(const std::vector<Diagnostic>& diagnostics) {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics) {
        char code[8];
        std::snprintf(code, sizeof code, "%02X", unsigned(d.code));
        out.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + ":#" + code);
    }
    return out;
}

using Where = std::vector<std::string>;

std::string repeated(const std::string& line, int times) {
    std::string text;
    for (int i = 0; i < times; ++i) text += line + "\n";
    return text;
}

} // namespace

TEST(Pmc960Checker, ACleanProgramHasNoDiagnostics) {
    const std::string program = "@A_ten_indexes_then_call_C\n"
                                "A3500\n"
                                "V 400\n" // spaces are not stored (L1412)
                                "I4096\n"
                                "I+,\n"
                                "LA9\n"
                                "FC\n"
                                "BB1:1\n"
                                "Q\n"
                                "@B_jog_until_IN02'_and_IN01'\r\n" // CR LF ends a line too
                                "J+;\n"
                                "U6:7\n"
                                "j*\n" // as the manual writes the stop commands (L1684)
                                "D100,\n"
                                "@C\n"
                                "OBC:C\n"
                                "E8:8\n"
                                "E";
    EXPECT_EQ(where(checkProgram(program)), Where{});
    EXPECT_EQ(where(checkProgram("")), Where{});
}

// The 21 commands (L641-711): K is none; S takes B D E F I L M N P S T V W (L665-677); TH takes A B C I L M
// P R S (L696-704). #A1 "An invalid command has been used" (L2332) at the letter that is none of them.
TEST(Pmc960Checker, AnUnknownCommandLetterIsA1AtThatLetter) {
    EXPECT_EQ(where(checkProgram("K100\n"
                                 "SX1\n"
                                 "THZ1\n"
                                 "s1f10000\n")), // the OCR's "s1f" for SLF (digest §11.1 #13): '1' is no S command
              (Where{"1:0:#A1", "2:1:#A1", "3:2:#A1", "4:1:#A1"}));
}

// #A2 "An invalid terminator or designator" (L2333): I[<distance>]#<direction>#[<sync>]<cr> (L1255) has no X;
// MPL has no comments but @ lines (L1026-1037), so the text after "I+ ;" is read as I's designators: the
// ';' is a sync, the 'g' (editor column 4, the space is not stored) is refused; A<rate><cr> (L1063) needs its
// rate before <cr>; D[<time>][<sync>]<cr> (L1123) has no X either.
TEST(Pmc960Checker, AnInvalidDesignatorIsA2AtThatCharacter) {
    EXPECT_EQ(where(checkProgram("I25X\n"
                                 "I+ ;go\n"
                                 "A\n"
                                 "D16X\n")),
              (Where{"1:3:#A2", "2:4:#A2", "3:1:#A2", "4:3:#A2"}));
}

// B, F and L search for their label (L1079, L1155, L1304) and give #C2 when no line starts with it (L2359),
// reported at the label. B| names TLB's label (L1081), known only when the branch runs.
TEST(Pmc960Checker, ALabelNoLineDefinesIsC2AtTheLabel) {
    EXPECT_EQ(where(checkProgram("@A\n"
                                 "BZ\n"
                                 "FZ1:1\n"
                                 "LZX3\n"
                                 "BA\n"
                                 "FA\n"
                                 "LA3\n"
                                 "B|\n"
                                 "@a\n" // labels are single bytes: a is not A
                                 "Ba\n")),
              (Where{"2:1:#C2", "3:1:#C2", "4:1:#C2"}));
}

// A line the controller stops reading never gets to its jump: B<label>[<hex>[:<mask>]]<cr> (L1079) has no X.
TEST(Pmc960Checker, OnlyTheFirstRefusalOfALineIsReported) {
    EXPECT_EQ(where(checkProgram("BZX\n")), Where{"1:2:#A2"});
}

// Labels 22H-7AH (L909): '{' is 7BH, and a <cr> is no label; #C5 (L2362). Loop counters X Y Z only: #C8 at
// the W (L1304-1308, L2365).
TEST(Pmc960Checker, AnInvalidLabelIsC5AndAnInvalidLoopCounterC8) {
    EXPECT_EQ(where(checkProgram("B{\n"
                                 "B\n"
                                 "@A\n"
                                 "LAW5\n")),
              (Where{"1:1:#C5", "2:1:#C5", "4:2:#C8"}));
}

// #C6 "A Program command cannot be executed during program execution" (L2363), when P's <program> or <label>
// designator comes (L1402): P? and P<cr> are SCI commands.
TEST(Pmc960Checker, ThePCommandInAProgramIsC6) {
    EXPECT_EQ(where(checkProgram("P?\n"
                                 "P\n")),
              (Where{"1:1:#C6", "2:1:#C6"}));
}

// Ranges of 5.7 (L885-909) and 7.x, checked when the value is complete: at its <cr>, or at the + that starts
// the motion (L2533).
TEST(Pmc960Checker, AValueOutOfEveryRangeIsRefusedWithItsCode) {
    EXPECT_EQ(
        where(checkProgram("A65536\n"       // #92: 1-65,535, external 0-65,534 (L885-900, L2318)
                           "I0+\n"          // #91: index 1-2,147,483,648 (L905, L2317)
                           "G1073741825+\n" // #93: go 0-1,073,741,824 (L906, L2319)
                           "D65536\n"       // #90: dwell 0-65,535 (L908, L1125, L2316)
                           "SV101\n"        // #90: feedrate 1-100 (L1696)
                           "SW2\n"          // #95: 0 or 1 (L1707-1708, L2321)
                           "V0\n"           // #94: 1 or 2 at least in every range (L886-903, L2320)
                           "TUA5:7:7\n"     // #AA: one ':' per number (L2342), at the second
                           "R2201\n")),     // #A4: tick 2 takes 3 hex digits, at most 512 (L2195, L2204)
        (Where{"1:6:#92", "2:2:#91", "3:11:#93", "4:6:#90", "5:5:#90", "6:3:#95", "7:2:#94", "8:6:#AA", "9:4:#A4"}));
}

// What depends on the controller's state when the line runs is not the text's fault: the external range
// takes A0 (L900); 5000 is a speed in some range or units (L2320); C without :speed needs a running cam (#81);
// SI<bank> needs THM (#9A); H's location is checked against THA (#9B); TGP20- subtracts from the present
// gain; SM1 needs DRVRDY' (#E2); TUV with the TUS in the table (#D4); THI's range is in conflict (L1918 vs
// L2336); with an encoder (THA 0) H ends at its direction (L1222), so I+ may follow on its line.
TEST(Pmc960Checker, StateDependentErrorsAreNotReported) {
    EXPECT_EQ(where(checkProgram("A0\n"
                                 "V5000\n"
                                 "J5000+\n"
                                 "C2000\n"
                                 "SI3?\n"
                                 "H5000+\n"
                                 "TGP20-\n"
                                 "SM1\n"
                                 "TUV60000\n"
                                 "THIa\n"
                                 "I+-\n"
                                 "H+I+\n")),
              Where{});
}

// The contour ticks G and H (L2202) are the controller's but not the simulator's (pmc960_commands.cpp).
TEST(Pmc960Checker, ContourTicksTheSimulatorLacksAreNotReported) {
    EXPECT_EQ(where(checkProgram("RG\n"
                                 "R1C0H\n")),
              Where{});
}

// The program-mode editor stores printing ASCII but space; anything else is ignored with a BELL (L1412): each
// byte of the UTF-8 degree sign, columns 4 and 5. '}' in column 1 erases the buffer to its end (L930).
TEST(Pmc960Checker, WhatTheEditorRefusesHasNoCode) {
    const auto d = checkProgram("@A_5\xC2\xB0\n"
                                "}\n");
    EXPECT_EQ(where(d), (Where{"1:4:#00", "1:5:#00", "2:0:#00"}));
    ASSERT_EQ(d.size(), 3u);
    EXPECT_NE(d[0].message.find("printing ASCII"), std::string::npos);
    EXPECT_NE(d[2].message.find("erases"), std::string::npos);
}

// 1,940 bytes (L982, pmc960_program.h), each line stored without its spaces and ended by CR (L1412): "A 1000"
// takes 6. 323 of them and "E" fill the buffer exactly; a 324th "A 1000" starts at byte 1,939, so its third
// stored character, the first 0 (editor column 3), is byte 1,941: #C1 (L2358).
TEST(Pmc960Checker, AProgramPastTheBufferIsC1WhereItStopsFitting) {
    EXPECT_EQ(where(checkProgram(repeated("A 1000", 323) + "E\n")), Where{});
    const auto d = checkProgram(repeated("A 1000", 324));
    EXPECT_EQ(where(d), Where{"324:3:#C1"});
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("1944"), std::string::npos);
}

// The 26 example files of the manual (digest §8). They hold the manual's prose; each entry quotes the commands
// from the file (markdown escapes and non-breaking spaces removed) and gives them as a program holds them:
// a label the example names is defined; the T1Y1 placeholders of the contour examples are concrete segments
// (digest §8.1); the binary transmissions of 21 and 22 are the V888 and I7500 they send (L1886, L1894); the
// OCR's s1f is SLF (§11.1 #13). Example 18's P commands are SCI commands: in a program each is #C6 (L2363).
TEST(Pmc960Checker, TheManualsExamplesCheckClean) {
    struct Example {
        std::string file;
        std::vector<std::string> quoted;
        std::string program;
        Where expected;
    };
    const std::vector<Example> examples = {
        {"01-label-comments.mpl",
         {"@.This_is_a_comment_line", "@X_Comment_after_a_program_label_'X'"},
         "@.This_is_a_comment_line\n@X_Comment_after_a_program_label_'X'\n",
         {}},
        {"02-acceleration.mpl", {"A3500<cr>", "A?", "A!"}, "A3500\nA?\nA!\n", {}},
        {"03-branch-conditional.mpl",
         {"BQ<cr>", "BQ1:1<cr>", "BQ10:F0<cr>", "label Q"},
         "@Q\nBQ\nBQ1:1\nBQ10:F0\n",
         {}},
        {"04-cam.mpl", {"C1000:100", "C2000^"}, "C1000:100\nC2000^\n", {}},
        {"05-dwell.mpl", {"D16<cr>", "D24,<cr>", "D300;<cr>"}, "D16\nD24,\nD300;\n", {}},
        {"06-exit-conditional.mpl", {"E<cr>", "E8:8<cr>"}, "E\nE8:8\n", {}},
        {"07-function-call.mpl", {"FA<cr>", "routine 'A'"}, "@A\nFA\n", {}},
        {"08-go.mpl", {"G!", "G+<cr>", "G%<cr>"}, "G!\nG+\nG%\n", {}},
        {"09-home-resolver.mpl", {"H15+<cr>", "H,-<cr>", "H*"}, "H15+\nH,-\nH*\n", {}},
        {"10-home-encoder.mpl", {"H+", "H,-", "H*"}, "H+\nH,-\nH*\n", {}},
        {"11-index.mpl",
         {"I250<cr>", "I+", "I,-", "I,+,-", "I!", "I?", "I*", "I%200<cr>"},
         "I250\nI+\nI,-\nI,+,-\nI!\nI?\nI*\nI%200\n",
         {}},
        {"12-jog.mpl", {"J!", "J?", "J+", "J,-", "J*", "J,-*+*-"}, "J!\nJ?\nJ+\nJ,-\nJ*\nJ,-*+*-\n", {}},
        {"13-loop-program-T.mpl", {"@T", "I+,", "LT9", "E"}, "@T\nI+,\nLT9\nE\n", {}},
        {"14-loop-reset-program-G-W.mpl",
         {"@G", "I+,", "BW1", "LG2999", "@W", "I,-", "LW19"},
         "@G\nI+,\nBW1\nLG2999\n@W\nI,-\nLW19\n",
         {}},
        {"15-loop-examples.mpl", {"LB20<cr>", "LBX20<cr>", "label 'B'"}, "@B\nLB20\nLBX20\n", {}},
        {"16-normalize.mpl", {"N2000,+", "N*", "N<cr>"}, "N2000,+\nN*\nN\n", {}},
        {"17-output-binary.mpl", {"OBC", "OBC:C", "OB?"}, "OBC\nOBC:C\nOB?\n", {}},
        {"18-program-command.mpl", {"P?", "P<cr>"}, "P?\nP\n", {"1:1:#C6", "2:1:#C6"}},
        {"19-software-limits.mpl", {"s1f10000", "s1r5000-"}, "slf10000\nslr5000-\n", {}},
        {"20-table-gains.mpl",
         {"TGP17 <cr>", "TGV34 <cr>", "TGP++V5-- <cr>", "TGE0 <cr>", "TGB4 <cr>"},
         "TGP17 \nTGV34 \nTGP++V5-- \nTGE0 \nTGB4 \n",
         {}},
        {"21-binary-input-velocity.mpl", {"v<00><03><78>"}, "V888\n", {}},
        {"22-binary-input-index.mpl", {"i<00><00><00><1d><1d><4c>", "7500 decimal"}, "I7500\n", {}},
        {"23-contour-first-segment.mpl", {"R}T1Y1}"}, "R1C0\n", {}},
        {"24-contour-three-segments-one-line.mpl", {"R}T1Y1}T2Y2}T3Y3}"}, "R1C032003300\n", {}},
        {"25-contour-separate-lines.mpl", {"R}T1Y1}<cr>", "R}T2Y2}<cr>", "R)T3Y3<cr>"}, "R1C0\nR3200\nR3300\n", {}},
        {"26-contour-sensor-start.mpl",
         {"SY30", "R)T1Y1)T2Y2<cr>", "SY0", "R)T3Y3<cr>"},
         "SY30\nR1C03200\nSY0\nR3300\n",
         {}},
    };
    std::set<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(PMC960_EXAMPLES_DIR))
        if (entry.path().extension() == ".mpl") files.insert(entry.path().filename().string());
    ASSERT_EQ(files.size(), examples.size());
    for (const Example& e : examples) {
        SCOPED_TRACE(e.file);
        ASSERT_TRUE(files.count(e.file));
        std::ifstream in(std::filesystem::path(PMC960_EXAMPLES_DIR) / e.file, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        std::string text;
        for (const char c : buffer.str())
            if (c != '\\') text += c; // the markdown escapes \_ \* (digest §11.1 #21)
        for (std::size_t at = text.find("\xC2\xA0"); at != std::string::npos; at = text.find("\xC2\xA0"))
            text.replace(at, 2, " ");
        for (const std::string& q : e.quoted) EXPECT_NE(text.find(q), std::string::npos) << q;
        EXPECT_EQ(where(checkProgram(e.program)), e.expected);
    }
}
