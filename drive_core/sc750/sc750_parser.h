// ServoBASIC Plus parser: tokens to a ProgramAst, checking section order, declarations and statement
// forms. Never executes anything. Throws CompileFailure on the first error (compile() catches it).
#pragma once

#include "sc750_ast.h"
#include "sc750_lexer.h"

#include <map>
#include <string>
#include <vector>

namespace drive_core::sc750 {

class Parser {
public:
    explicit Parser(std::vector<Token> tokens);
    ProgramAst parse();

    // A reserved word of the language (upper case): never a label, SUB or variable name.
    static bool isKeyword(const std::string& upper);

private:
    // structure (sc750_parser.cpp)
    void parseParams();
    void parseDims();
    void parseDim(bool nonVolatile);
    void parseAfterEnd();
    Block parseBlock(const std::vector<std::string>& terminators);
    Block parseBlockBody(const std::vector<std::string>& terminators);
    void parseLine(Block& into);
    StmtPtr parseStatement(Block& into);
    StmtPtr parseIf();
    StmtPtr parseFor();
    StmtPtr parseWhile();
    StmtPtr parsePrint();
    StmtPtr parseInput();
    StmtPtr parseWhen();
    StmtPtr parseTmrset();
    StmtPtr parseAssignment();
    // expressions (sc750_parser_expr.cpp)
    ExprPtr parseExpression();
    void enter(); // one level deeper; fails beyond kMaxDepth
    ExprPtr parseXor();
    ExprPtr parseOr();
    ExprPtr parseAnd();
    ExprPtr parseNot();
    ExprPtr parseRelation();
    ExprPtr parseAdditive();
    ExprPtr parseMod();
    ExprPtr parseMultiplicative();
    ExprPtr parseUnary();
    ExprPtr parsePower();
    ExprPtr parsePrimary();
    ExprPtr parseName();
    ExprPtr parseVariable(bool forWrite); // an assignable name: user variable, array element, predefined

    // token helpers
    const Token& peek(int ahead = 0) const;
    const Token& next();
    bool atName(std::string_view upper, int ahead = 0) const;
    bool atOperator(std::string_view op) const;
    bool atLineEnd() const; // Newline, Colon or End
    void expectName(std::string_view upper, std::string_view what);
    void expectOperator(std::string_view op, std::string_view what);
    void endStatement();
    void skipBlankLines();
    Where here() const;
    [[noreturn]] void fail(const Token& at, const std::string& message) const;
    int symbolIndex(const std::string& upper) const;

    std::vector<Token> m_tokens;
    std::size_t m_pos = 0;
    ProgramAst m_ast;
    std::map<std::string, int> m_symbols;
    bool m_inInterrupt = false;
    bool m_volatileSeen = false;
    int m_depth = 0;        // nesting of expressions and blocks, bounded so no input exhausts the stack
    int m_singleLineIf = 0; // inside a single-line IF, ELSE ends a statement
};

} // namespace drive_core::sc750
