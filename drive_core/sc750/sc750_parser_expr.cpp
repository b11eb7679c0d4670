// ServoBASIC Plus parser: expressions by the manual's precedence (L1075-L1119) and the token helpers.
// Lowest first: XOR, OR, AND, NOT, relations, + -, MOD, * /, unary -, ^, primary.
#include "sc750_parser.h"

#include <set>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

namespace {

ExprPtr binary(std::string op, ExprPtr left, ExprPtr right, Where where) {
    auto e = std::make_unique<Expr>();
    e->kind = ExprKind::Binary;
    e->op = std::move(op);
    e->where = std::move(where);
    e->args.push_back(std::move(left));
    e->args.push_back(std::move(right));
    return e;
}

} // namespace

constexpr int kMaxDepth = 100; // chosen: deeper than any hand-written program nests

void Parser::enter() {
    if (++m_depth > kMaxDepth) fail(peek(), "nested too deeply");
}

// expression := xor
ExprPtr Parser::parseExpression() {
    enter();
    ExprPtr e = parseXor();
    --m_depth;
    return e;
}

// xor := or {XOR or}
ExprPtr Parser::parseXor() {
    ExprPtr e = parseOr();
    while (atName("XOR")) {
        Where w = here();
        next();
        e = binary("XOR", std::move(e), parseOr(), w);
    }
    return e;
}

// or := and {OR and}
ExprPtr Parser::parseOr() {
    ExprPtr e = parseAnd();
    while (atName("OR")) {
        Where w = here();
        next();
        e = binary("OR", std::move(e), parseAnd(), w);
    }
    return e;
}

// and := not {AND not}
ExprPtr Parser::parseAnd() {
    ExprPtr e = parseNot();
    while (atName("AND")) {
        Where w = here();
        next();
        e = binary("AND", std::move(e), parseNot(), w);
    }
    return e;
}

// not := NOT not | relation
ExprPtr Parser::parseNot() {
    if (atName("NOT")) {
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Unary;
        e->op = "NOT";
        e->where = here();
        next();
        enter();
        e->args.push_back(parseNot());
        --m_depth;
        return e;
    }
    return parseRelation();
}

// relation := additive [('=' | '<>' | '<' | '>' | '<=' | '>=') additive]
ExprPtr Parser::parseRelation() {
    ExprPtr e = parseAdditive();
    static const std::set<std::string> kRel = {"=", "<>", "<", ">", "<=", ">="};
    while (peek().kind == TokenKind::Operator && kRel.count(peek().text) != 0) {
        Where w = here();
        const std::string op = next().text;
        e = binary(op, std::move(e), parseAdditive(), w);
    }
    return e;
}

// additive := mod {('+' | '-') mod}
ExprPtr Parser::parseAdditive() {
    ExprPtr e = parseMod();
    while (atOperator("+") || atOperator("-")) {
        Where w = here();
        const std::string op = next().text;
        e = binary(op, std::move(e), parseMod(), w);
    }
    return e;
}

// mod := multiplicative {MOD multiplicative}
ExprPtr Parser::parseMod() {
    ExprPtr e = parseMultiplicative();
    while (atName("MOD")) {
        Where w = here();
        next();
        e = binary("MOD", std::move(e), parseMultiplicative(), w);
    }
    return e;
}

// multiplicative := unary {('*' | '/') unary}
ExprPtr Parser::parseMultiplicative() {
    ExprPtr e = parseUnary();
    while (atOperator("*") || atOperator("/")) {
        Where w = here();
        const std::string op = next().text;
        e = binary(op, std::move(e), parseUnary(), w);
    }
    return e;
}

// unary := ('-' | '+') unary | power
ExprPtr Parser::parseUnary() {
    if (atOperator("-") || atOperator("+")) {
        Where w = here();
        const bool minus = next().text == "-";
        enter();
        ExprPtr operand = parseUnary();
        --m_depth;
        if (!minus) return operand;
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Unary;
        e->op = "-";
        e->where = std::move(w);
        e->args.push_back(std::move(operand));
        return e;
    }
    return parsePower();
}

// power := primary {'^' ['-'] primary}
ExprPtr Parser::parsePower() {
    ExprPtr e = parsePrimary();
    while (atOperator("^")) {
        Where w = here();
        next();
        ExprPtr right;
        if (atOperator("-")) {
            right = std::make_unique<Expr>();
            right->kind = ExprKind::Unary;
            right->op = "-";
            right->where = here();
            next();
            right->args.push_back(parsePrimary());
        } else {
            right = parsePrimary();
        }
        e = binary("^", std::move(e), std::move(right), w);
    }
    return e;
}

// primary := number | string | '(' expression ')' | name
ExprPtr Parser::parsePrimary() {
    const Token& t = peek();
    auto e = std::make_unique<Expr>();
    e->where = here();
    switch (t.kind) {
    case TokenKind::Integer:
    case TokenKind::Float:
        e->kind = t.kind == TokenKind::Integer ? ExprKind::Integer : ExprKind::Float;
        e->value = t.number;
        next();
        return e;
    case TokenKind::String:
        e->kind = ExprKind::String;
        e->text = t.text;
        next();
        return e;
    case TokenKind::Operator:
        if (t.text == "(") {
            next();
            ExprPtr inner = parseExpression();
            expectOperator(")", ") to close the parenthesis");
            return inner;
        }
        break;
    case TokenKind::Name: return parseName();
    default: break;
    }
    fail(t, t.kind == TokenKind::Newline || t.kind == TokenKind::End ? "expression expected at end of line"
                                                                     : "expression expected");
}

// name := function ['(' args ')'] | variable | predefined ['[' axis ']'] | STATUS '[' axis ']'
ExprPtr Parser::parseName() {
    const Token& t = peek();
    if (const cat::FunctionInfo* f = cat::findFunction(t.upper)) {
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Function;
        e->where = here();
        e->symbol = int(f - cat::functions().data());
        next();
        if (f->maxArgs == 0) {
            if (atOperator("(")) {
                next();
                expectOperator(")", ") after " + std::string(f->name));
            }
            return e;
        }
        expectOperator("(", "( after " + std::string(f->name));
        for (;;) {
            e->args.push_back(parseExpression());
            if (!atOperator(",")) break;
            next();
        }
        expectOperator(")", ") after the arguments of " + std::string(f->name));
        const int n = int(e->args.size());
        if (n < f->minArgs || n > f->maxArgs) fail(t, std::string(f->name) + " takes " + std::string(f->syntax));
        return e;
    }
    if (t.upper == "STATUS" && peek(1).kind == TokenKind::Operator && peek(1).text == "[") {
        auto e = std::make_unique<Expr>();
        e->kind = ExprKind::Remote;
        e->where = here();
        e->text = "STATUS";
        next();
        next();
        e->args.push_back(parseExpression());
        expectOperator("]", "] after the axis");
        return e;
    }
    return parseVariable(false);
}

// variable := user ['(' index ')'] | predefined ['[' axis ']'] | (LANINT|LANFLT) '(' n ')' '[' axis ']'
ExprPtr Parser::parseVariable(bool forWrite) {
    const Token& t = peek();
    auto e = std::make_unique<Expr>();
    e->where = here();
    if (t.kind != TokenKind::Name) fail(t, "expected a variable");
    if (t.upper == "LANINT" || t.upper == "LANFLT") {
        e->kind = ExprKind::Remote;
        e->text = t.upper;
        next();
        expectOperator("(", "(n) after " + t.text);
        e->args.push_back(parseExpression());
        expectOperator(")", ") after the index");
        expectOperator("[", "[axis] after " + t.text + "(n)");
        e->args.push_back(parseExpression());
        expectOperator("]", "] after the axis");
        return e;
    }
    const int user = symbolIndex(t.upper);
    if (user >= 0) {
        const Symbol& s = m_ast.symbols[std::size_t(user)];
        e->kind = ExprKind::User;
        e->symbol = user;
        next();
        if (s.array) {
            if (!atOperator("(")) fail(t, t.text + " is an array: give an index in ( )");
            next();
            e->args.push_back(parseExpression());
            expectOperator(")", ") after the array index");
        } else if (atOperator("(")) {
            fail(peek(), t.text + " is not an array");
        }
        return e;
    }
    const int predef = cat::variableIndex(t.upper);
    if (predef >= 0) {
        const cat::VariableInfo& info = cat::variables()[std::size_t(predef)];
        next();
        if (atOperator("[")) {
            if (forWrite) fail(t, "another axis's " + t.text + " is read-only in a program (L2283)");
            e->kind = ExprKind::Remote;
            e->text = std::string(info.name);
            next();
            e->args.push_back(parseExpression());
            expectOperator("]", "] after the axis");
            return e;
        }
        if (forWrite && info.access == cat::Access::ReadOnly) fail(t, t.text + " is read-only");
        e->kind = ExprKind::Predef;
        e->symbol = predef;
        return e;
    }
    if (isKeyword(t.upper)) fail(t, "unexpected " + t.text);
    fail(t, t.text + " is not declared: DIM it before use");
}

// --- token helpers ---

const Token& Parser::peek(int ahead) const {
    const long i = long(m_pos) + ahead;
    if (i < 0) return m_tokens.front();
    return m_tokens[std::min(std::size_t(i), m_tokens.size() - 1)];
}

const Token& Parser::next() {
    const Token& t = m_tokens[m_pos];
    if (m_pos + 1 < m_tokens.size()) ++m_pos;
    return t;
}

bool Parser::atName(std::string_view upper, int ahead) const {
    const Token& t = peek(ahead);
    return t.kind == TokenKind::Name && t.upper == upper;
}

bool Parser::atOperator(std::string_view op) const {
    return peek().kind == TokenKind::Operator && peek().text == op;
}

bool Parser::atLineEnd() const {
    const TokenKind k = peek().kind;
    return k == TokenKind::Newline || k == TokenKind::Colon || k == TokenKind::End ||
           (m_singleLineIf > 0 && atName("ELSE"));
}

void Parser::expectName(std::string_view upper, std::string_view what) {
    if (!atName(upper)) fail(peek(), "expected " + std::string(what));
    next();
}

void Parser::expectOperator(std::string_view op, std::string_view what) {
    if (!atOperator(op)) fail(peek(), "expected " + std::string(what));
    next();
}

void Parser::skipBlankLines() {
    while (peek().kind == TokenKind::Newline || peek().kind == TokenKind::Colon) next();
}

Where Parser::here() const {
    const Token& t = peek();
    return Where{t.line, t.column, t.kind == TokenKind::String ? "\"" + t.text + "\"" : t.text};
}

void Parser::fail(const Token& at, const std::string& message) const {
    std::string near = at.kind == TokenKind::String ? "\"" + at.text + "\"" : at.text;
    throw CompileFailure{CompileError{at.line, at.column, std::move(near), message}};
}

bool Parser::isKeyword(const std::string& upper) {
    static const std::set<std::string> kWords = {
        "IF",       "THEN",      "ELSE",         "ELSEIF",   "END",          "ENDIF",  "FOR",    "TO",
        "STEP",     "NEXT",      "WHILE",        "WEND",     "GOTO",         "GOSUB",  "RETURN", "CALL",
        "SUB",      "SWAP",      "PRINT",        "INPUT",    "CLS",          "BEEP",   "PAUSE",  "WHEN",
        "CONTINUE", "INTERRUPT", "RESTART",      "TMRSET",   "DIM",          "AS",     "PARAMS", "STOP",
        "AND",      "OR",        "XOR",          "NOT",      "MOD",          "LET",    "GO.VEL", "GO.INCR",
        "GO.ABS",   "GO.HOME",   "ABORT.MOTION", "UPD.MOVE", "LANINTERRUPT", "LANINT", "LANFLT", "STATUS",
        "REM",      "INTEGER",   "LONG",         "SINGLE",   "DOUBLE",       "FLOAT",  "STRING"};
    return kWords.count(upper) != 0;
}

int Parser::symbolIndex(const std::string& upper) const {
    const auto it = m_symbols.find(upper);
    return it == m_symbols.end() ? -1 : it->second;
}

} // namespace drive_core::sc750
