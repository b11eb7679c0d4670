// A compiled ServoBASIC Plus program as the drive holds it: code, data layout, PARAMS, string constants,
// interrupt vectors and the line table. The .BIN file is its serialised form (BIN_FORMAT.md).
#pragma once

#include "drive_core/catalog/sc750_catalog.h"

#include <cstdint>
#include <string>
#include <vector>

namespace drive_core::sc750 {

using catalog::sc750::ValueType;

// Every instruction is 5 bytes in the .BIN: the opcode, then a signed 32-bit little-endian argument.
// Addresses are instruction indices (byte offset = 5 x index).
enum class Op : std::uint8_t {
    Nop = 0,
    PushI,        // arg: int32
    PushF,        // arg: float32 bits
    PushS,        // arg: string constant index
    LoadV,        // arg: variable index (scalar)
    StoreV,       // arg: variable index; pops value (already of the variable's type)
    LoadA,        // arg: variable index; pops index
    StoreA,       // arg: variable index; pops value, then index
    LoadP,        // arg: catalog variable index
    StoreP,       // arg: catalog variable index; pops value (converted by the VM to the variable's type)
    RemoteRead,   // arg: catalog variable index; pops axis
    RemoteStatus, // pops axis; pushes 1 if present
    LanRead,      // arg: 0 LANINT, 1 LANFLT; pops n, axis
    LanWrite,     // arg: 0 LANINT, 1 LANFLT; pops value, axis, n
    IntToFloat,
    FloatToInt, // round half to even (QuickBASIC CINT)
    AddI,
    SubI,
    MulI,
    ModI,
    NegI,
    AddF,
    SubF,
    MulF,
    DivF,
    PowF,
    NegF,
    Concat,
    CompareI, // arg: Relation; pushes -1 / 0
    CompareF,
    CompareS,
    And,
    Or,
    Xor,
    Not,
    CallFunction, // arg: function index | argc << 8
    Jump,         // arg: address
    JumpIfZero,   // arg: address; pops integer
    Gosub,        // arg: address
    Return,
    ForCheck,   // arg: 0 integer, 1 float; pops step, limit, value; pushes -1 to continue, 0 to leave
    PrintValue, // pops any value
    PrintZone,  // the `,` separator: next 14-column zone
    PrintNewline,
    InputPrompt, // arg: string index << 1 | question (index -1 = no prompt: "? ")
    Input,       // arg: ValueType; blocks until a line; pushes the value
    Motion,      // arg: MotionKind (1 GO.VEL … 6 UPD.MOVE)
    Pause,
    When,   // arg: source | relation << 8 | action << 12 | actionArg << 16; pops actionValue, value (float)
    Tmrset, // arg: pulse | out << 1 | outLevel << 5 | inp << 6 | inpLevel << 11 | pout << 12 | poutLevel << 16
            //      pops delay (float), timer number
    End,
    Stop,
    Cls,
    Beep,
    Restart, // arg: address in main
    EndInterrupt,
    LanInterrupt, // pops axis
    Count
};

enum class Relation : std::int32_t { Equal, NotEqual, Less, Greater, LessEqual, GreaterEqual };

struct Instruction {
    Op op = Op::Nop;
    std::int32_t arg = 0;
};

struct ProgramVariable {
    std::string name; // upper case; compiler temporaries start with '#'
    ValueType type = ValueType::Integer;
    int count = 1; // elements
    bool array = false;
    bool nonVolatile = false;
};

struct ProgramParam {
    int variable = -1; // catalog index
    double value = 0;
};

struct LineEntry {
    std::int32_t address = 0; // first instruction of a statement
    std::int32_t line = 0;    // 1-based source line
};

inline constexpr std::uint16_t kBinVersion = 1;
inline constexpr int kInstructionBytes = 5;
inline constexpr int kStringBytes = 256; // a STRING variable: length byte + up to 255 characters (chosen)
inline constexpr int kMaxStringLength = 255;
inline constexpr int kStandardLimitBytes = 25000; // data + code (L2648)
inline constexpr int kTurboDataBytes = 25000;
inline constexpr int kTurboCodeBytes = 57216;

struct Program {
    bool turbo = false; // compiled for a turbo SC750 (larger code space)
    std::vector<ProgramParam> params;
    std::vector<ProgramVariable> variables;
    std::vector<std::string> strings;
    std::vector<std::int32_t> interrupts; // one per catalog interrupt source; -1 = no routine
    std::vector<LineEntry> lines;         // ascending address
    std::vector<Instruction> code;

    int codeBytes() const { return int(code.size()) * kInstructionBytes; }
    int dataBytes() const;
    // The source line of the statement containing address (0 if none).
    int lineAt(std::int32_t address) const;
    // The first statement address on line, or -1 when the line holds no executable statement.
    std::int32_t addressOfLine(int line) const;
};

} // namespace drive_core::sc750
