// ServoBASIC Plus parser: program sections and statements (expressions are in sc750_parser_expr.cpp).
#include "sc750_parser.h"

#include <algorithm>
#include <set>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

Parser::Parser(std::vector<Token> tokens) : m_tokens(std::move(tokens)) {}

// program := [params] {dim} body END {SUB … END SUB | stmt} {INTERRUPT src … END INTERRUPT}
ProgramAst Parser::parse() {
    skipBlankLines();
    if (atName("PARAMS")) parseParams();
    parseDims();
    m_ast.main = parseBlock({"END"});
    m_ast.end = here();
    if (peek().kind == TokenKind::End) { // END may be left out when nothing follows (L1133, L2052 programs)
        int back = -1;
        while (peek(back).kind == TokenKind::Newline && back > -int(m_pos)) --back;
        m_ast.end.line = peek(back).line; // the implicit END belongs to the last line with text
        return std::move(m_ast);
    }
    next(); // END
    endStatement();
    parseAfterEnd();
    return std::move(m_ast);
}

// params := PARAMS START nl {NAME = [-]number nl} PARAMS END
void Parser::parseParams() {
    next();
    expectName("START", "PARAMS START");
    endStatement();
    for (;;) {
        skipBlankLines();
        if (atName("PARAMS")) {
            next();
            expectName("END", "PARAMS END");
            endStatement();
            return;
        }
        const Token& name = peek();
        if (name.kind != TokenKind::Name) fail(name, "expected a set-up parameter or PARAMS END");
        const int index = cat::variableIndex(name.upper);
        if (index < 0 || cat::variables()[std::size_t(index)].access != cat::Access::Parameter)
            fail(name, name.text + " is not a set-up parameter");
        ParamSetting setting{index, 0, here()};
        next();
        expectOperator("=", "= after the parameter name");
        double sign = 1;
        if (atOperator("-")) {
            next();
            sign = -1;
        }
        const Token& value = peek();
        if (value.kind != TokenKind::Integer && value.kind != TokenKind::Float)
            fail(value, "a PARAMS value must be a number");
        setting.value = sign * value.number;
        const auto& info = cat::variables()[std::size_t(index)];
        if (setting.value < info.minimum || setting.value > info.maximum)
            fail(value, "value out of range for " + std::string(info.name));
        next();
        endStatement();
        m_ast.params.push_back(std::move(setting));
    }
}

// dims := {DIM [NV] name[(n)] {, name[(n)]} AS type nl}
void Parser::parseDims() {
    for (;;) {
        skipBlankLines();
        if (!atName("DIM")) return;
        next();
        bool nv = false;
        if (atName("NV") && !atName("AS", 1) && !(peek(1).kind == TokenKind::Operator && peek(1).text == ",")) {
            next();
            nv = true;
            if (m_volatileSeen) fail(peek(-1), "non-volatile DIMs must come before the volatile ones");
        } else {
            m_volatileSeen = true;
        }
        parseDim(nv);
        endStatement();
    }
}

// dim := name[(n)] {, name[(n)]} AS INTEGER|LONG|SINGLE|DOUBLE|FLOAT|STRING
void Parser::parseDim(bool nonVolatile) {
    std::vector<Symbol> names;
    for (;;) {
        const Token& name = peek();
        if (name.kind != TokenKind::Name) fail(name, "expected a variable name");
        if (isKeyword(name.upper)) fail(name, name.text + " is a reserved word");
        if (name.upper.find('.') != std::string::npos)
            fail(name, "user variable names may not contain '.' (reserved for predefined names)");
        if (cat::findVariable(name.upper) || cat::findFunction(name.upper))
            fail(name, name.text + " is a predefined name");
        if (m_symbols.count(name.upper) != 0) fail(name, name.text + " is declared twice");
        for (const Symbol& s : names)
            if (s.name == name.upper) fail(name, name.text + " is declared twice");
        Symbol symbol;
        symbol.name = name.upper;
        symbol.where = here();
        symbol.nonVolatile = nonVolatile;
        next();
        if (atOperator("(")) {
            next();
            const Token& bound = peek();
            if (bound.kind != TokenKind::Integer) fail(bound, "an array size must be an integer constant");
            if (bound.number > 4095) fail(bound, "array too large (upper bound at most 4095)");
            symbol.array = true;
            symbol.count = int(bound.number) + 1; // QuickBASIC: indices 0..n
            next();
            expectOperator(")", ") after the array size");
        }
        names.push_back(std::move(symbol));
        if (!atOperator(",")) break;
        next();
    }
    expectName("AS", "AS and a type");
    const Token& type = peek();
    ValueType vt;
    if (type.upper == "INTEGER" || type.upper == "LONG")
        vt = ValueType::Integer;
    else if (type.upper == "SINGLE" || type.upper == "DOUBLE" || type.upper == "FLOAT")
        vt = ValueType::Float;
    else if (type.upper == "STRING")
        vt = ValueType::String;
    else
        fail(type, "expected INTEGER, LONG, SINGLE, DOUBLE, FLOAT or STRING");
    next();
    for (Symbol& s : names) {
        if (s.name.back() == '$' && vt != ValueType::String) {
            const Where& w = s.where;
            throw CompileFailure{{w.line, w.column, w.near, "a name ending in $ must be a STRING"}};
        }
        s.type = vt;
        m_symbols[s.name] = int(m_ast.symbols.size());
        m_ast.symbols.push_back(std::move(s));
    }
}

// after-end := {SUB name nl block END SUB | stmt} {INTERRUPT source nl block END INTERRUPT}
void Parser::parseAfterEnd() {
    std::set<std::string> subs;
    for (;;) {
        skipBlankLines();
        const Token& t = peek();
        if (t.kind == TokenKind::End) return;
        if (atName("SUB")) {
            if (!m_ast.interrupts.empty()) fail(t, "SUBs must come before the interrupt routines");
            next();
            const Token& name = peek();
            if (name.kind != TokenKind::Name || isKeyword(name.upper)) fail(name, "expected a SUB name");
            if (!subs.insert(name.upper).second) fail(name, "SUB " + name.text + " is defined twice");
            Routine r{name.upper, -1, here(), {}};
            next();
            endStatement();
            r.body = parseBlock({"END SUB"});
            if (peek().kind == TokenKind::End) fail(t, "SUB " + r.name + " has no END SUB");
            next();
            next();
            endStatement();
            m_ast.subs.push_back(std::move(r));
        } else if (atName("INTERRUPT")) {
            next();
            const Token& source = peek();
            const int index = cat::interruptIndex(source.upper);
            if (source.kind != TokenKind::Name || index < 0)
                fail(source, "unknown interrupt source (CCWINH, CCWOT, CHAR, CWINH, CWOT, DISABLE, FAULT, "
                             "I1HI…I16HI, I1LO…I16LO, PACLAN, POS.ERROR)");
            for (const Routine& r : m_ast.interrupts)
                if (r.source == index) fail(source, "INTERRUPT " + source.text + " is defined twice");
            Routine r{source.upper, index, here(), {}};
            next();
            endStatement();
            m_inInterrupt = true;
            r.body = parseBlock({"END INTERRUPT"});
            m_inInterrupt = false;
            if (peek().kind == TokenKind::End) fail(t, "INTERRUPT " + r.name + " has no END INTERRUPT");
            next();
            next();
            endStatement();
            m_ast.interrupts.push_back(std::move(r));
        } else {
            if (!m_ast.interrupts.empty()) fail(t, "only INTERRUPT routines may follow the interrupt routines");
            parseLine(m_ast.tail);
        }
    }
}

// block := {stmt (':' | nl)} up to one of the terminators (not consumed)
Block Parser::parseBlock(const std::vector<std::string>& terminators) {
    enter();
    Block block = parseBlockBody(terminators);
    --m_depth;
    return block;
}

// block-body := {stmt (':' | nl)} — stops before a terminator's first word(s) or at end of file
Block Parser::parseBlockBody(const std::vector<std::string>& terminators) {
    Block block;
    for (;;) {
        while (peek().kind == TokenKind::Newline || peek().kind == TokenKind::Colon) next();
        if (peek().kind == TokenKind::End) return block;
        for (const std::string& t : terminators) {
            const auto space = t.find(' ');
            if (space == std::string::npos) {
                if (atName(t) && (t != "END" || peek(1).kind == TokenKind::Newline ||
                                  peek(1).kind == TokenKind::Colon || peek(1).kind == TokenKind::End))
                    return block;
            } else if (atName(t.substr(0, space)) && atName(t.substr(space + 1), 1)) {
                return block;
            }
        }
        parseLine(block);
    }
}

// line := [label ':'] stmt {':' stmt}   (stops at a terminator the caller checks)
void Parser::parseLine(Block& into) {
    StmtPtr s = parseStatement(into);
    if (s) into.push_back(std::move(s));
    endStatement();
}

void Parser::endStatement() {
    const Token& t = peek();
    if (t.kind == TokenKind::Newline || t.kind == TokenKind::Colon) {
        next();
        return;
    }
    if (t.kind == TokenKind::End) return;
    fail(t, "unexpected '" + t.text + "' after the statement");
}

// stmt := label ':' [stmt] | IF … | FOR … | WHILE … | PRINT … | INPUT … | WHEN … | TMRSET(…) | GOTO l
//       | GOSUB l | CALL s | RETURN | SWAP a, b | RESTART [l] | motion | PAUSE | STOP | END | CLS | BEEP
//       | LANINTERRUPT[axis] | [LET] assignment
StmtPtr Parser::parseStatement(Block& into) {
    const Token& t = peek();
    if (t.kind != TokenKind::Name)
        fail(t, t.kind == TokenKind::Integer ? "line numbers are not allowed" : "expected a statement");
    auto make = [&](StmtKind kind) {
        auto s = std::make_unique<Stmt>();
        s->kind = kind;
        s->where = here();
        return s;
    };
    const std::string& w = t.upper;
    // label definition: name ':'
    if (!isKeyword(w) && peek(1).kind == TokenKind::Colon && !cat::findVariable(w) && m_symbols.count(w) == 0) {
        auto s = make(StmtKind::Label);
        s->label = w;
        next();
        next();
        if (!atLineEnd()) into.push_back(std::move(s)), s = parseStatement(into);
        return s;
    }
    if (w == "IF") return parseIf();
    if (w == "FOR") return parseFor();
    if (w == "WHILE") return parseWhile();
    if (w == "PRINT") return parsePrint();
    if (w == "INPUT") return parseInput();
    if (w == "WHEN") return parseWhen();
    if (w == "TMRSET") return parseTmrset();
    if (w == "GOTO" || w == "GOSUB" || w == "CALL") {
        auto s = make(w == "GOTO" ? StmtKind::Goto : w == "GOSUB" ? StmtKind::Gosub : StmtKind::Call);
        next();
        const Token& label = peek();
        if (label.kind != TokenKind::Name || isKeyword(label.upper))
            fail(label, w == "CALL" ? "expected a SUB name" : "expected a label");
        s->label = label.upper;
        s->where = here();
        next();
        return s;
    }
    static const std::pair<const char*, MotionKind> kMotion[] = {
        {"GO.VEL", MotionKind::GoVel},   {"GO.INCR", MotionKind::GoIncr},     {"GO.ABS", MotionKind::GoAbs},
        {"GO.HOME", MotionKind::GoHome}, {"ABORT.MOTION", MotionKind::Abort}, {"UPD.MOVE", MotionKind::UpdMove}};
    for (const auto& [name, kind] : kMotion)
        if (w == name) {
            auto s = make(StmtKind::Motion);
            s->motion = kind;
            next();
            return s;
        }
    static const std::pair<const char*, StmtKind> kSimple[] = {{"RETURN", StmtKind::Return},
                                                               {"PAUSE", StmtKind::Pause},
                                                               {"STOP", StmtKind::Stop},
                                                               {"CLS", StmtKind::Cls},
                                                               {"BEEP", StmtKind::Beep}};
    for (const auto& [name, kind] : kSimple)
        if (w == name) {
            auto s = make(kind);
            next();
            return s;
        }
    if (w == "SWAP") {
        auto s = make(StmtKind::Swap);
        next();
        s->target = parseVariable(true);
        expectOperator(",", ", between the two variables");
        s->target2 = parseVariable(true);
        return s;
    }
    if (w == "RESTART") {
        if (!m_inInterrupt) fail(t, "RESTART is allowed only in an INTERRUPT routine");
        auto s = make(StmtKind::Restart);
        next();
        if (!atLineEnd()) {
            s->label = peek().upper;
            next();
        }
        return s;
    }
    if (w == "LANINTERRUPT") {
        auto s = make(StmtKind::LanInterrupt);
        next();
        expectOperator("[", "[axis]");
        s->value = parseExpression();
        expectOperator("]", "] after the axis");
        return s;
    }
    if (w == "END") {
        const Token& what = peek(1);
        if (what.kind == TokenKind::Name && (what.upper == "IF" || what.upper == "SUB" || what.upper == "INTERRUPT"))
            fail(t, "END " + what.upper + " without " + what.upper);
        auto s = make(StmtKind::End);
        next();
        return s;
    }
    if (w == "ENDIF") fail(t, "END IF without IF");
    if (w == "ELSE" || w == "ELSEIF") fail(t, "ELSE without IF");
    if (w == "NEXT") fail(t, "NEXT without FOR");
    if (w == "WEND") fail(t, "WEND without WHILE");
    if (w == "DIM") fail(t, "DIM must come before the first executable statement");
    if (w == "PARAMS") fail(t, "the PARAMS section must be at the start of the program");
    if (w == "SUB" || w == "INTERRUPT") fail(t, w + " must come after the main program's END");
    if (w == "CONTINUE") fail(t, "CONTINUE is allowed only as a WHEN action");
    if (w == "LET") next();
    return parseAssignment();
}

// assignment := variable '=' expression
StmtPtr Parser::parseAssignment() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::Assign;
    s->where = here();
    s->target = parseVariable(true);
    expectOperator("=", "= in the assignment");
    s->value = parseExpression();
    return s;
}

} // namespace drive_core::sc750
