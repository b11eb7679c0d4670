// ServoBASIC Plus code generator: statements (expressions are in sc750_codegen_expr.cpp).
#include "sc750_codegen.h"

#include <bit>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

Program CodeGenerator::generate(const ProgramAst& ast, bool turbo) {
    m_ast = &ast;
    m_program = Program{};
    m_program.turbo = turbo;
    for (const ParamSetting& p : ast.params) m_program.params.push_back({p.variable, p.value});
    for (const Symbol& s : ast.symbols)
        m_program.variables.push_back({s.name, s.type, s.count, s.array, s.nonVolatile});
    m_program.interrupts.assign(cat::interruptSources().size(), -1);

    m_scope = 0;
    emitBlock(ast.main);
    m_program.lines.push_back({here(), ast.end.line});
    emit(Op::End);
    emitBlock(ast.tail);
    if (!ast.tail.empty()) emit(Op::End);
    for (std::size_t i = 0; i < ast.subs.size(); ++i) {
        m_scope = int(i) + 1;
        m_subs[ast.subs[i].name] = here();
        emitBlock(ast.subs[i].body);
        emit(Op::Return);
    }
    for (std::size_t i = 0; i < ast.interrupts.size(); ++i) {
        m_scope = 1000 + int(i);
        m_program.interrupts[std::size_t(ast.interrupts[i].source)] = here();
        emitBlock(ast.interrupts[i].body);
        emit(Op::EndInterrupt);
    }
    for (const Fixup& f : m_fixups) {
        const auto it = m_labels.find(f.label);
        if (it == m_labels.end()) fail(f.where, "label " + f.label + " is not defined");
        if (!f.gosub && it->second.scope != f.scope) fail(f.where, "GOTO " + f.label + " leaves its SUB or routine");
        m_program.code[f.instruction].arg = it->second.address;
    }
    for (std::size_t i = 0; i < m_callFixups.size(); ++i) {
        const auto it = m_subs.find(m_callFixups[i].second);
        if (it == m_subs.end()) fail(m_callWhere[i], "SUB " + m_callFixups[i].second + " is not defined");
        m_program.code[m_callFixups[i].first].arg = it->second;
    }
    const Where& end = ast.end;
    const int code = m_program.codeBytes();
    const int data = m_program.dataBytes();
    if (!turbo && code + data > kStandardLimitBytes)
        fail(end, "program too large: " + std::to_string(code + data) +
                      " bytes of code and data, a standard SC750 holds 25,000");
    if (turbo && data > kTurboDataBytes)
        fail(end, "too much data: " + std::to_string(data) + " bytes, the SC750 holds 25,000");
    if (turbo && code > kTurboCodeBytes)
        fail(end, "program too large: " + std::to_string(code) + " bytes of code, a turbo SC750 holds 57,216");
    return std::move(m_program);
}

void CodeGenerator::emitBlock(const Block& block) {
    for (const StmtPtr& s : block) emitStatement(*s);
}

void CodeGenerator::emitStatement(const Stmt& s) {
    if (s.kind != StmtKind::Label) m_program.lines.push_back({here(), s.where.line});
    switch (s.kind) {
    case StmtKind::Assign: emitAssign(s); break;
    case StmtKind::Print: emitPrint(s); break;
    case StmtKind::Input: emitInput(s); break;
    case StmtKind::If: emitIf(s); break;
    case StmtKind::For: emitFor(s); break;
    case StmtKind::While: {
        const std::int32_t top = here();
        emitAs(*s.value, ValueType::Integer);
        const std::size_t exit = emit(Op::JumpIfZero);
        emitBlock(s.body);
        emit(Op::Jump, top);
        m_program.code[exit].arg = here();
        break;
    }
    case StmtKind::Goto:
    case StmtKind::Gosub:
        m_fixups.push_back({emit(s.kind == StmtKind::Goto ? Op::Jump : Op::Gosub), s.label, m_scope,
                            s.kind == StmtKind::Gosub, s.where});
        break;
    case StmtKind::Return: emit(Op::Return); break;
    case StmtKind::Call:
        m_callFixups.emplace_back(emit(Op::Gosub), s.label);
        m_callWhere.push_back(s.where);
        break;
    case StmtKind::Swap: emitSwap(s); break;
    case StmtKind::Label: defineLabel(s.label, s.where); break;
    case StmtKind::Motion: emit(Op::Motion, std::int32_t(s.motion)); break;
    case StmtKind::Pause: emit(Op::Pause); break;
    case StmtKind::When: {
        const WhenSpec& w = s.when;
        emitAs(*w.value, ValueType::Float);
        if (w.actionValue)
            emitAs(*w.actionValue, ValueType::Float);
        else
            emit(Op::PushF, 0);
        emit(Op::When, w.source | w.relation << 8 | w.action << 12 | w.actionArg << 16);
        break;
    }
    case StmtKind::End: emit(Op::End); break;
    case StmtKind::Stop: emit(Op::Stop); break;
    case StmtKind::Cls: emit(Op::Cls); break;
    case StmtKind::Beep: emit(Op::Beep); break;
    case StmtKind::Restart:
        if (s.label.empty())
            emit(Op::Restart, 0);
        else
            m_fixups.push_back({emit(Op::Restart), s.label, 0, true, s.where});
        break;
    case StmtKind::Tmrset: {
        const TmrsetSpec& t = s.tmrset;
        emitAs(*s.args[0], ValueType::Integer);
        emitAs(*s.args[1], ValueType::Float);
        emit(Op::Tmrset, int(t.pulse) | t.output << 1 | t.outputLevel << 5 | t.input << 6 | t.inputLevel << 11 |
                             t.positionOutput << 12 | t.positionLevel << 16);
        break;
    }
    case StmtKind::LanInterrupt:
        emitAs(*s.value, ValueType::Integer);
        emit(Op::LanInterrupt);
        break;
    }
}

void CodeGenerator::emitAssign(const Stmt& s) {
    const ValueType want = targetType(*s.target);
    const ValueType have = typeOf(*s.value);
    if ((want == ValueType::String) != (have == ValueType::String)) {
        emitExpr(*s.value); // an error inside the expression is the first one
        fail(s.where, want == ValueType::String ? "type mismatch: a number cannot be assigned to a STRING"
                                                : "type mismatch: a string cannot be assigned to a number");
    }
    emitTargetIndex(*s.target);
    emitAs(*s.value, want);
    emitStore(*s.target, want, s.where);
}

// Pushes what a store into target needs below the value: an array index, or LANINT's n and axis.
void CodeGenerator::emitTargetIndex(const Expr& target) {
    if (target.kind == ExprKind::User && !target.args.empty()) emitAs(*target.args[0], ValueType::Integer);
    if (target.kind == ExprKind::Remote) {
        emitAs(*target.args[0], ValueType::Integer);
        emitAs(*target.args[1], ValueType::Integer);
    }
}

void CodeGenerator::emitStore(const Expr& target, ValueType, const Where& where) {
    switch (target.kind) {
    case ExprKind::User: emit(target.args.empty() ? Op::StoreV : Op::StoreA, target.symbol); return;
    case ExprKind::Predef: emit(Op::StoreP, target.symbol); return;
    case ExprKind::Remote: emit(Op::LanWrite, target.text == "LANFLT" ? 1 : 0); return;
    default: fail(where, "cannot assign to this");
    }
}

void CodeGenerator::emitIf(const Stmt& s) {
    std::vector<std::size_t> toEnd;
    for (std::size_t i = 0; i < s.branches.size(); ++i) {
        const Branch& b = s.branches[i];
        std::size_t skip = 0;
        if (b.condition) {
            if (typeOf(*b.condition) == ValueType::String) fail(b.condition->where, "a condition cannot be a string");
            emitAs(*b.condition, ValueType::Integer);
            skip = emit(Op::JumpIfZero);
        }
        emitBlock(b.body);
        if (i + 1 < s.branches.size()) toEnd.push_back(emit(Op::Jump));
        if (b.condition) m_program.code[skip].arg = here();
    }
    for (std::size_t j : toEnd) m_program.code[j].arg = here();
}

// FOR v = a TO b [STEP s]: limit and step are evaluated once, into hidden variables (QuickBASIC).
void CodeGenerator::emitFor(const Stmt& s) {
    const int var = s.target->symbol;
    const ValueType type = m_ast->symbols[std::size_t(var)].type;
    const std::string n = std::to_string(++m_forCount);
    const int limit = hiddenVariable("#FOR" + n + ".LIMIT", type);
    const int step = hiddenVariable("#FOR" + n + ".STEP", type);
    for (const Expr* e : {s.value.get(), s.limit.get(), s.step.get()})
        if (e && typeOf(*e) == ValueType::String) fail(e->where, "FOR needs numbers");
    emitAs(*s.value, type);
    emit(Op::StoreV, var);
    emitAs(*s.limit, type);
    emit(Op::StoreV, limit);
    if (s.step) {
        emitAs(*s.step, type);
    } else if (type == ValueType::Integer) {
        emit(Op::PushI, 1);
    } else {
        emit(Op::PushF, std::bit_cast<std::int32_t>(1.0f));
    }
    emit(Op::StoreV, step);
    const std::int32_t top = here();
    emit(Op::LoadV, var);
    emit(Op::LoadV, limit);
    emit(Op::LoadV, step);
    emit(Op::ForCheck, type == ValueType::Float ? 1 : 0);
    const std::size_t exit = emit(Op::JumpIfZero);
    emitBlock(s.body);
    emit(Op::LoadV, var);
    emit(Op::LoadV, step);
    emit(type == ValueType::Float ? Op::AddF : Op::AddI);
    emit(Op::StoreV, var);
    emit(Op::Jump, top);
    m_program.code[exit].arg = here();
}

void CodeGenerator::emitPrint(const Stmt& s) {
    char last = 0;
    for (const PrintItem& item : s.items) {
        if (item.expr) {
            emitExpr(*item.expr);
            emit(Op::PrintValue);
        }
        if (item.separator == ',') emit(Op::PrintZone);
        last = item.separator;
    }
    if (last == 0) emit(Op::PrintNewline);
}

void CodeGenerator::emitInput(const Stmt& s) {
    const int prompt = s.hasPrompt ? stringConstant(s.prompt) : -1;
    emit(Op::InputPrompt, prompt * 2 + (s.promptQuestion ? 1 : 0));
    const ValueType want = targetType(*s.target);
    emitTargetIndex(*s.target);
    emit(Op::Input, std::int32_t(want));
    emitStore(*s.target, want, s.where);
}

void CodeGenerator::emitSwap(const Stmt& s) {
    const ValueType a = targetType(*s.target);
    const ValueType b = targetType(*s.target2);
    if (a != b) fail(s.where, "SWAP needs two variables of the same type");
    // no PacLAN operand reaches here: the parser refuses writing another axis's variable (L2283)
    const int tmp = hiddenVariable(a == ValueType::String  ? "#SWAP.S"
                                   : a == ValueType::Float ? "#SWAP.F"
                                                           : "#SWAP.I",
                                   a);
    emitExpr(*s.target);
    emit(Op::StoreV, tmp);
    emitTargetIndex(*s.target);
    emitExpr(*s.target2);
    emitStore(*s.target, a, s.where);
    emitTargetIndex(*s.target2);
    emit(Op::LoadV, tmp);
    emitStore(*s.target2, a, s.where);
}

void CodeGenerator::defineLabel(const std::string& name, const Where& where) {
    if (m_labels.count(name) != 0) fail(where, "label " + name + " is defined twice");
    m_labels[name] = Label{here(), m_scope};
}

std::size_t CodeGenerator::emit(Op op, std::int32_t arg) {
    m_program.code.push_back({op, arg});
    return m_program.code.size() - 1;
}

int CodeGenerator::stringConstant(const std::string& text) {
    for (std::size_t i = 0; i < m_program.strings.size(); ++i)
        if (m_program.strings[i] == text) return int(i);
    m_program.strings.push_back(text);
    return int(m_program.strings.size()) - 1;
}

int CodeGenerator::hiddenVariable(const std::string& name, ValueType type) {
    for (std::size_t i = 0; i < m_program.variables.size(); ++i)
        if (m_program.variables[i].name == name) return int(i);
    m_program.variables.push_back({name, type, 1, false, false});
    return int(m_program.variables.size()) - 1;
}

void CodeGenerator::fail(const Where& where, const std::string& message) {
    throw CompileFailure{CompileError{where.line, where.column, where.near, message}};
}

} // namespace drive_core::sc750
