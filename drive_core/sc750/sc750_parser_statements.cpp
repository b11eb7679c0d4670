// ServoBASIC Plus parser: the compound and special statements (IF, FOR, WHILE, PRINT, INPUT, WHEN, TMRSET).
#include "sc750_parser.h"

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

// if := IF expr THEN (nl block {ELSE IF expr THEN nl block} [ELSE [stmts] nl block] END IF
//                    | stmt {: stmt} [ELSE stmt {: stmt}])
StmtPtr Parser::parseIf() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::If;
    s->where = here();
    const Token& opener = peek();
    next();
    Branch first;
    first.condition = parseExpression();
    expectName("THEN", "THEN after the IF condition");
    if (peek().kind != TokenKind::Newline && peek().kind != TokenKind::End) {
        // single-line IF: the rest of the line belongs to it
        ++m_singleLineIf;
        Branch* branch = &first;
        s->branches.push_back(std::move(first));
        branch = &s->branches.back();
        for (;;) {
            if (atName("ELSE")) {
                next();
                s->branches.push_back(Branch{});
                branch = &s->branches.back();
                continue;
            }
            StmtPtr inner = parseStatement(branch->body);
            if (inner) branch->body.push_back(std::move(inner));
            if (peek().kind == TokenKind::Colon) {
                next();
                continue;
            }
            if (atName("ELSE")) continue;
            break;
        }
        --m_singleLineIf;
        return s;
    }
    const std::vector<std::string> terms = {"ELSE", "ELSEIF", "END IF", "ENDIF"};
    first.body = parseBlock(terms);
    s->branches.push_back(std::move(first));
    for (;;) {
        if (peek().kind == TokenKind::End) fail(opener, "IF without END IF");
        if (atName("ENDIF")) {
            next();
            return s;
        }
        if (atName("END")) {
            next();
            next();
            return s;
        }
        const bool elseIf = atName("ELSEIF") || (atName("ELSE") && atName("IF", 1));
        if (s->branches.back().condition == nullptr)
            fail(peek(), elseIf ? "ELSE IF after ELSE" : "second ELSE in one IF");
        Branch b;
        if (elseIf) {
            next();
            if (atName("IF")) next();
            b.condition = parseExpression();
            expectName("THEN", "THEN after the ELSE IF condition");
            endStatement();
        } else {
            next(); // ELSE
            while (!atLineEnd()) {
                StmtPtr inner = parseStatement(b.body); // ELSE GOTO wait_loop (L2057)
                if (inner) b.body.push_back(std::move(inner));
                if (peek().kind == TokenKind::Colon) next();
            }
        }
        Block more = parseBlock(terms);
        for (StmtPtr& m : more) b.body.push_back(std::move(m));
        s->branches.push_back(std::move(b));
    }
}

// for := FOR var '=' expr TO expr [STEP expr] nl block NEXT [var]
StmtPtr Parser::parseFor() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::For;
    s->where = here();
    const Token& opener = peek();
    next();
    s->target = parseVariable(true);
    if (s->target->kind != ExprKind::User || !s->target->args.empty() ||
        m_ast.symbols[std::size_t(s->target->symbol)].type == ValueType::String)
        fail(opener, "the FOR variable must be a numeric user variable");
    expectOperator("=", "= after the FOR variable");
    s->value = parseExpression();
    expectName("TO", "TO in the FOR statement");
    s->limit = parseExpression();
    if (atName("STEP")) {
        next();
        s->step = parseExpression();
    }
    s->body = parseBlock({"NEXT"});
    if (peek().kind == TokenKind::End) fail(opener, "FOR without NEXT");
    next(); // NEXT
    if (peek().kind == TokenKind::Name && !atLineEnd()) {
        if (peek().upper != m_ast.symbols[std::size_t(s->target->symbol)].name)
            fail(peek(), "NEXT " + peek().text + " does not match FOR " + s->target->where.near);
        next();
    }
    return s;
}

// while := WHILE expr (':' | nl) block WEND
StmtPtr Parser::parseWhile() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::While;
    s->where = here();
    const Token& opener = peek();
    next();
    s->value = parseExpression();
    s->body = parseBlock({"WEND"});
    if (peek().kind == TokenKind::End) fail(opener, "WHILE without WEND");
    next();
    return s;
}

// print := PRINT {expr | ';' | ','}
StmtPtr Parser::parsePrint() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::Print;
    s->where = here();
    next();
    while (!atLineEnd()) {
        PrintItem item;
        if (!atOperator(";") && !atOperator(",")) item.expr = parseExpression();
        if (atOperator(";") || atOperator(",")) {
            item.separator = next().text[0];
        } else if (!atLineEnd()) {
            fail(peek(), "expected ; or , between PRINT items");
        }
        s->items.push_back(std::move(item));
    }
    return s;
}

// input := INPUT ["prompt" (';' | ',')] variable
StmtPtr Parser::parseInput() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::Input;
    s->where = here();
    next();
    if (peek().kind == TokenKind::String) {
        s->hasPrompt = true;
        s->prompt = next().text;
        if (!atOperator(";") && !atOperator(",")) fail(peek(), "expected ; or , after the INPUT prompt");
        s->promptQuestion = next().text == ";";
    } else {
        s->promptQuestion = true;
    }
    s->target = parseVariable(true);
    return s;
}

// when := WHEN (INPn '=' 0|1 | (POS.COMMAND|POSITION|ENCPOS|ANALOG.IN) ('>'|'<') expr) ',' action
// action := OUTn '=' 0|1 | RATIO '=' expr | GO.VEL | GO.INCR | GO.ABS | GO.HOME | ABORT.MOTION | UPD.MOVE
//         | PAUSE | CONTINUE
StmtPtr Parser::parseWhen() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::When;
    s->where = here();
    next();
    const Token& cond = peek();
    WhenSpec& w = s->when;
    static const char* kSources[] = {"POS.COMMAND", "POSITION", "ENCPOS", "ANALOG.IN"};
    const std::string& c = cond.upper;
    if (c.size() > 3 && c.rfind("INP", 0) == 0 && cat::findVariable(c) && c != "INPUTS") {
        w.source = std::stoi(c.substr(3));
        next();
        expectOperator("=", "= 0 or = 1 after " + cond.text);
        const Token& level = peek();
        if (level.kind != TokenKind::Integer || (level.number != 0 && level.number != 1))
            fail(level, "an input condition compares with 0 or 1");
        w.relation = 0;
        w.value = std::make_unique<Expr>();
        w.value->value = level.number;
        w.value->where = here();
        next();
    } else {
        for (int i = 0; i < 4; ++i)
            if (c == kSources[i]) w.source = 17 + i;
        if (w.source == 0)
            fail(cond, "a WHEN condition is INPn = 0|1, or POS.COMMAND, POSITION, ENCPOS or ANALOG.IN > or < value");
        next();
        if (atOperator(">"))
            w.relation = 1;
        else if (atOperator("<"))
            w.relation = 2;
        else
            fail(peek(), "expected > or < after " + cond.text);
        next();
        w.value = parseExpression();
    }
    expectOperator(",", ", between the WHEN condition and its action");
    const Token& act = peek();
    const std::string& a = act.upper;
    static const char* kActions[] = {"GO.VEL", "GO.INCR", "GO.ABS", "GO.HOME", "ABORT.MOTION", "UPD.MOVE", "PAUSE"};
    if (a == "CONTINUE") {
        w.action = 0;
        next();
    } else if (a.size() > 3 && a.rfind("OUT", 0) == 0 && a != "OUTPUTS" && cat::findVariable(a)) {
        w.action = 1;
        w.actionArg = std::stoi(a.substr(3));
        next();
        expectOperator("=", "= 0 or = 1 after " + act.text);
        const Token& level = peek();
        if (level.kind != TokenKind::Integer || (level.number != 0 && level.number != 1))
            fail(level, "a WHEN output action sets 0 or 1");
        w.actionValue = std::make_unique<Expr>();
        w.actionValue->value = level.number;
        w.actionValue->where = here();
        next();
    } else if (a == "RATIO") {
        w.action = 2;
        next();
        expectOperator("=", "= after RATIO");
        w.actionValue = parseExpression();
    } else {
        for (int i = 0; i < 7; ++i)
            if (a == kActions[i]) w.action = 3 + i;
        if (w.action == 0)
            fail(act, "a WHEN action is OUTn = 0|1, RATIO = value, GO.VEL, GO.INCR, GO.ABS, GO.HOME, "
                      "ABORT.MOTION, UPD.MOVE, PAUSE or CONTINUE");
        next();
    }
    return s;
}

// tmrset := TMRSET '(' n ',' LEVEL|PULSE ',' delay ',' OUTm '=' v ',' INPk '=' v [',' [POUTj '=' v]] ')'
StmtPtr Parser::parseTmrset() {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::Tmrset;
    s->where = here();
    next();
    expectOperator("(", "( after TMRSET");
    s->args.push_back(parseExpression());
    expectOperator(",", ", after the timer number");
    if (atName("LEVEL"))
        s->tmrset.pulse = false;
    else if (atName("PULSE"))
        s->tmrset.pulse = true;
    else
        fail(peek(), "expected LEVEL or PULSE");
    next();
    expectOperator(",", ", after LEVEL or PULSE");
    s->args.push_back(parseExpression());
    auto pin = [&](const char* prefix, int maxNumber, int& number, int& level) {
        const Token& t = peek();
        const std::string p(prefix);
        if (t.kind != TokenKind::Name || t.upper.rfind(p, 0) != 0 || t.upper.size() == p.size() ||
            t.upper.find_first_not_of("0123456789", p.size()) != std::string::npos)
            fail(t, "expected " + p + "n = 0|1");
        number = std::stoi(t.upper.substr(p.size()));
        if (number < 1 || number > maxNumber) fail(t, p + " number out of range 1-" + std::to_string(maxNumber));
        next();
        expectOperator("=", "= after " + t.text);
        const Token& v = peek();
        if (v.kind != TokenKind::Integer || (v.number != 0 && v.number != 1)) fail(v, "expected 0 or 1");
        level = int(v.number);
        next();
    };
    expectOperator(",", ", after the delay");
    pin("OUT", 12, s->tmrset.output, s->tmrset.outputLevel);
    expectOperator(",", ", after the output");
    pin("INP", 16, s->tmrset.input, s->tmrset.inputLevel);
    if (atOperator(",")) {
        next();
        if (!atOperator(")")) pin("POUT", 12, s->tmrset.positionOutput, s->tmrset.positionLevel);
    }
    expectOperator(")", ") at the end of TMRSET");
    return s;
}

} // namespace drive_core::sc750
