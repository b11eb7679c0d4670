// ServoBASIC Plus code generator: walks the ProgramAst, checks types and labels, and emits the stack
// code of a Program (sc750_program.h). Throws CompileFailure with the statement's line on an error.
#pragma once

#include "sc750_ast.h"
#include "sc750_error.h"
#include "sc750_program.h"

#include <map>
#include <string>
#include <vector>

namespace drive_core::sc750 {

class CodeGenerator {
public:
    Program generate(const ProgramAst& ast, bool turbo);

private:
    struct Fixup {
        std::size_t instruction;
        std::string label;
        int scope;
        bool gosub; // GOSUB may reach a label in any routine; GOTO stays in its own
        Where where;
    };
    struct Label {
        std::int32_t address;
        int scope;
    };

    void emitBlock(const Block& block);
    void emitStatement(const Stmt& s);
    void emitAssign(const Stmt& s);
    void emitIf(const Stmt& s);
    void emitFor(const Stmt& s);
    void emitPrint(const Stmt& s);
    void emitInput(const Stmt& s);
    void emitSwap(const Stmt& s);
    void emitStore(const Expr& target, ValueType valueType, const Where& where);
    void emitTargetIndex(const Expr& target);
    ValueType emitExpr(const Expr& e);
    void emitAs(const Expr& e, ValueType want); // emits e converted to a numeric type (or a string)
    void emitFunction(const Expr& e);
    ValueType typeOf(const Expr& e) const;
    ValueType targetType(const Expr& target) const;
    std::size_t emit(Op op, std::int32_t arg = 0);
    std::int32_t here() const { return std::int32_t(m_program.code.size()); }
    int stringConstant(const std::string& text);
    int hiddenVariable(const std::string& name, ValueType type);
    void defineLabel(const std::string& name, const Where& where);
    [[noreturn]] static void fail(const Where& where, const std::string& message);

    const ProgramAst* m_ast = nullptr;
    Program m_program;
    std::map<std::string, Label> m_labels;
    std::map<std::string, std::int32_t> m_subs;
    std::vector<Fixup> m_fixups;
    std::vector<std::pair<std::size_t, std::string>> m_callFixups;
    std::vector<Where> m_callWhere;
    int m_scope = 0; // 0 main and its GOSUB routines, 1.. SUBs, 1000.. interrupts
    int m_forCount = 0;
};

} // namespace drive_core::sc750
