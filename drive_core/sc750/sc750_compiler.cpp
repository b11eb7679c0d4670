// The compiler driver: runs the stages in order and turns the first failure into a result.
#include "sc750_compiler.h"

#include "sc750_bin.h"
#include "sc750_codegen.h"
#include "sc750_lexer.h"
#include "sc750_parser.h"

namespace drive_core::sc750 {

CompileResult compile(std::string_view source, CompileOptions options) {
    CompileResult result;
    try {
        Parser parser(Lexer::tokenize(source));
        const ProgramAst ast = parser.parse();
        CodeGenerator generator;
        result.program = generator.generate(ast, options.turbo);
        result.bin = writeBin(result.program);
    } catch (const CompileFailure& failure) {
        result.error = failure.error;
    }
    return result;
}

} // namespace drive_core::sc750
