// The syntax tree the ServoBASIC Plus parser builds and the code generator walks. Plain data: nothing
// here executes. Every node keeps the line, column and text it came from, for diagnostics.
#pragma once

#include "drive_core/catalog/sc750_catalog.h"

#include <memory>
#include <string>
#include <vector>

namespace drive_core::sc750 {

using catalog::sc750::ValueType;

struct Where {
    int line = 0;
    int column = 0;
    std::string near;
};

enum class ExprKind {
    Integer,  // value
    Float,    // value
    String,   // text
    User,     // symbol (index into ProgramAst::symbols); args[0] = index for arrays
    Predef,   // symbol = catalog variable index
    Remote,   // name[axis] / STATUS[axis] / LANINT(n)[axis]: text = name, args = [axis] or [n, axis]
    Function, // symbol = index into catalog functions(); args
    Unary,    // op "-" or "NOT"; args[0]
    Binary,   // op; args[0], args[1]
};

struct Expr {
    ExprKind kind = ExprKind::Integer;
    Where where;
    double value = 0;
    std::string text; // String literal / Remote name
    std::string op;
    int symbol = -1;
    std::vector<std::unique_ptr<Expr>> args;
};
using ExprPtr = std::unique_ptr<Expr>;

enum class StmtKind {
    Assign, // target = value
    Print,  // items
    Input,  // prompt, target
    If,     // branches
    For,    // target, value (start), limit, step (may be null), body
    While,  // value (condition), body
    Goto,   // label
    Gosub,  // label
    Return,
    Call,   // label (SUB name)
    Swap,   // target, target2
    Label,  // label
    Motion, // motion
    Pause,
    When, // when
    End,  // END inside the main body is the program's end; STOP
    Stop,
    Cls,
    Beep,
    Restart,      // label (optional)
    Tmrset,       // args, tmrset
    LanInterrupt, // value (axis)
};

enum class MotionKind { GoVel = 1, GoIncr, GoAbs, GoHome, Abort, UpdMove };

struct PrintItem {
    ExprPtr expr;       // may be null (separator only)
    char separator = 0; // ';', ',' or 0 (end of statement)
};

struct Stmt;
using StmtPtr = std::unique_ptr<Stmt>;
using Block = std::vector<StmtPtr>;

struct Branch {
    ExprPtr condition; // null for ELSE
    Block body;
};

// WHEN condition, action (L1995-L2017), restricted forms only.
struct WhenSpec {
    int source = 0;   // 1..16 INPn, 17 POS.COMMAND, 18 POSITION, 19 ENCPOS, 20 ANALOG.IN
    int relation = 0; // 0 '=', 1 '>', 2 '<'
    ExprPtr value;
    int action = 0;    // 0 CONTINUE, 1 OUTn=, 2 RATIO=, 3..8 GO.VEL..UPD.MOVE order of MotionKind, 9 PAUSE
    int actionArg = 0; // OUTn: n
    ExprPtr actionValue;
};

struct TmrsetSpec {
    bool pulse = false;
    int output = 0, outputLevel = 0;
    int input = 0, inputLevel = 0;
    int positionOutput = 0, positionLevel = 0; // 0 = left blank
};

struct Stmt {
    StmtKind kind = StmtKind::Assign;
    Where where;
    ExprPtr target, target2, value, limit, step;
    std::vector<PrintItem> items;
    std::string prompt;
    bool hasPrompt = false;
    bool promptQuestion = false; // `;` after the prompt: "? " follows it
    std::vector<Branch> branches;
    Block body;
    std::string label; // upper case
    MotionKind motion = MotionKind::GoVel;
    WhenSpec when;
    TmrsetSpec tmrset;
    std::vector<ExprPtr> args;
};

struct Symbol {
    std::string name; // upper case, `$` kept
    ValueType type = ValueType::Integer;
    int count = 1; // elements; arrays: upper bound + 1
    bool array = false;
    bool nonVolatile = false;
    Where where;
};

struct ParamSetting {
    int variable = -1; // catalog index
    double value = 0;
    Where where;
};

struct Routine {
    std::string name; // SUB name, or the interrupt source label
    int source = -1;  // interrupt: index into catalog interruptSources()
    Where where;
    Block body;
};

struct ProgramAst {
    std::vector<ParamSetting> params;
    std::vector<Symbol> symbols;
    Block main; // up to (not including) END
    Where end;  // the main program's END
    Block tail; // GOSUB routines written after END, outside SUBs
    std::vector<Routine> subs;
    std::vector<Routine> interrupts;
};

} // namespace drive_core::sc750
