// SC750 statements, functions, interrupt sources, DACMAP selections and fault codes (digest §4–§6),
// and the case-insensitive look-ups the compiler, simulator and IDE share.
#include "sc750_catalog.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace drive_core::catalog::sc750 {

namespace {

using enum StatementKind;
using enum ValueType;

// clang-format off
const StatementInfo kStatements[] = {
    {"DIM", "DIM name[(n)][, name…] AS INTEGER|LONG|SINGLE|DOUBLE|FLOAT|STRING", Basic, "declare user variables", "L1213, L1040-L1062"},
    {"PARAMS START", "PARAMS START … PARAMS END", Structure, "non-volatile parameter section", "L945, L974, L990"},
    {"REM", "REM text  |  ' text", Basic, "comment", "L1222"},
    {"END", "END", Structure, "end of the main program", "L1215, L1005"},
    {"STOP", "STOP", Basic, "stop program execution", "L1223"},
    {"GOTO", "GOTO label", Basic, "jump to a label", "L1218, L1121-L1136"},
    {"GOSUB", "GOSUB label … RETURN", Basic, "call a label subroutine", "L1217"},
    {"RETURN", "RETURN", Basic, "return from GOSUB", "L1217"},
    {"SUB", "SUB name … END SUB", Structure, "named subroutine (no parameters, all variables global)", "L1007-L1009"},
    {"CALL", "CALL name", Basic, "call a SUB", "L1214"},
    {"IF", "IF c THEN … [ELSE IF c THEN …] [ELSE …] END IF  |  IF c THEN stmt [ELSE stmt]", Basic, "conditional", "L1219"},
    {"FOR", "FOR v = a TO b [STEP s] … NEXT [v]", Basic, "counted loop", "L1216"},
    {"WHILE", "WHILE c … WEND", Basic, "pre-tested loop", "L1236"},
    {"SWAP", "SWAP a, b", Basic, "exchange two variables", "L1235"},
    {"PRINT", "PRINT [expr {;|,} …]", Io, "print to the serial port", "L1221, L2188"},
    {"INPUT", "INPUT [\"prompt\" {;|,}] var", Io, "read a CR-terminated line", "L1220, L2189"},
    {"CLS", "CLS", Io, "scroll the terminal clear", "L2191"},
    {"BEEP", "BEEP", Io, "send a beep (BEL)", "L1212, L2192"},
    {"GO.VEL", "GO.VEL", Motion, "run at RUN.SPEED in direction DIR", "L1435"},
    {"GO.INCR", "GO.INCR", Motion, "move INDEX.DIST counts", "L1436"},
    {"GO.ABS", "GO.ABS", Motion, "move to TARGET.POS", "L1437"},
    {"GO.HOME", "GO.HOME", Motion, "move to POS.COMMAND = 0", "L1438"},
    {"ABORT.MOTION", "ABORT.MOTION", Motion, "stop commanded motion at DECEL.RATE", "L1439, L1494"},
    {"UPD.MOVE", "UPD.MOVE", Motion, "apply new rates, speed, DIR to the motion in progress", "L1477"},
    {"PAUSE", "PAUSE", Timing, "wait PAUSE.TIME seconds", "L2034-L2044"},
    {"WHEN", "WHEN condition, action", Timing, "wait for a fast condition, act, latch WHEN.*", "L1970-L2032"},
    {"CONTINUE", "WHEN …, CONTINUE", Timing, "no action (WHEN only)", "L2017"},
    {"INTERRUPT", "INTERRUPT source … END INTERRUPT", Structure, "interrupt routine", "L1895-L1928"},
    {"RESTART", "RESTART [label]", Structure, "leave an interrupt routine, restart main", "L1773-L1776, L1856"},
    {"TMRSET", "TMRSET(n, LEVEL|PULSE, delay, OUTm=v, INPk=v, [POUTj=v])", Timing, "configure software timer", "L2202-L2236"},
    {"LANINTERRUPT", "LANINTERRUPT[axis]", PacLan, "send a PacLAN interrupt", "L2382-L2388"},
};

const FunctionInfo kFunctions[] = {
    {"ABS", 1, 1, Float, "ABS(x)", "absolute value", "L1238-L1269"},
    {"ATAN", 1, 1, Float, "ATAN(x)", "arctangent, radians", "L1238-L1269"},
    {"CINT", 1, 1, Integer, "CINT(x)", "round to integer (half to even)", "L1238-L1269"},
    {"COS", 1, 1, Float, "COS(x)", "cosine, radians", "L1238-L1269"},
    {"FIX", 1, 1, Integer, "FIX(x)", "truncate toward zero", "L1238-L1269"},
    {"INT", 1, 1, Integer, "INT(x)", "largest integer <= x", "L1238-L1269"},
    {"LOG", 1, 1, Float, "LOG(x)", "natural logarithm", "L1238-L1269"},
    {"LOG10", 1, 1, Float, "LOG10(x)", "base-10 logarithm", "L1238-L1269"},
    {"SGN", 1, 1, Integer, "SGN(x)", "sign -1, 0, 1", "L1238-L1269"},
    {"SIN", 1, 1, Float, "SIN(x)", "sine, radians", "L1238-L1269"},
    {"SQR", 1, 1, Float, "SQR(x)", "square root", "L1238-L1269"},
    {"TAN", 1, 1, Float, "TAN(x)", "tangent, radians", "L1238-L1269"},
    {"ASC", 1, 1, Integer, "ASC(s$)", "code of the first character (0 for \"\")", "L1271-L1297"},
    {"CHR$", 1, 1, String, "CHR$(n)", "character of code n", "L1271-L1297"},
    {"HEX$", 1, 1, String, "HEX$(n)", "hexadecimal text", "L1271-L1297"},
    {"INKEY$", 0, 0, String, "INKEY$", "next received character, \"\" if none", "L1271-L1297, L3187"},
    {"INSTR", 2, 3, Integer, "INSTR([start,] s$, find$)", "position of find$ in s$, 0 if absent", "L1271-L1297"},
    {"LCASE$", 1, 1, String, "LCASE$(s$)", "lower case", "L1271-L1297"},
    {"LEFT$", 2, 2, String, "LEFT$(s$, n)", "leftmost n characters", "L1271-L1297"},
    {"LEN", 1, 1, Integer, "LEN(s$)", "length", "L1271-L1297"},
    {"LTRIM$", 1, 1, String, "LTRIM$(s$)", "trims leading and trailing spaces (as the manual says)", "L1282"},
    {"MID$", 2, 3, String, "MID$(s$, start[, n])", "substring from start (1-based)", "L1271-L1297"},
    {"RIGHT$", 2, 2, String, "RIGHT$(s$, n)", "rightmost n characters", "L1271-L1297"},
    {"SPACE$", 1, 1, String, "SPACE$(n)", "n spaces", "L1271-L1297"},
    {"STR$", 1, 1, String, "STR$(x)", "number to text, leading space if >= 0", "L1271-L1297"},
    {"STRING$", 2, 2, String, "STRING$(n, c)", "n copies of a character (code or string)", "L1271-L1297"},
    {"UCASE$", 1, 1, String, "UCASE$(s$)", "upper case", "L1271-L1297"},
    {"VAL", 1, 1, Float, "VAL(s$)", "numeric value of text", "L1271-L1297"},
};

const InterruptSourceInfo kInterrupts[] = {
    {"CCWINH", "CCW inhibit input (INH-) active", "L1853"},
    {"CCWOT", "POSITION CCW of the CCW over-travel limit", "L1854"},
    {"CHAR", "a character received on the serial port", "L1846"},
    {"CWINH", "CW inhibit input (INH+) active", "L1853"},
    {"CWOT", "POSITION CW of the CW over-travel limit", "L1845"},
    {"DISABLE", "the controller becomes disabled", "L1847"},
    {"FAULT", "the controller faults", "L1848"},
    {"I1HI", "INP1 = 1", "L1859"}, {"I2HI", "INP2 = 1", "L1859"}, {"I3HI", "INP3 = 1", "L1859"},
    {"I4HI", "INP4 = 1", "L1859"}, {"I5HI", "INP5 = 1", "L1859"}, {"I6HI", "INP6 = 1", "L1859"},
    {"I7HI", "INP7 = 1", "L1859"}, {"I8HI", "INP8 = 1", "L1859"}, {"I9HI", "INP9 = 1", "L1859"},
    {"I10HI", "INP10 = 1", "L1859"}, {"I11HI", "INP11 = 1", "L1859"}, {"I12HI", "INP12 = 1", "L1859"},
    {"I13HI", "INP13 = 1", "L1859"}, {"I14HI", "INP14 = 1", "L1859"}, {"I15HI", "INP15 = 1", "L1859"},
    {"I16HI", "INP16 = 1", "L1859"},
    {"I1LO", "INP1 = 0", "L1859"}, {"I2LO", "INP2 = 0", "L1859"}, {"I3LO", "INP3 = 0", "L1859"},
    {"I4LO", "INP4 = 0", "L1859"}, {"I5LO", "INP5 = 0", "L1859"}, {"I6LO", "INP6 = 0", "L1859"},
    {"I7LO", "INP7 = 0", "L1859"}, {"I8LO", "INP8 = 0", "L1859"}, {"I9LO", "INP9 = 0", "L1859"},
    {"I10LO", "INP10 = 0", "L1859"}, {"I11LO", "INP11 = 0", "L1859"}, {"I12LO", "INP12 = 0", "L1859"},
    {"I13LO", "INP13 = 0", "L1859"}, {"I14LO", "INP14 = 0", "L1859"}, {"I15LO", "INP15 = 0", "L1859"},
    {"I16LO", "INP16 = 0", "L1859"},
    {"PACLAN", "a PacLAN interrupt message received", "L2358-L2388"},
    {"POS.ERROR", "|POS.ERROR| above POS.ERROR.MOVING (moving) or POS.ERROR.STOPPED (at rest)", "L1861"},
};

const DacMapInfo kDacMap[] = {
    {0, "ANALOG.OUT", "ServoBASIC variable", 1.0, "V", "L2147-L2161"},
    {1, "VELOCITY", "resolver velocity", 1.0, "kRPM", "L2147-L2161"},
    {2, "VEL.CMD", "net velocity command", 1.0, "kRPM", "L2147-L2161"},
    {3, "VEL.ERR", "velocity error", 1.0, "kRPM", "L2147-L2161"},
    {4, "FVEL.ERR", "filtered velocity error", 1.0, "kRPM", "L2147-L2161"},
    {5, "POSITION", "resolver position", 40.0, "rev", "L2147-L2161"},
    {6, "POS.ERROR", "position error", 40.0, "rev", "L2147-L2161"},
    {7, "POS.COMMAND", "net position command", 40.0, "rev", "L2147-L2161"},
    {8, "ICMD", "torque current command", 0.5, "A", "L2147-L2161"},
    {9, "IFB", "measured torque current", 0.5, "A", "L2147-L2161"},
    {10, "FAD", "A/D after filter", 1.0, "V", "L2147-L2161"},
    {11, "ENC.FREQ", "encoder frequency", 0.1, "kHz", "L2147-L2161"},
    {12, "ENCPOS", "encoder position", 40.0, "4096 counts", "L2147-L2161"},
    {13, "IT.FILT", "I.t circuit output", 0.5, "A", "L2147-L2161"},
};

const FaultInfo kFaults[] = {
    {0, "0", "No fault, disabled", "No fault, disabled", "L1527"},
    {1, "1", "Software resolver overspeed", "Software resolver overspeed", "L1531"},
    {2, "2", "Motor overtemperature", "Motor overtemperature", "L1533"},
    {3, "3", "Servocontroller overtemperature", "Servocontroller overtemperature", "L1534"},
    {4, "4", "Servocontroller IT", "Servocontroller IT", "L1534"},
    {5, "5", "Motor line-neutral fault", "Bus overcurrent", "L1535"},
    {6, "6", "Control undervoltage", "Control undervoltage", "L1536"},
    {7, "7", "Bus OV/OC (highest priority)", "Output overcurrent", "L1537"},
    {8, "8", "No fault, enabled", "No fault, enabled", "L1538"},
    {9, "9", "Estimated shunt regulator IT fault", "Measured shunt regulator IT fault", "L1539"},
    {10, "A", "", "Bus overvoltage or hot control undervoltage", "L1540"},
    {11, "b", "Encoder +5 V low", "Encoder +5 V low", "L1541"},
    {12, "c", "Terminal +5 V low", "Terminal +5 V low", "L1541"},
    {13, "d", "", "Power stage control undervoltage", "L1542"},
    {14, "E", "Microprocessor fault", "Microprocessor fault", "L1543"},
    {241, "F 1", "Following error overflow", "Following error overflow", "L1550"},
    {242, "F 2", "Program memory fault", "Program memory fault", "L1551"},
    {243, "F 3", "Parameter memory fault", "Parameter memory fault", "L1552"},
    {244, "F 4", "Run time error", "Run time error", "L1553"},
    {245, "F 5", "PacLAN error", "PacLAN error", "L1553"},
    {246, "F 6", "Incompatible Motion Dialogue", "Incompatible Motion Dialogue", "L1554"},
};
// clang-format on

bool equalsNoCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

template <typename T, typename Key> const T* findIn(std::span<const T> items, std::string_view name, Key key) {
    for (const T& item : items)
        if (equalsNoCase(key(item), name)) return &item;
    return nullptr;
}

} // namespace

std::span<const StatementInfo> statements() {
    return kStatements;
}
std::span<const FunctionInfo> functions() {
    return kFunctions;
}
std::span<const InterruptSourceInfo> interruptSources() {
    return kInterrupts;
}
std::span<const DacMapInfo> dacMap() {
    return kDacMap;
}
std::span<const FaultInfo> faults() {
    return kFaults;
}

const VariableInfo* findVariable(std::string_view name) {
    const int i = variableIndex(name);
    return i < 0 ? nullptr : &variables()[std::size_t(i)];
}

int variableIndex(std::string_view name) {
    const auto all = variables();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (equalsNoCase(all[i].name, name)) return int(i);
    return -1;
}

const FunctionInfo* findFunction(std::string_view name) {
    return findIn(functions(), name, [](const FunctionInfo& f) { return f.name; });
}

const StatementInfo* findStatement(std::string_view name) {
    return findIn(statements(), name, [](const StatementInfo& s) { return s.name; });
}

int interruptIndex(std::string_view label) {
    const auto all = interruptSources();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (equalsNoCase(all[i].label, label)) return int(i);
    return -1;
}

const FaultInfo* findFault(int code) {
    for (const FaultInfo& f : kFaults)
        if (f.code == code) return &f;
    return nullptr;
}

} // namespace drive_core::catalog::sc750
