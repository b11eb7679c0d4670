// BDS5 commands: the 49 entries of App. C (L6555-7134), assignment, the v3.0.0 additions (L9302-9319) and the
// resident editor's commands (§4.3.2 L3466-3720). Entries count the parameters after the command word.
#include "bds5_catalog.h"

#include <array>

namespace drive_core::catalog::bds5 {
namespace {

constexpr unsigned kAll = kInteractive | kMonitor | kProgram;
constexpr unsigned kTerminalAndProgram = kInteractive | kProgram;

// Monitor mode accepts only ? ; B DIS EN ERR K MOTOR P PS R RS S ZPE and assignments (Table 2.4 L1300-1304).
// One entry per command form, packed by hand: clang-format would put every field on its own line.
// clang-format off
constexpr std::array kCommands{
    // ---- App. C ----
    CommandInfo{.name = ";", .longName = "COMMENT", .syntax = "; <text>", .modes = kAll | kEditor,
                .minEntries = 0, .maxEntries = 0,
                .description = "Comment. Comments can follow any instruction; entire lines can be comments. "
                               "The semicolon must be preceded by a space unless it is the first character "
                               "in a line. Allowed on any line including the BDS5 Editor.",
                .manualLines = "L6559-6566, L1355-1365"},
    CommandInfo{.name = "$", .longName = "LABEL", .syntax = "<label>$ | <A$|B$|C$> <switch> <ON|OFF>",
                .modes = kProgram, .minEntries = 0, .maxEntries = 2,
                .description = "Labels 0-500 (decimal constants, never repeated), allowed only in the user "
                               "program. Special labels: A$, B$, C$ (alarms, followed by the switch and the "
                               "state that fires them), VARIABLE$, POWER-UP$, AUTO$, MANUAL$, ERROR$ (must "
                               "be last) and BACKGROUND$. An alarm fires if its switch is in the given "
                               "state when execution is enabled; otherwise it is edge sensitive (ON = "
                               "positive edge).",
                .manualLines = "L6568-6593, L3728-3747, L4603-4615"},
    CommandInfo{.name = "?", .longName = "QUICK IF",
                .syntax = "? <expr> <logical> <expr> [instruction] [: instruction]", .modes = kAll,
                .minEntries = 4, .maxEntries = 14,
                .description = "Conditionally executes one instruction if the condition is true, and "
                               "another (after :) if it is false; either may be omitted but not both. The "
                               "instruction may be any instruction except TIL (ERR 117). Logical is GT, GE, "
                               "LT, LE, EQ or NE. Allowed from the interactive and monitor modes and the "
                               "user program.",
                .manualLines = "L6595-6612, L3836-3900"},
    CommandInfo{.name = "B", .longName = "BREAK", .syntax = "B", .modes = kProgram | kMonitor,
                .minEntries = 0, .maxEntries = 0,
                .description = "Break program execution: all tasks stop and the drive returns to the "
                               "interactive mode; motion in progress is not stopped. Allowed from the user "
                               "program or the monitor mode (^X from the terminal does S then B).",
                .manualLines = "L6614-6618, L3748-3750"},
    // App. C gives no modes for CONTINUE; interactive and program chosen like the other motion commands.
    CommandInfo{.name = "CONTINUE", .longName = "CONTINUE", .syntax = "CONTINUE [time]",
                .modes = kTerminalAndProgram, .minEntries = 0, .maxEntries = 1,
                .description = "Continue motion at the present speed and turn REG and GEAR off. Optionally "
                               "give the number of milliseconds (up to 1 second) over which the present "
                               "speed is averaged; default 1 ms. SEG becomes 1; a following J ramps with "
                               "ACC/DEC.",
                .manualLines = "L6620-6631, L3135-3158"},
    CommandInfo{.name = "DUMP", .longName = "DUMP", .syntax = "DUMP [VERSION|TL]", .modes = kInteractive,
                .minEntries = 0, .maxEntries = 1,
                .description = "Display all the variables and the user program on the terminal (protected "
                               "variables and program lines prefixed with ;), DUMP VERSION the firmware "
                               "version, DUMP TL the compensation (TL) variables (v3 adds LPF and LPFHZ). "
                               "Allowed from interactive; the drive must be disabled (ERR 51).",
                .manualLines = "L6633-6638, L5396-5414, L9315"},
    CommandInfo{.name = "D", .longName = "DELAY", .syntax = "D <time>", .modes = kProgram, .minEntries = 1,
                .maxEntries = 1, .idling = true,
                .description = "Delay program execution for the given time in milliseconds, up to "
                               "2,147,483,647 (25 days). Idling: with multitasking D suspends the task but "
                               "lets other tasks proceed. Allowed only from the user program.",
                .manualLines = "L6640-6648, L4479-4511"},
    CommandInfo{.name = "DIS", .longName = "DISABLE", .syntax = "DIS", .modes = kAll, .minEntries = 0,
                .maxEntries = 0,
                .description = "Disable the BDS5: turns off the variable READY. Allowed from interactive "
                               "mode, monitor mode and the user program.",
                .manualLines = "L6650-6654, L2117-2125"},
    CommandInfo{.name = "ED", .longName = "EDIT", .syntax = "ED", .modes = kInteractive, .minEntries = 0,
                .maxEntries = 0,
                .description = "Edit the user program with the resident editor (prompt e->; Escape exits). "
                               "Editor commands: P, empty line, PASS, I, F, C, DEL, SIZE, NEW. Allowed only "
                               "from interactive mode.",
                .manualLines = "L6656-6673, L3466-3482"},
    CommandInfo{.name = "ELIF", .longName = "ELSE IF", .syntax = "ELIF <expr> <logical> <expr>",
                .modes = kProgram, .minEntries = 3, .maxEntries = 3,
                .description = "Part of block IF: conditionally begins block execution when no earlier "
                               "block of the IF ran. Allowed from the user program.",
                .manualLines = "L6675-6685, L3938-4103"},
    CommandInfo{.name = "ELSE", .longName = "ELSE", .syntax = "ELSE", .modes = kProgram, .minEntries = 0,
                .maxEntries = 0,
                .description = "Part of block IF: begins the last block, executed when no IF/ELIF condition "
                               "was true. Allowed from the user program.",
                .manualLines = "L6687-6691, L3938-4103"},
    CommandInfo{.name = "EN", .longName = "ENABLE", .syntax = "EN", .modes = kAll, .minEntries = 0,
                .maxEntries = 0,
                .description = "Enable the BDS5: turns on the variable READY (and clears the FAULT latch "
                               "and the macro-move memory). Allowed from interactive mode, monitor mode and "
                               "the user program; not from ERROR$ (ERR 55).",
                .manualLines = "L6693-6697, L2111-2115, L2522"},
    CommandInfo{.name = "END", .longName = "END", .syntax = "END", .modes = kProgram, .minEntries = 0,
                .maxEntries = 0,
                .description = "End a task. With multitasking END ends that task. If there are no special "
                               "labels in the program (except POWER-UP$), END is equivalent to Break (B); "
                               "otherwise the BDS5 becomes inactive waiting for a task to resume execution.",
                .manualLines = "L6699-6703, L4579-4601"},
    CommandInfo{.name = "ENDIF", .longName = "END IF", .syntax = "ENDIF", .modes = kProgram, .minEntries = 0,
                .maxEntries = 0,
                .description = "Part of block IF: ends the block IF. Allowed from the user program.",
                .manualLines = "L6705-6709, L3938-4103"},
    CommandInfo{.name = "ERR", .longName = "ERROR", .syntax = "ERR <error number> | ERR HIST | ERR CLR",
                .modes = kAll, .minEntries = 1, .maxEntries = 1,
                .description = "ERR n displays the message for error n (1-999; ERROR NOT FOUND if unknown), "
                               "ERR HIST the error history (20 most recent errors, newest first) and ERR "
                               "CLR clears the history. Allowed from interactive and monitor modes and the "
                               "user program.",
                .manualLines = "L6711-6727, L6110-6148"},
    CommandInfo{.name = "GOSUB", .longName = "GO SUBROUTINE", .syntax = "GOSUB <label> | GOSUB X<n>",
                .modes = kProgram, .minEntries = 1, .maxEntries = 1,
                .description = "Go to a subroutine; RET returns. 4 levels (ERR 118). A user variable may "
                               "hold the label. Not allowed in alarms, VARIABLE$, BACKGROUND$ (ERR 63) or "
                               "ERROR$. Allowed only from the user program.",
                .manualLines = "L6729-6740, L3791-3821"},
    CommandInfo{.name = "GOTO", .longName = "GO TO", .syntax = "GOTO <label> | GOTO X<n>", .modes = kProgram,
                .minEntries = 1, .maxEntries = 1,
                .description = "Go to a program label; a user variable may hold the label. Jumping out of "
                               "IF blocks closes them; jumping into one gives ERR 116. Allowed only from "
                               "the user program.",
                .manualLines = "L6742-6753, L3752-3789, L4093-4103"},
    CommandInfo{.name = "H", .longName = "HOLD", .syntax = "H <switch> <ON|OFF>", .modes = kProgram,
                .minEntries = 2, .maxEntries = 2, .idling = true,
                .description = "Delay (hold up) execution of a task until a switch is in the specified "
                               "state. Any switch except REMOTE and XS11-XS50 (XS1-XS10 are allowed). "
                               "Idling. Allowed only from the user program.",
                .manualLines = "L6755-6766, L4450-4477"},
    CommandInfo{.name = "IF", .longName = "IF", .syntax = "IF <expr> <logical> <expr>", .modes = kProgram,
                .minEntries = 3, .maxEntries = 3,
                .description = "Conditionally execute a block of instructions, followed by any number of "
                               "ELIF, an optional ELSE and one ENDIF (ERR 115 if missing). Blocks nest. "
                               "Allowed from the user program.",
                .manualLines = "L6768-6783, L3938-4103"},
    CommandInfo{.name = "INPUT", .longName = "INPUT",
                .syntax = "INPUT \"<text>\" <variable>[decimal] [min max]", .modes = kProgram,
                .minEntries = 2, .maxEntries = 4, .idling = true,
                .description = "Print the text and wait for the operator to type a number and Enter; the "
                               "value is multiplied by 10^decimal and kept within min/max (both or neither) "
                               "or the variable's limits. Any programmable variable. Idling. Allowed only "
                               "from the user program.",
                .manualLines = "L6785-6802, L4380-4436"},
    CommandInfo{.name = "J", .longName = "JOG", .syntax = "J <velocity>", .modes = kTerminalAndProgram,
                .minEntries = 1, .maxEntries = 1,
                .description = "Jog at a continuous speed (within +/-VMAX) using ACC, DEC and SCRV; J 0 "
                               "stops at DEC. Allowed from the interactive mode and the user program.",
                .manualLines = "L6804-6815, L2437-2447"},
    CommandInfo{.name = "JF", .longName = "JOG FROM", .syntax = "JF <position> <velocity>",
                .modes = kTerminalAndProgram, .minEntries = 2, .maxEntries = 2,
                .description = "Jog, but wait until the position command (PCMD) crosses the specified "
                               "position before beginning accel/decel to the new velocity. Speed must not "
                               "be zero. Allowed from the interactive mode and the user program.",
                .manualLines = "L6817-6828, L2734-2750"},
    CommandInfo{.name = "JT", .longName = "JOG TO", .syntax = "JT <position> <velocity>",
                .modes = kTerminalAndProgram, .minEntries = 2, .maxEntries = 2,
                .description = "Jog at a continuous speed, but delay beginning accel/decel so that the "
                               "position command equals the specified position when the accel/decel is "
                               "complete. Allowed from the interactive mode and the user program.",
                .manualLines = "L6830-6841, L2734-2800"},
    CommandInfo{.name = "K", .longName = "KILL", .syntax = "K", .modes = kAll, .minEntries = 0,
                .maxEntries = 0,
                .description = "Disable the drive and break the program. Allowed from interactive and "
                               "monitor modes and the user program.",
                .manualLines = "L6843-6847, L2121-2123"},
    CommandInfo{.name = "MA", .longName = "MOVE ABSOLUTE", .syntax = "MA <position> [velocity]",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 2,
                .description = "Move to the specified position at the specified speed (VDEFAULT if not "
                               "given). Allowed from the interactive mode and the user program.",
                .manualLines = "L6849-6860, L2314-2340"},
    CommandInfo{.name = "MCA", .longName = "MACRO ABSOLUTE", .syntax = "MCA <position> [traverse] [end]",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 3,
                .description = "Define an absolute macro-move section to the specified position at the "
                               "specified traverse and ending speeds. Allowed from the interactive mode and "
                               "the user program.",
                .manualLines = "L6862-6875, L2500-2577"},
    CommandInfo{.name = "MCD", .longName = "MACRO DWELL", .syntax = "MCD <time>",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 1,
                .description = "Define a macro-move dwell section for the specified time (ms); only valid "
                               "when the previous section ended at zero speed. With profile regulation the "
                               "time is inversely proportional to the external input frequency. Allowed "
                               "from the interactive mode and the user program.",
                .manualLines = "L6877-6887, L2508-2514"},
    CommandInfo{.name = "MCGO", .longName = "MACRO GO", .syntax = "MCGO", .modes = kTerminalAndProgram,
                .minEntries = 0, .maxEntries = 0,
                .description = "Execute a macro move; only valid when the last macro-move section ended at "
                               "zero speed. Allowed from the interactive mode and the user program.",
                .manualLines = "L6889-6893, L2516-2522"},
    CommandInfo{.name = "MCI", .longName = "MACRO INCREMENTAL", .syntax = "MCI <distance> [traverse] [end]",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 3,
                .description = "Define an incremental macro-move section for the specified distance at the "
                               "specified traverse and ending speed. Allowed from the interactive mode and "
                               "the user program.",
                .manualLines = "L6895-6908"},
    CommandInfo{.name = "MI", .longName = "MOVE INCREMENTAL", .syntax = "MI <distance> [velocity]",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 2,
                .description = "Incrementally move the specified distance at the specified speed (VDEFAULT "
                               "if not given). Allowed from the interactive mode and the user program.",
                .manualLines = "L6910-6921, L2354-2402"},
    // App. C gives no modes; Table 2.4 lists MOTOR among the monitor commands.
    CommandInfo{.name = "MOTOR", .longName = "MOTOR", .syntax = "MOTOR", .modes = kInteractive | kMonitor,
                .minEntries = 0, .maxEntries = 0,
                .description = "Display the present motor/drive combination the BDS5 was configured for "
                               "when shipped. Not normally used by the customer.",
                .manualLines = "L6923-6927, L1300-1304"},
    CommandInfo{.name = "MRD", .longName = "MOVE R/D", .syntax = "MRD <R/D position> <velocity> [CW|CCW]",
                .modes = kTerminalAndProgram, .minEntries = 2, .maxEntries = 3,
                .description = "Absolute move so that the resolver-to-digital converter output (PRD) equals "
                               "the given value (0-4095 for 12-bit). CW or CCW force the direction, "
                               "otherwise the shortest way. Allowed from the interactive mode and the user "
                               "program.",
                .manualLines = "L6929-6939, L2581-2613"},
    CommandInfo{.name = "NORM", .longName = "NORMALIZE", .syntax = "NORM <position> [CAM]",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 2,
                .description = "Normalize the position command and position feedback to the specified "
                               "position (same as PFB=position). Allowed when there is no commanded motion. "
                               "v3: NORM <pos> CAM aligns and enables camming (GEAR must be off).",
                .manualLines = "L6941-6949, L2449-2483, L9314"},
    CommandInfo{.name = "P", .longName = "PRINT", .syntax = "P <expr>[format] | \"<text>\" ...",
                .modes = kAll, .minEntries = 1, .maxEntries = 14,
                .description = "Print expressions (optional format: B binary, H hex, S ON/OFF, C character, "
                               "nn.m or nn.m.p decimal point) and quoted texts on a new line, terminated "
                               "with CR LF. Allowed from the interactive and monitor modes and the user "
                               "program.",
                .manualLines = "L6951-6985, L4191-4358"},
    // chosen: the status prints may have no item (the status word alone).
    CommandInfo{.name = "PS", .longName = "PRINT WITH STATUS", .syntax = "PS <expr>[format] | \"<text>\" ...",
                .modes = kAll, .minEntries = 0, .maxEntries = 14,
                .description = "Print with status: identical to P except the status of the BDS5 (OFF, "
                               "READY, ACTIVE, FAULT, JOG, PROFILE, GEAR) is displayed at the end of the "
                               "line.",
                .manualLines = "L6987-6989, L4343-4358"},
    CommandInfo{.name = "PLAY", .longName = "PLAYBACK", .syntax = "PLAY", .modes = kInteractive,
                .minEntries = 0, .maxEntries = 0,
                // The listing's layout is not in the manual; bds5_recorder.h documents the one chosen.
                .description = "Play back recorded points: prints all the variables recorded by the last "
                               "RECORD command (ERR 65 if nothing was recorded since power-up). The first "
                               "line repeats the set-up: RECORD <n> <t> <v1> [<v2> <v3> <v4>]. Then one line "
                               "per sampled instant, the first taken when RECORD started and one every t ms "
                               "after: the values in RECORD order, each an integer in user units "
                               "right-justified in 12 columns as P prints it. Lines end with CR LF. Motion "
                               "Link's scope formats and plots the data. Not available while EXTDX is on "
                               "(v3: ERR 63).",
                .manualLines = "L6991-6993, L6395, L9295-9297"},
    CommandInfo{.name = "R", .longName = "REFRESH", .syntax = "R <expr>[format] | \"<text>\" ...",
                .modes = kAll, .minEntries = 1, .maxEntries = 14,
                .description = "Refresh screen: same as P except that no line feed is printed (CR only), to "
                               "overprint a status line. Allowed from the interactive and monitor modes and "
                               "the user program.",
                .manualLines = "L6995-6997, L4360-4378"},
    // chosen: RD idles like D (Table 4.8 lists only W, D, H, INPUT).
    CommandInfo{.name = "RD", .longName = "REGULATED DELAY", .syntax = "RD <time>", .modes = kProgram,
                .minEntries = 1, .maxEntries = 1, .idling = true,
                .description = "Delay program execution, timed by the external clock: the time is exact at "
                               "REGKHZ and lengthens as the external frequency drops. REG need not be on. "
                               "One task at a time (ERR 62). Allowed only from the user program.",
                .manualLines = "L6999-7009, L5823-5839"},
    CommandInfo{.name = "RECORD", .longName = "RECORD",
                .syntax = "RECORD <number> <time> <var1> [var2 var3 var4]", .modes = kTerminalAndProgram,
                .minEntries = 3, .maxEntries = 6,
                .description = "Record 1-4 variables every <time> ms for <number> intervals (at most 1000 "
                               "points in all: 1000/500/333/250). PE, REMOTE, TMR1-TMR4, VAVG, VXAVG and "
                               "user switches cannot be recorded. Allowed from the user program or the "
                               "interactive mode. Not available while EXTDX is on (v3: ERR 63).",
                .manualLines = "L7011-7037, L6370-6397, L9295-9297"},
    CommandInfo{.name = "RET", .longName = "RETURN", .syntax = "RET", .modes = kProgram, .minEntries = 0,
                .maxEntries = 0,
                .description = "Return from a subroutine (ERR 119 without GOSUB). Allowed only from the "
                               "user program.",
                .manualLines = "L7039-7043"},
    CommandInfo{.name = "RS", .longName = "REFRESH WITH STATUS",
                .syntax = "RS <expr>[format] | \"<text>\" ...", .modes = kAll, .minEntries = 0,
                .maxEntries = 14,
                .description = "Refresh screen with status: identical to R except the status of the drive "
                               "is displayed at the end of the printed line.",
                .manualLines = "L7045-7047"},
    CommandInfo{.name = "RUN", .longName = "RUN", .syntax = "RUN [label] | RUN X<n>",
                .modes = kTerminalAndProgram, .minEntries = 0, .maxEntries = 1,
                .description = "Run the program starting at the label (ERR 70 if missing); without a label, "
                               "run multitasking only. Allowed from the interactive mode; from v3.0.0 also "
                               "from within the program, to restart it from an alarm or error label.",
                .manualLines = "L7049-7062, L3736-3746, L9307"},
    CommandInfo{.name = "S", .longName = "STOP", .syntax = "S", .modes = kAll, .minEntries = 0,
                .maxEntries = 0,
                .description = "Stop motion using a deceleration of AMAX; all motion commands are cancelled "
                               "and the drive stays enabled (from monitor mode S also breaks the program). "
                               "Allowed from the interactive and monitor modes and the user program.",
                .manualLines = "L7064-7068, L2212-2231"},
    CommandInfo{.name = "TIL", .longName = "UNTIL", .syntax = "TIL <expr> <logical> <expr> [instruction]",
                .modes = kProgram, .minEntries = 3, .maxEntries = 14,
                .description = "Continuously execute an optional instruction until the condition is true; "
                               "without an instruction, delay until it is true. The instruction cannot be "
                               "another TIL. Not idling. Allowed only from the user program.",
                .manualLines = "L7070-7082, L3902-3936"},
    CommandInfo{.name = "TUNE", .longName = "TUNE", .syntax = "TUNE <bandwidth> <stability>",
                .modes = kTerminalAndProgram, .minEntries = 2, .maxEntries = 2,
                .description = "Tune the motor to a new load: sets KP, KV, KVI and KPROP for the bandwidth "
                               "(5, 10, 15, 20, 25, 30, 40, 50 Hz) and stability (1 slightly overdamped, 2 "
                               "critically damped, 3 slightly underdamped). Shakes the motor. Allowed from "
                               "the interactive mode and the user program.",
                .manualLines = "L7084-7096, L6264-6286"},
    CommandInfo{.name = "W", .longName = "WAIT", .syntax = "W <segment>", .modes = kProgram, .minEntries = 1,
                .maxEntries = 1, .idling = true,
                .description = "Wait for the given segment of the last motion command to start (W 0: until "
                               "motion stops); never waits when motion has stopped. Idling. Allowed only "
                               "from the user program.",
                .manualLines = "L7098-7111, L4513-4549"},
    CommandInfo{.name = "ZPE", .longName = "ZERO POSITION ERROR", .syntax = "ZPE", .modes = kAll,
                .minEntries = 0, .maxEntries = 0,
                .description = "Clear the position error (PCMD = PFB). Useful when enabling the position "
                               "loop after position error has accumulated. Allowed from the interactive and "
                               "monitor modes and the user program.",
                .manualLines = "L7113-7115, L2485-2494"},
    CommandInfo{.name = "<BDS", .longName = "SEND PROGRAM", .syntax = "<BDS", .modes = kTerminalAndProgram,
                .minEntries = 0, .maxEntries = 0,
                .description = "Send (download) the program from BDS5 program memory to the terminal, each "
                               "line ended by CR LF. Allowed from the interactive mode and the user program "
                               "(Chapter 4 says not from a program).",
                .manualLines = "L7117-7121, L5348-5354"},
    CommandInfo{.name = ">BDS", .longName = "RECEIVE PROGRAM", .syntax = ">BDS [password]",
                .modes = kTerminalAndProgram, .minEntries = 0, .maxEntries = 1,
                .description = "Receive (upload) a program from the terminal into program memory (prompt "
                               "l->, one line per prompt, Escape ends); the old program is destroyed. If "
                               "the editor password is set and missing or wrong, ERR 110 and the program "
                               "remains.",
                .manualLines = "L7123-7134, L5356-5394"},

    // ---- Assignment (L1437-1448) ----
    CommandInfo{.name = "=", .longName = "ASSIGNMENT", .syntax = "<variable>=<expr> | <variable> <expr>",
                .modes = kAll, .minEntries = 0, .maxEntries = 2,
                .description = "Set a programmable variable: VAR=expr, VAR expr or VAR = expr (the variable "
                               "is the command word). The variable's programming condition (ERR "
                               "50/51/81/111) and limits (ERR 83/84) apply.",
                .manualLines = "L1437-1448, L10078"},

    // ---- v3.0.0 additions (BDS5300.DOC L9302-9319, BDS5COM2 L10105-10116) ----
    CommandInfo{.name = "PA", .longName = "PRINT APPEND", .syntax = "PA <expr>[format] | \"<text>\" ...",
                .modes = kAll, .minEntries = 1, .maxEntries = 14, .version3 = true,
                .description = "Print Append: like P except there is no terminating carriage return and "
                               "line feed.",
                .manualLines = "L9305, L10111"},
    CommandInfo{.name = "PAS", .longName = "PRINT APPEND STATUS",
                .syntax = "PAS <expr>[format] | \"<text>\" ...", .modes = kAll, .minEntries = 0,
                .maxEntries = 14, .version3 = true,
                .description = "Print Append Status: identical to PA except it also prints the drive "
                               "status; no terminating CR LF.",
                .manualLines = "L9306, L10112"},
    // chosen: CLEARX, RAND, TRECORD and TPLAY modes (the notice gives none).
    CommandInfo{.name = "CLEARX", .longName = "CLEAR USER REGISTERS", .syntax = "CLEARX",
                .modes = kTerminalAndProgram, .minEntries = 0, .maxEntries = 0, .version3 = true,
                .description = "Clear all user registers and user flags (X1-X750, XS1-XS50) to zero. One "
                               "CLEARX line can replace all X and XS lines of a .VAR file to speed up the "
                               "upload.",
                .manualLines = "L9308"},
    CommandInfo{.name = "RAND", .longName = "RANDOM", .syntax = "RAND <seed> | RAND X<n> <expr1> <expr2>",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 3, .version3 = true,
                .description = "Random number generator. RAND seed (0-31,000) starts the sequence; RAND Xn "
                               "e1 e2 stores a random number between the bounds e1 and e2 (|e1-e2| <= "
                               "31,000) in user register Xn (n 1-250, even with EXTDX on).",
                .manualLines = "L9310"},
    CommandInfo{.name = "TRECORD", .longName = "TRACE RECORD", .syntax = "TRECORD START|STOP|CONTINUE",
                .modes = kTerminalAndProgram, .minEntries = 1, .maxEntries = 1, .version3 = true,
                .description = "Real time trace record command; can be buried in the user program to "
                               "control real time tracing. Not available while EXTDX is on (ERR 63).",
                .manualLines = "L9317"},
    CommandInfo{.name = "TPLAY", .longName = "TRACE PLAYBACK",
                .syntax = "TPLAY | TPLAY NEWEST <n> | TPLAY OLDEST <n> | TPLAY <n> | TPLAY <line1> <line2>",
                .modes = kInteractive, .minEntries = 0, .maxEntries = 2, .version3 = true,
                .description = "Real time trace playback: dumps the whole trace buffer, the newest or "
                               "oldest n lines, n lines, or lines line1 to line2, as #<line> LINE <pgm "
                               "line> <prompt> <command> (prompt ta. tB. tC. tV. t.. t*. tI. tM. names the "
                               "active task). Not available while EXTDX is on (ERR 63).",
                .manualLines = "L9318-9319"},

    // ---- Resident editor (e-> prompt) ----
    CommandInfo{.name = "P", .longName = "EDITOR PRINT", .syntax = "P [line] | P <line1> <line2> | P BEG END",
                .modes = kEditor, .minEntries = 0, .maxEntries = 2,
                .description = "Print a program line (or range; BEG and END name the first and last lines) "
                               "and go to it; without a line, print the current line. A line not in the "
                               "program gives BAD ENTRY. An empty line goes down one line and prints it.",
                .manualLines = "L3484-3514"},
    CommandInfo{.name = "PASS", .longName = "PASSWORD", .syntax = "PASS", .modes = kEditor, .minEntries = 0,
                .maxEntries = 0,
                .description = "Asks for the new editor password; an empty line removes it. With a password "
                               "the program cannot be changed (nor loaded with >BDS without it) but can be "
                               "displayed.",
                .manualLines = "L3516-3526"},
    CommandInfo{.name = "I", .longName = "INSERT", .syntax = "I [line]", .modes = kEditor, .minEntries = 0,
                .maxEntries = 1,
                .description = "Enter the insert mode (prompt i->): everything typed goes into program "
                               "memory, before the current line or as the new line n. Escape exits.",
                .manualLines = "L3528-3570"},
    CommandInfo{.name = "F", .longName = "FIND", .syntax = "F", .modes = kEditor, .minEntries = 0,
                .maxEntries = 0,
                .description = "Search down through program memory for a string: FIND WHAT? (prompt f->); "
                               "an empty line reuses the last string. NOT FOUND if absent.",
                .manualLines = "L3572-3614"},
    CommandInfo{.name = "C", .longName = "CHANGE", .syntax = "C", .modes = kEditor, .minEntries = 0,
                .maxEntries = 0,
                .description = "Change a string in the current line only: CHANGE WHAT? then CHANGE TO WHAT? "
                               "(prompt c->); both default to the previous strings.",
                .manualLines = "L3616-3664"},
    CommandInfo{.name = "DEL", .longName = "DELETE", .syntax = "DEL [line1 [line2]]", .modes = kEditor,
                .minEntries = 0, .maxEntries = 2,
                .description = "Delete the current line, one line, or the range of lines line1 to line2.",
                .manualLines = "L3666-3692"},
    CommandInfo{.name = "SIZE", .longName = "SIZE", .syntax = "SIZE", .modes = kEditor, .minEntries = 0,
                .maxEntries = 0,
                .description = "Show the remaining program memory (about 16000 characters in all), e.g. 65 "
                               "% LEFT.",
                .manualLines = "L3694-3708"},
    CommandInfo{.name = "NEW", .longName = "NEW", .syntax = "NEW", .modes = kEditor, .minEntries = 0,
                .maxEntries = 0,
                .description = "Clear the user program and the editor password; also resets a corrupt "
                               "program (ERR 202).",
                .manualLines = "L3710-3720"},
};
// clang-format on

} // namespace

std::span<const CommandInfo> commands() {
    return kCommands;
}

} // namespace drive_core::catalog::bds5
