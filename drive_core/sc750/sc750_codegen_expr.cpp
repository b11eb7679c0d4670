// ServoBASIC Plus code generator: expressions, their types and conversions. INTEGER is int32, FLOAT
// float32; + - * on two integers stay integer, / and ^ are always float, AND/OR/XOR/NOT/MOD integer.
#include "sc750_codegen.h"

#include <bit>
#include <cmath>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

namespace {

bool isRelation(const std::string& op) {
    return op == "=" || op == "<>" || op == "<" || op == ">" || op == "<=" || op == ">=";
}

Relation relationOf(const std::string& op) {
    if (op == "=") return Relation::Equal;
    if (op == "<>") return Relation::NotEqual;
    if (op == "<") return Relation::Less;
    if (op == ">") return Relation::Greater;
    if (op == "<=") return Relation::LessEqual;
    return Relation::GreaterEqual;
}

// Which arguments of each function are strings ('S') or numbers ('N'); INSTR's optional start first.
std::string_view signatureOf(std::string_view name, std::size_t argc) {
    if (name == "ASC" || name == "LEN" || name == "LCASE$" || name == "UCASE$" || name == "LTRIM$" || name == "VAL")
        return "S";
    if (name == "MID$") return "SNN";
    if (name == "LEFT$" || name == "RIGHT$") return "SN";
    if (name == "INSTR") return argc == 3 ? "NSS" : "SS";
    if (name == "STRING$") return "N?";
    return "N";
}

} // namespace

ValueType CodeGenerator::targetType(const Expr& target) const {
    return typeOf(target);
}

ValueType CodeGenerator::typeOf(const Expr& e) const {
    switch (e.kind) {
    case ExprKind::Integer:
        return e.value > 2147483647.0 || e.value < -2147483648.0 ? ValueType::Float : ValueType::Integer;
    case ExprKind::Float: return ValueType::Float;
    case ExprKind::String: return ValueType::String;
    case ExprKind::User: return m_ast->symbols[std::size_t(e.symbol)].type;
    case ExprKind::Predef: return cat::variables()[std::size_t(e.symbol)].type;
    case ExprKind::Remote:
        if (e.text == "STATUS" || e.text == "LANINT") return ValueType::Integer;
        if (e.text == "LANFLT") return ValueType::Float;
        return cat::findVariable(e.text)->type;
    case ExprKind::Function: return cat::functions()[std::size_t(e.symbol)].result;
    case ExprKind::Unary:
        if (e.op == "NOT") return ValueType::Integer;
        return typeOf(*e.args[0]);
    case ExprKind::Binary: {
        const ValueType a = typeOf(*e.args[0]);
        const ValueType b = typeOf(*e.args[1]);
        if (isRelation(e.op) || e.op == "AND" || e.op == "OR" || e.op == "XOR" || e.op == "MOD")
            return ValueType::Integer;
        if (e.op == "/" || e.op == "^") return ValueType::Float;
        if (a == ValueType::String || b == ValueType::String) return ValueType::String;
        return a == ValueType::Integer && b == ValueType::Integer ? ValueType::Integer : ValueType::Float;
    }
    }
    return ValueType::Integer;
}

void CodeGenerator::emitAs(const Expr& e, ValueType want) {
    const ValueType have = emitExpr(e);
    if (have == want) return;
    if (have == ValueType::String || want == ValueType::String)
        fail(e.where, want == ValueType::String ? "type mismatch: a string is needed here"
                                                : "type mismatch: a number is needed here");
    emit(want == ValueType::Float ? Op::IntToFloat : Op::FloatToInt);
}

ValueType CodeGenerator::emitExpr(const Expr& e) {
    switch (e.kind) {
    case ExprKind::Integer:
        if (typeOf(e) == ValueType::Float) {
            emit(Op::PushF, std::bit_cast<std::int32_t>(float(e.value)));
            return ValueType::Float;
        }
        emit(Op::PushI, std::int32_t(e.value));
        return ValueType::Integer;
    case ExprKind::Float: emit(Op::PushF, std::bit_cast<std::int32_t>(float(e.value))); return ValueType::Float;
    case ExprKind::String: emit(Op::PushS, stringConstant(e.text)); return ValueType::String;
    case ExprKind::User:
        if (e.args.empty()) {
            emit(Op::LoadV, e.symbol);
        } else {
            emitAs(*e.args[0], ValueType::Integer);
            emit(Op::LoadA, e.symbol);
        }
        return typeOf(e);
    case ExprKind::Predef: emit(Op::LoadP, e.symbol); return typeOf(e);
    case ExprKind::Remote:
        if (e.text == "STATUS") {
            emitAs(*e.args[0], ValueType::Integer);
            emit(Op::RemoteStatus);
        } else if (e.text == "LANINT" || e.text == "LANFLT") {
            emitAs(*e.args[0], ValueType::Integer);
            emitAs(*e.args[1], ValueType::Integer);
            emit(Op::LanRead, e.text == "LANFLT" ? 1 : 0);
        } else {
            emitAs(*e.args[0], ValueType::Integer);
            emit(Op::RemoteRead, cat::variableIndex(e.text));
        }
        return typeOf(e);
    case ExprKind::Function: emitFunction(e); return typeOf(e);
    case ExprKind::Unary: {
        const ValueType t = typeOf(*e.args[0]);
        if (t == ValueType::String) fail(e.where, "type mismatch: " + e.op + " needs a number");
        if (e.op == "NOT") {
            emitAs(*e.args[0], ValueType::Integer);
            emit(Op::Not);
            return ValueType::Integer;
        }
        emitExpr(*e.args[0]);
        emit(t == ValueType::Integer ? Op::NegI : Op::NegF);
        return t;
    }
    case ExprKind::Binary: break;
    }
    const Expr& l = *e.args[0];
    const Expr& r = *e.args[1];
    const ValueType a = typeOf(l);
    const ValueType b = typeOf(r);
    const bool strings = a == ValueType::String || b == ValueType::String;
    if (strings && a != b) fail(e.where, "type mismatch: " + e.op + " between a string and a number");
    if (strings) {
        if (e.op == "+") {
            emitExpr(l);
            emitExpr(r);
            emit(Op::Concat);
            return ValueType::String;
        }
        if (!isRelation(e.op)) fail(e.where, "type mismatch: " + e.op + " cannot take strings");
        emitExpr(l);
        emitExpr(r);
        emit(Op::CompareS, std::int32_t(relationOf(e.op)));
        return ValueType::Integer;
    }
    if (e.op == "AND" || e.op == "OR" || e.op == "XOR" || e.op == "MOD") {
        emitAs(l, ValueType::Integer);
        emitAs(r, ValueType::Integer);
        emit(e.op == "AND" ? Op::And : e.op == "OR" ? Op::Or : e.op == "XOR" ? Op::Xor : Op::ModI);
        return ValueType::Integer;
    }
    const bool integer = a == ValueType::Integer && b == ValueType::Integer && e.op != "/" && e.op != "^";
    const ValueType t = integer ? ValueType::Integer : ValueType::Float;
    emitAs(l, t);
    emitAs(r, t);
    if (isRelation(e.op)) {
        emit(integer ? Op::CompareI : Op::CompareF, std::int32_t(relationOf(e.op)));
        return ValueType::Integer;
    }
    if (e.op == "+") emit(integer ? Op::AddI : Op::AddF);
    if (e.op == "-") emit(integer ? Op::SubI : Op::SubF);
    if (e.op == "*") emit(integer ? Op::MulI : Op::MulF);
    if (e.op == "/") emit(Op::DivF);
    if (e.op == "^") emit(Op::PowF);
    return t;
}

// Arguments are pushed as they are (numbers keep their type); the VM converts per function.
void CodeGenerator::emitFunction(const Expr& e) {
    const cat::FunctionInfo& f = cat::functions()[std::size_t(e.symbol)];
    const std::string_view sig = signatureOf(f.name, e.args.size());
    for (std::size_t i = 0; i < e.args.size(); ++i) {
        const ValueType t = typeOf(*e.args[i]);
        const char want = i < sig.size() ? sig[i] : 'N';
        if (want == 'S' && t != ValueType::String)
            fail(e.args[i]->where, std::string(f.name) + " needs a string here: " + std::string(f.syntax));
        if (want == 'N' && t == ValueType::String)
            fail(e.args[i]->where, std::string(f.name) + " needs a number here: " + std::string(f.syntax));
        emitExpr(*e.args[i]);
    }
    emit(Op::CallFunction, e.symbol | std::int32_t(e.args.size()) << 8);
}

} // namespace drive_core::sc750
