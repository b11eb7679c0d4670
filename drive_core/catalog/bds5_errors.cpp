// BDS5 error codes: all 100 codes of App. D (L7136-7540); 103-111, whose numbers and titles were lost there,
// come from the second copy of the appendix (L10229-10676). Messages are the drive's own upper-case texts.
#include "bds5_catalog.h"

#include <array>

namespace drive_core::catalog::bds5 {
namespace {

constexpr std::string_view kContactFactory = "Contact the factory.";
constexpr std::string_view kInternal = "This is an internal error. It breaks program execution and disables the BDS5.";

// One entry per error, packed by hand: clang-format would put every field on its own line.
// clang-format off
constexpr std::array kErrors{
    // D.2.1 Firmware faults: not printed; the CPU LED blinks the error number, then pauses.
    // chosen: "HARDWARE- U-P FAIL" as both copies spell it (probably "HARDWARE-uP FAIL"; never printed).
    ErrorInfo{.code = 2, .message = "HARDWARE- U-P FAIL", .severity = Severity::Firmware,
              .meaning = "The microprocessor cannot pass self-test. The CPU light blinks twice and then "
                         "pauses. The BDS5 will not communicate or run the user program.",
              .remedy = kContactFactory, .manualLines = "L7159-7165"},
    ErrorInfo{.code = 3, .message = "HARDWARE-CHECKSUM", .severity = Severity::Firmware,
              .meaning = "The microprocessor cannot pass the checksum self-test. The CPU light blinks three "
                         "times and then pauses. The BDS5 will not communicate or run the user program.",
              .remedy = kContactFactory, .manualLines = "L7167-7173"},
    ErrorInfo{.code = 4, .message = "SOFTWARE WATCHDOG", .severity = Severity::Firmware,
              .meaning = "The microprocessor has failed the software watchdog self-test. The CPU light "
                         "blinks four times and then pauses. The BDS5 will not communicate or run the user "
                         "program.",
              .remedy = kContactFactory, .manualLines = "L7175-7177"},
    ErrorInfo{.code = 5, .message = "+5 VOLTS", .severity = Severity::Firmware,
              .meaning = "The +5 volts is too low. The CPU light blinks five times and then pauses. The "
                         "BDS5 will not communicate or run the user program.",
              .remedy = "Check the +10 VDC input into the BDS5 (Connector C4, pin 4 or 8); below 6.5 V for "
                        "even a short time causes this error. It happens when the logic supply is loaded "
                        "too heavily, or when the line voltage (PSR4/5 Connector C1, pins 2 and 3) is below "
                        "98 VAC.",
              .manualLines = "L7179-7181"},

    // D.2.2 BDS5 faults.
    ErrorInfo{.code = 10, .message = "REMOTE OFF", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that requires the hardware input REMOTE "
                         "on the signal connector to be active. This error breaks program execution.",
              .remedy = "Turn the REMOTE input on.", .manualLines = "L7183-7185"},
    ErrorInfo{.code = 11, .message = "OVER-TEMP", .severity = Severity::Disable,
              .meaning = "The thermostat on the BDS5 heatsink opened, indicating overheating (excessive "
                         "ambient temperature, obstructed airflow, broken fan, etc.). This error breaks "
                         "program execution and disables the BDS5.",
              .remedy = "Correct any such condition before resuming operation. REMOVE ALL POWER BEFORE "
                        "CHECKING THIS. If everything is functioning properly, a drive with a higher "
                        "current rating may be required.",
              .manualLines = "L7187-7189"},
    ErrorInfo{.code = 12, .message = "OVER-CURRENT", .severity = Severity::Disable,
              .meaning = "The BDS5 detected an overcurrent: a shorted motor winding, a shorted power "
                         "transistor or a short circuit in the wiring. This error breaks program execution "
                         "and disables the BDS5.",
              .remedy = "Check all wiring before resuming operation.", .manualLines = "L7191-7193"},
    ErrorInfo{.code = 13, .message = "OVER-SPEED", .severity = Severity::Disable,
              .meaning = "The speed of the motor was greater than the variable VOSPD. This error breaks "
                         "program execution and disables the BDS5.",
              .remedy = "If this occurs occasionally it may be a nuisance fault: raise VOSPD by 5% or 10% "
                        "(at most 120% of VMAX). Otherwise check the tuning (overshoot, ringing) and the "
                        "resolver.",
              .manualLines = "L7195-7196, L6013"},
    ErrorInfo{.code = 14, .message = "POWER BUS", .severity = Severity::Disable,
              .meaning = "The power supply high voltage bus has either an overvoltage fault or an "
                         "undervoltage fault. This error breaks program execution and disables the BDS5.",
              .remedy = "", .manualLines = "L7197-7198"},
    ErrorInfo{.code = 15, .message = "COMP BOARD", .severity = Severity::Disable,
              .meaning = "You attempted to enable the BDS5 with the compensation board removed. This error "
                         "breaks program execution.",
              .remedy = "Replace the compensation board.", .manualLines = "L7199-7200"},
    ErrorInfo{.code = 17, .message = "FEEDBACK LOSS", .severity = Severity::Disable,
              .meaning = "One or more wires to the resolver have been broken, or the resolver connector has "
                         "been removed. This error breaks program execution.",
              .remedy = "Check the resolver wiring and connector.", .manualLines = "L7201-7202"},
    ErrorInfo{.code = 18, .message = "BAD TL", .severity = Severity::Disable,
              .meaning = "The small MC board and the larger IBD board both encode the current and voltage "
                         "rating and they must match. This error breaks program execution.",
              .remedy = "If you exchanged the MC card, replace the original card. Otherwise contact the "
                        "factory.",
              .manualLines = "L7203-7204"},
    ErrorInfo{.code = 19, .message = "MOTION (HDWR LINE)", .severity = Severity::Break,
              .meaning = "The MOTION input was off at the beginning of a motion instruction, or it turned "
                         "off during a motion instruction. This signal comes from the optional I/O card. "
                         "This error breaks program execution.",
              .remedy = "Turn the MOTION input on before commanding motion.", .manualLines = "L7205-7206"},
    ErrorInfo{.code = 20, .message = "TUNE FAILED", .severity = Severity::Disable,
              .meaning = "The TUNE command failed. Either the inertia on the motor is too large for the "
                         "desired bandwidth, the motor is not functioning properly, the bus voltage is too "
                         "low, or the BDS5 is not functioning properly.",
              .remedy = "Try reducing the desired bandwidth. Make sure REMOTE is on. If this does not work, "
                        "tune the system by hand.",
              .manualLines = "L7207-7208"},
    // chosen: "+/-12 VOLTS"; the manual prints a plus-minus sign, which the 7-bit serial port cannot send.
    ErrorInfo{.code = 22, .message = "+/-12 VOLTS", .severity = Severity::Disable,
              .meaning = "The +/-12 volts is out of tolerance. This error breaks program execution.",
              .remedy = kContactFactory, .manualLines = "L7210-7212"},

    // D.2.3 Positioner faults.
    ErrorInfo{.code = 23, .message = "SOFTWARE OVERTRAVEL", .severity = Severity::Break,
              .meaning = "Software travel limits are enabled and either PMAX or PMIN, the software limits, "
                         "have been exceeded. This error breaks program execution (while camming it also "
                         "disables).",
              .remedy = "If your application does not need software travel limits, or to disable them "
                        "temporarily, type PLIM OFF.",
              .manualLines = "L7214-7220, L9472"},
    ErrorInfo{.code = 24, .message = "HARDWARE OVERTRAVEL", .severity = Severity::Disable,
              .meaning = "The BDS5 detected an overtravel condition while it was enabled: LIMIT is 0. LIMIT "
                         "should be connected to normally closed limit switch contacts that open at "
                         "overtravel. Hardware overtravel limits cannot be disabled. This error breaks "
                         "program execution and disables the BDS5.",
              .remedy = "Print the state of the overtravel limit switch with P LIMIT; move the load back "
                        "off the limit switch by hand.",
              .manualLines = "L7222-7228, L2245-2249"},
    ErrorInfo{.code = 25, .message = "PE OVERFLOW", .severity = Severity::Disable,
              .meaning = "The variable PE, the position error, exceeded the variable PEMAX (following error "
                         "overflow). This error breaks program execution and disables the BDS5.",
              .remedy = "Raise PEMAX by about 20%; check whether ICMD saturates at ILIM (record ICMD), the "
                        "load is too big, ILIM is too low, ACC/DEC are too high or the AC line is too low "
                        "for the speed.",
              .manualLines = "L7230-7232, L6003-6011"},
    ErrorInfo{.code = 26, .message = "PFB ROLLOVER", .severity = Severity::Disable,
              .meaning = "The variable PFB, the position feedback, exceeded +/-2,147,483,647 counts (or its "
                         "position-unit equivalent). This can occur if the motor rotates indefinitely in "
                         "one direction.",
              .remedy = "If your application requires this, consider using the rotary mode.",
              .manualLines = "L7234-7236"},
    ErrorInfo{.code = 27, .message = "R/D JUMPERS", .severity = Severity::Disable,
              .meaning = "Either the jumpers on the BDS5 MC2 card are incorrectly set or the wrong TL has "
                         "been loaded.",
              .remedy = kContactFactory, .manualLines = "L7238-7240"},

    // D.3.1 Position calculation errors.
    ErrorInfo{.code = 30, .message = "TOO MANY MOVES", .severity = Severity::Break,
              .meaning = "You typed too many move commands (MA, MI, MCGO) from the interactive mode: one "
                         "move can execute and one be pending. It does not occur from the user program, "
                         "which waits for the motion buffer. This error breaks program execution.",
              .remedy = "Wait for the executing move to finish before typing the next one.",
              .manualLines = "L7242-7244"},
    ErrorInfo{.code = 31, .message = "TOO MANY MRD MOVES", .severity = Severity::Break,
              .meaning = "You attempted to execute a motion instruction that required the profile buffer to "
                         "be empty, as when two MRD instructions are active at once. This error breaks "
                         "program execution.",
              .remedy = "Use a synchronizer (W, TIL) to delay the instruction that caused the error.",
              .manualLines = "L7246-7248"},
    ErrorInfo{.code = 32, .message = "ACC/DEC TOO LOW", .severity = Severity::Break,
              .meaning = "A motion command calculated a profile whose acceleration or deceleration segment "
                         "was more than 30 seconds long. This error breaks program execution.",
              .remedy = "Increase ACC or DEC or reduce the speed change of the move.",
              .manualLines = "L7250-7252"},
    ErrorInfo{.code = 33, .message = "VEL OUT OF BOUNDS", .severity = Severity::Break,
              .meaning = "The commanded velocity of a motion command was out of range: +/-VMAX for jog (J), "
                         "0 to +VMAX for other motion commands. This error breaks program execution.",
              .remedy = "Command a velocity within the range.", .manualLines = "L7254-7256"},

    // D.3.2 Macro move / JT / JF errors.
    ErrorInfo{.code = 40, .message = "CHANGED DIRECTION", .severity = Severity::Break,
              .meaning = "You attempted to change direction with an instruction that does not allow it (JT, "
                         "JF and macro moves). This error breaks program execution.",
              .remedy = "", .manualLines = "L7260-7261"},
    ErrorInfo{.code = 41, .message = "MOVE NEEDS MOTION", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that requires the motor to be in motion: "
                         "JT, JF and MCI/MCA with no velocity parameter. This error breaks program "
                         "execution.",
              .remedy = "", .manualLines = "L7262-7263"},
    ErrorInfo{.code = 42, .message = "MOVE w/o TIME", .severity = Severity::Break,
              .meaning = "You attempted a move that required more time than was available, e.g. a JT or "
                         "macro segment whose final position cannot be reached because of acceleration "
                         "limits, or a JT or JF when already well beyond the specified position. This error "
                         "breaks program execution.",
              .remedy = "", .manualLines = "L7264-7265, L2750"},
    ErrorInfo{.code = 43, .message = "MACRO NOT READY", .severity = Severity::Break,
              .meaning = "MCGO was executed when the last macro-move segment did not end at zero speed, or "
                         "the macro-move memory is empty (it is cleared every time the BDS5 is turned on). "
                         "This error breaks program execution.",
              .remedy = "End the last section at zero speed, or define the macro move again.",
              .manualLines = "L7266-7267"},
    ErrorInfo{.code = 44, .message = "MCD w/MACRO MOVING", .severity = Severity::Break,
              .meaning = "You attempted to insert a macro-move dwell when the previous macro-move segment "
                         "ended at a speed other than zero. This error breaks program execution.",
              .remedy = "", .manualLines = "L7268-7269"},
    // The texts of 45 and 46 read as if swapped (digest §12.2 item 11); kept as printed.
    ErrorInfo{.code = 45, .message = "MCA ACTIVE", .severity = Severity::Break,
              .meaning = "You attempted to insert an MCA segment after an MCI segment. This error breaks "
                         "program execution.",
              .remedy = "Do not mix MCA and MCI sections in one macro move.", .manualLines = "L7270-7271"},
    ErrorInfo{.code = 46, .message = "MCI ACTIVE", .severity = Severity::Break,
              .meaning = "You attempted to insert an MCI segment after an MCA segment in a macro move. This "
                         "error breaks program execution.",
              .remedy = "Do not mix MCA and MCI sections in one macro move.", .manualLines = "L7272-7273"},
    ErrorInfo{.code = 47, .message = "MCI/MCA TOO COMPLEX", .severity = Severity::Break,
              .meaning = "You attempted to execute a macro move that required too many segments (more than "
                         "30). This error breaks program execution.",
              .remedy = "", .manualLines = "L7275-7277"},
    ErrorInfo{.code = 48, .message = "MCA/MCI RUNNING", .severity = Severity::Break,
              .meaning = "You attempted to build a macro move while another macro move was running. This "
                         "error breaks program execution.",
              .remedy = "", .manualLines = "L7279-7281"},

    // D.4.1 Programming modes or motion modes.
    ErrorInfo{.code = 50, .message = "DRIVE INHIBITED", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that required the BDS5 to be enabled "
                         "while it was inhibited (Chapter 5 shows the text as BDS5 INHIBITED). This error "
                         "will break program execution if the instruction is issued from the user program.",
              .remedy = "Enable the drive with EN.", .manualLines = "L7283-7285, L6046-6050"},
    ErrorInfo{.code = 51, .message = "DRIVE ENABLED", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that required the BDS5 to be inhibited "
                         "while it was enabled. This error will break program execution if the instruction "
                         "is issued from the user program.",
              .remedy = "Disable the drive with DIS first.", .manualLines = "L7287-7289"},
    ErrorInfo{.code = 52, .message = "NOT FROM TERMINAL", .severity = Severity::Warning,
              .meaning = "You attempted to execute an instruction from the terminal that is not allowed "
                         "from the terminal. This error generates no action.",
              .remedy = "", .manualLines = "L7291-7293"},
    // The manual gives severity 1 yet says this error breaks program execution.
    ErrorInfo{.code = 53, .message = "NOT FROM PROGRAM", .severity = Severity::Warning,
              .meaning = "You attempted to execute an instruction from the program that is not allowed from "
                         "the program. This error breaks program execution.",
              .remedy = "", .manualLines = "L7295-7297"},
    ErrorInfo{.code = 54, .message = "NOT FROM MONITOR", .severity = Severity::Warning,
              .meaning = "You attempted to execute an instruction while in the monitor mode that is not "
                         "allowed from the monitor mode. This error generates no action.",
              .remedy = "", .manualLines = "L7299-7300"},
    ErrorInfo{.code = 55, .message = "NOT FROM RECOVERY", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction from the error recovery (the user's error "
                         "handler ERROR$) that is not allowed: enabling the BDS5, GOSUB and GOTO. This "
                         "error breaks execution.",
              .remedy = "", .manualLines = "L7301-7302"},
    ErrorInfo{.code = 56, .message = "NOT w/GEAR", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that is not allowed with the gear mode "
                         "enabled, for example MRD, MA, JT and JF. This error breaks execution if the "
                         "instruction was issued from the program.",
              .remedy = "Turn GEAR off first.", .manualLines = "L7303-7304"},
    ErrorInfo{.code = 57, .message = "NOT w/PROFILE", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that is not allowed while the BDS5 is "
                         "profiling: move instructions (MA, MI, MRD) or macro moves executing, the traverse "
                         "segment before the accel/decel of JT and JF, and the accel/decel of all jogs. "
                         "This error breaks execution.",
              .remedy = "", .manualLines = "L7305-7306"},
    ErrorInfo{.code = 58, .message = "NOT w/JOGGING", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that is not allowed when the BDS5 is "
                         "jogging. This error breaks execution if the instruction was issued from the "
                         "program.",
              .remedy = "", .manualLines = "L7307-7308"},
    ErrorInfo{.code = 59, .message = "NOT w/ROTARY", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction that is not allowed when the BDS5 is in "
                         "the rotary mode. This error breaks execution if the instruction was issued from "
                         "the program.",
              .remedy = "Type ROTARY OFF to turn the rotary mode off.", .manualLines = "L7309-7312"},
    ErrorInfo{.code = 60, .message = "OUTSIDE PROTARY", .severity = Severity::Break,
              .meaning = "You attempted an absolute move (MA or MCA) beyond PROTARY, e.g. MA 2000 with "
                         "PROTARY 1000. This error breaks execution if the instruction was issued from the "
                         "program.",
              .remedy = "Use incremental moves (MI and MCI) to move beyond the rotary limit.",
              .manualLines = "L7314-7320"},
    ErrorInfo{.code = 61, .message = "NORMALIZE FIRST", .severity = Severity::Break,
              .meaning = "You attempted to turn on the rotary mode when PFB was less than zero or greater "
                         "than PROTARY. This error breaks execution if the instruction was issued from the "
                         "program.",
              .remedy = "Use the NORM command to normalize the position to between 0 and PROTARY.",
              .manualLines = "L7322-7324"},
    ErrorInfo{.code = 62, .message = "RD ALREADY IN USE", .severity = Severity::Break,
              .meaning = "You attempted to execute RD while RD was in use from another task (two task "
                         "levels used RD at the same time). This error breaks program execution.",
              .remedy = "", .manualLines = "L7326-7328"},
    ErrorInfo{.code = 63, .message = "NOT AT THIS LEVEL", .severity = Severity::Break,
              .meaning = "You attempted to execute a command that is not allowed at the present task level, "
                         "e.g. GOSUB and GOTO from within an alarm (the serial transcripts also show it for "
                         "J and RUN typed in monitor mode). This error breaks program execution.",
              .remedy = "", .manualLines = "L7330-7332, L9805"},
    ErrorInfo{.code = 64, .message = "BACKWARD REGULATION", .severity = Severity::Disable,
              .meaning = "The external input counted backwards more than 30,000 counts when REG was on. "
                         "This error breaks program execution and disables the BDS5.",
              .remedy = "", .manualLines = "L7334-7336"},
    ErrorInfo{.code = 65, .message = "RECORD NOT READY", .severity = Severity::Disable,
              .meaning = "You entered a PLAY command when nothing had been recorded since the last time the "
                         "BDS5 powered up.",
              .remedy = "Use RECORD before PLAY.", .manualLines = "L7338-7340"},

    // D.4.2 Improper use of labels.
    ErrorInfo{.code = 70, .message = "LABEL NOT FOUND", .severity = Severity::Break,
              .meaning = "You attempted to branch to a label (from RUN, GOSUB or GOTO) that does not exist. "
                         "This error breaks program execution.",
              .remedy = "", .manualLines = "L7344-7346"},
    ErrorInfo{.code = 71, .message = "LABEL USED TWICE", .severity = Severity::Break,
              .meaning = "The user program has a label that is used more than once. This error breaks "
                         "program execution.",
              .remedy = "", .manualLines = "L7348-7350"},
    ErrorInfo{.code = 74, .message = "ERROR$ MUST BE LAST", .severity = Severity::Break,
              .meaning = "The user's error handler (ERROR$) must be the last label in the program buffer: "
                         "no labels after ERROR$, and no GOTO or GOSUB while the error handler executes. "
                         "The handler provides a graceful exit and cannot restart the program. This error "
                         "breaks program execution.",
              .remedy = "Use IF, TIL and ? to execute conditional commands in the error handler.",
              .manualLines = "L7352-7354"},

    // D.4.3 Invalid instructions or entries.
    ErrorInfo{.code = 79, .message = "BAD FORMAT", .severity = Severity::Break,
              .meaning = "You entered a format that the BDS5 does not recognize, e.g. INPUT \"INPUT X1\" "
                         "X1[.3] (the decimal point after the \"[\" is incorrect). This error breaks "
                         "program execution if the instruction is issued from the user program.",
              .remedy = "Pay careful attention to the rules for formats in Chapter 4.",
              .manualLines = "L7358-7366"},
    ErrorInfo{.code = 80, .message = "INVALID INSTRUCTION", .severity = Severity::Break,
              .meaning = "You attempted to execute an instruction or change a variable that the BDS5 does "
                         "not recognize. This error breaks program execution if the instruction is issued "
                         "from the user program.",
              .remedy = "", .manualLines = "L7368-7370"},
    ErrorInfo{.code = 81, .message = "NOT PROGRAMMABLE", .severity = Severity::Break,
              .meaning = "You attempted to change a variable that is not programmable. This error will "
                         "break program execution if the instruction is issued from the user program.",
              .remedy = "", .manualLines = "L7372-7374"},
    ErrorInfo{.code = 82, .message = "BAD NUMBER ENTRIES", .severity = Severity::Break,
              .meaning = "The instruction that is executing has too many or too few parameters. This error "
                         "breaks program execution if the instruction is issued from the user program.",
              .remedy = "Look up the instruction to determine the correct number of entries.",
              .manualLines = "L7376-7378"},
    ErrorInfo{.code = 83, .message = "BAD OR OUT OF RANGE", .severity = Severity::Break,
              .meaning = "You entered a parameter to an instruction that was too large or too small, or in "
                         "the wrong format, such as a character string where a number is expected. This "
                         "error breaks program execution if the instruction is issued from the user program.",
              .remedy = "Check the variable limits (Appendix E).", .manualLines = "L7380-7382"},
    ErrorInfo{.code = 84, .message = "OUT OF BOUNDS", .severity = Severity::Break,
              .meaning = "The variable listed is out of bounds. This error breaks execution.",
              .remedy = "If the variable is protected (set by the factory), contact the factory. Otherwise "
                        "set it within its bounds.",
              .manualLines = "L7384-7386"},
    ErrorInfo{.code = 85, .message = "BAD INDIRECTION", .severity = Severity::Break,
              .meaning = "You attempted an indirect reference to a user variable that does not exist, e.g. "
                         "X1 10000 then P X(X1) refers to X10000. This error breaks program execution if "
                         "the instruction is issued from the user program.",
              .remedy = "", .manualLines = "L7388-7394"},
    ErrorInfo{.code = 86, .message = "USER PROGRAM FULL", .severity = Severity::Break,
              .meaning = "You attempted to load a program larger than the BDS5 can hold, with >BDS or "
                         "Motion Link's Program Transmit (^T). This error breaks program execution.",
              .remedy = "", .manualLines = "L7396-7398"},
    ErrorInfo{.code = 87, .message = "EMBEDDED QUOTE", .severity = Severity::Break,
              .meaning = "You entered a command with an embedded quote, e.g. P\"BAD COMMAND\". A space must "
                         "precede an opening quote and follow a closing quote. This error breaks program "
                         "execution if the instruction is issued from the user program.",
              .remedy = "", .manualLines = "L7400-7408"},
    ErrorInfo{.code = 88, .message = "NO CLOSING QUOTE", .severity = Severity::Break,
              .meaning = "You entered a command with an odd number of quotes. This error breaks program "
                         "execution if the instruction is issued from the user program.",
              .remedy = "", .manualLines = "L7410-7412"},
    ErrorInfo{.code = 89, .message = "NOT FOR ALARM/HOLD/RECORD", .severity = Severity::Break,
              .meaning = "You specified a switch that is not allowed for an alarm, a hold or a record "
                         "command, e.g. A$ REMOTE ON (REMOTE is not allowed to fire an alarm).",
              .remedy = "", .manualLines = "L7414-7423"},
    ErrorInfo{.code = 90, .message = "TOO MANY POINTS", .severity = Severity::Break,
              .meaning = "You specified too many points in a RECORD command. Only 1000 points total can be "
                         "recorded: four variables no more than 250 times.",
              .remedy = "", .manualLines = "L7425-7427"},

    // D.4.4 Math errors.
    ErrorInfo{.code = 92, .message = "ZERO DIVIDE", .severity = Severity::Break,
              .meaning = "You attempted to divide a number by 0. This error breaks program execution if the "
                         "instruction is issued from the user program.",
              .remedy = "", .manualLines = "L7429-7431"},
    ErrorInfo{.code = 93, .message = "MATH OVERFLOW", .severity = Severity::Break,
              .meaning = "The final result of a calculation or an intermediate result was greater than 2^31 "
                         "or less than -2^31. This error breaks program execution.",
              .remedy = "", .manualLines = "L7433-7435"},
    ErrorInfo{.code = 94, .message = ">2 PARENTHESES", .severity = Severity::Break,
              .meaning = "The BDS5 evaluated an expression with more levels of parentheses than it "
                         "supports; up to two levels are allowed. This error breaks program execution.",
              .remedy = "", .manualLines = "L7437-7439"},
    ErrorInfo{.code = 95, .message = "UNEVEN PARENTHESES", .severity = Severity::Break,
              .meaning = "The number of closing parentheses in an expression was not equal to the number of "
                         "opening parentheses. This error breaks program execution.",
              .remedy = "", .manualLines = "L7441-7443"},
    ErrorInfo{.code = 96, .message = "SCALING OVERFLOW", .severity = Severity::Break,
              .meaning = "During a conversion to or from user units, the result was greater than 2^31 or "
                         "less than -2^31. This error breaks program execution if the instruction is issued "
                         "from the user program.",
              .remedy = "", .manualLines = "L7445-7447"},
    ErrorInfo{.code = 97, .message = "GEAR OVERFLOW", .severity = Severity::Disable,
              .meaning = "Overflow when calculating the velocity from the external pulse input: GEARI too "
                         "small or GEARO too large, so the input times the gear ratio exceeded the highest "
                         "allowable input frequency, 2 MHz. This error breaks program execution and "
                         "disables the BDS5.",
              .remedy = "", .manualLines = "L7449-7451"},

    // D.4.5 Communication errors (numbers lost at L7453-7461; taken from the second copy).
    ErrorInfo{.code = 103, .message = "BAUD RATE", .severity = Severity::HistoryOnly,
              .meaning = "The variable BAUD contains a value that is not supported by the BDS5. This error "
                         "occurs during the autobaud sequence and so is never printed; it is only seen in "
                         "the error history buffer. This error has no action (manual severity 1).",
              .remedy = "", .manualLines = "L10609-10611, L7453"},
    ErrorInfo{.code = 104, .message = "ABAUD & MULTIDROP", .severity = Severity::HistoryOnly,
              .meaning = "Autobaud was attempted while in multidrop communications: ABAUD is on and ADDR is "
                         "not zero. This error occurs during the autobaud sequence and so is never printed; "
                         "it is only seen in the error history buffer. This error has no action (manual "
                         "severity 1).",
              .remedy = "Turn ABAUD off, or set ADDR to 0.", .manualLines = "L10613-10615, L7457"},
    ErrorInfo{.code = 105, .message = "SERIAL WDOG", .severity = Severity::Disable,
              .meaning = "The serial port did not receive a valid command for WTIME milliseconds while the "
                         "serial watchdog was enabled (WATCH = 1). This error breaks program execution and "
                         "disables the BDS5.",
              .remedy = "", .manualLines = "L10617-10619, L7461"},
    // D.4.6 Password errors.
    ErrorInfo{.code = 110, .message = "EDIT PASSWORD", .severity = Severity::Warning,
              .meaning = "You attempted to execute an instruction that requires the editor password; this "
                         "occurs with the >BDS command.",
              .remedy = "Follow the command with the password: >BDS <password>.",
              .manualLines = "L10621-10623, L7471"},
    ErrorInfo{.code = 111, .message = "FACTORY SETTABLE", .severity = Severity::Break,
              .meaning = "You attempted to change a variable that is protected; these variables are set at "
                         "the factory. This error breaks program execution if the instruction is issued "
                         "from the user program.",
              .remedy = "", .manualLines = "L10625-10627, L7475"},

    // D.4.7 Errors from IF, TIL and GOSUB commands.
    ErrorInfo{.code = 115, .message = "IF w/o ENDIF", .severity = Severity::Break,
              .meaning = "The program executed an IF command to begin an IF block, but could not find the "
                         "corresponding ENDIF. This error breaks program execution.",
              .remedy = "", .manualLines = "L7481-7483"},
    ErrorInfo{.code = 116, .message = "IF NOT STARTED", .severity = Severity::Break,
              .meaning = "An ELSE, ELIF or ENDIF was encountered when there was no IF, e.g. after a GOTO to "
                         "the middle of an IF/ELIF/ELSE/ENDIF block. This error breaks program execution.",
              .remedy = "", .manualLines = "L7485-7487"},
    ErrorInfo{.code = 117, .message = "TIL FOLLOWS ?/TIL", .severity = Severity::Break,
              .meaning = "The ? or TIL instruction was used to execute a conditional TIL. This error breaks "
                         "program execution.",
              .remedy = "", .manualLines = "L7489-7491"},
    ErrorInfo{.code = 118, .message = "TOO MANY GOSUBS", .severity = Severity::Break,
              .meaning = "The last GOSUB was one GOSUB too many; the BDS5 has 4 levels of subroutines. This "
                         "error breaks program execution.",
              .remedy = "", .manualLines = "L7493-7495"},
    ErrorInfo{.code = 119, .message = "RETURN w/o GOSUB", .severity = Severity::Break,
              .meaning = "The BDS5 encountered a RET when it was not expecting one: more returns than "
                         "GOSUBs. This error breaks program execution.",
              .remedy = "", .manualLines = "L7497-7499"},

    // D.4.8 Power-up marker (not an error).
    ErrorInfo{.code = 199, .message = "DRIVE POWERED UP", .severity = Severity::HistoryOnly,
              .meaning = "This is not a true error. ERROR 199 marks the error history buffer when the BDS5 "
                         "powers up.",
              .remedy = "", .manualLines = "L7503-7505, L6118"},

    // D.4.9 Internal errors.
    ErrorInfo{.code = 200, .message = "FOLDBACK OUT", .severity = Severity::Disable,
              .meaning = "The factory set variables that control foldback are out of bounds. This error "
                         "breaks program execution and disables the BDS5.",
              .remedy = kContactFactory, .manualLines = "L7509-7510"},
    ErrorInfo{.code = 201, .message = "SLIP TOO BIG", .severity = Severity::Disable,
              .meaning = "The induction motor variables that control slip are out of bounds. This error "
                         "breaks program execution and disables the BDS5.",
              .remedy = kContactFactory, .manualLines = "L7511-7512"},
    ErrorInfo{.code = 202, .message = "USER PROGRAM CORRUPT", .severity = Severity::Disable,
              .meaning = "The user program is corrupt, usually after installing a new battery back-up RAM, "
                         "or when power to the BDS5 was lost while editing the program. This error will "
                         "break program execution.",
              .remedy = "Reset the user program with the editor NEW command (or load it again with >BDS); "
                        "you will need to reload your program.",
              .manualLines = "L7513-7514, L3712-3720"},
    ErrorInfo{.code = 203, .message = "AMPS BAD", .severity = Severity::Disable,
              .meaning = "The BDS5 variable AMPS is invalid. This error breaks program execution.",
              .remedy = kContactFactory, .manualLines = "L7515-7516"},
    ErrorInfo{.code = 204, .message = "PROGRAM OVERRUN", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7517-7518"},
    // The second copy spells it "MBUF OVRUN" (L10653); App. D's spelling is kept.
    ErrorInfo{.code = 205, .message = "MBUF OVRRUN", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7519-7520"},
    ErrorInfo{.code = 206, .message = "PROFILE OVERFLOW", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7521-7522"},
    ErrorInfo{.code = 208, .message = "GENERAL INTERNAL", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = "Carefully write down the entire line that is printed with the error and contact "
                        "the factory.",
              .manualLines = "L7524-7526"},
    ErrorInfo{.code = 209, .message = "STACK OVERFLOW", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = "Carefully write down the entire line that is printed with the error and contact "
                        "the factory.",
              .manualLines = "L7528-7530"},
    // App. D lists 211-219 as one entry "INTERNAL 1-9"; each code prints its own digit.
    ErrorInfo{.code = 211, .message = "INTERNAL 1", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 212, .message = "INTERNAL 2", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 213, .message = "INTERNAL 3", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 214, .message = "INTERNAL 4", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 215, .message = "INTERNAL 5", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 216, .message = "INTERNAL 6", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 217, .message = "INTERNAL 7", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 218, .message = "INTERNAL 8", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 219, .message = "INTERNAL 9", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = kContactFactory, .manualLines = "L7532-7535"},
    ErrorInfo{.code = 255, .message = "UNKNOWN", .severity = Severity::Disable, .meaning = kInternal,
              .remedy = "If this error exists in the error history upon initial power-up, clear it with ERR "
                        "CLR. Contact the factory if it occurs during operation.",
              .manualLines = "L7537-7539"},
};
// clang-format on

} // namespace

std::span<const ErrorInfo> errors() {
    return kErrors;
}

} // namespace drive_core::catalog::bds5
