// servodesk-cli vars: every family's variable file, read from or sent to the drive.
#include "cli_runner.h"

#include "cli_files.h"

#include "machine/parameter_line_transfer.h"

namespace app::cli {

using machine::ParameterLineTransfer;
using machine::VariableResult;

// vars dump FILE / vars send FILE, every family: the BDS5's .VAR, the others' parameter files.
void CliRunner::vars(const CliCommand& c) {
    if (!ParameterLineTransfer::handles(m_family)) return bds5Vars(c);
    QString error;
    std::optional<QString> text;
    if (c.kind == CliCommand::Kind::VarsSend && !(text = readTextFile(c.args[0], error))) return fail(kUsage, error);
    auto* t = new ParameterLineTransfer(*m_session, this);
    connect(t, &ParameterLineTransfer::progress, this,
            [this](int done, int total) { progress(QStringLiteral("%1/%2 lines").arg(done).arg(total)); });
    connect(t, &ParameterLineTransfer::finished, this, [this, t, c](const VariableResult& r) {
        t->deleteLater();
        progress(QString());
        for (const auto& e : r.errors) {
            const QString where =
                e.sourceLine > 0 ? QStringLiteral("%1:%2").arg(c.args[0]).arg(e.sourceLine) : c.args[0];
            out(QStringLiteral("%1: %2\n").arg(where, e.text));
        }
        if (r.status == VariableResult::Status::Lost) return fail(kNoAnswer, r.summary);
        if (r.status == VariableResult::Status::Refused) return fail(kDriveError, r.summary);
        QString why;
        if (c.kind == CliCommand::Kind::VarsDump && !writeTextFile(c.args[0], r.text, why)) return fail(kUsage, why);
        out(r.summary + QLatin1Char('\n'));
        next();
    });
    if (text)
        t->send(*text);
    else
        t->dump();
}

} // namespace app::cli
