// BDS5 outline: every line through drive_core's lexLine, labels recognised by Bds5Program's rules.
#include "bds5_outline.h"

#include "drive_core/bds5/bds5_lexer.h"
#include "drive_core/bds5/bds5_program.h"

#include <QRegularExpression>
#include <QStringList>

namespace editor {

namespace dbds5 = drive_core::bds5;

namespace {

// What each dedicated label is for (Table 4.5, L4603-4615), shown when its line has no comment.
QString roleOf(dbds5::DedicatedLabel which) {
    switch (which) {
    case dbds5::DedicatedLabel::PowerUp: return QStringLiteral("runs at power-up");
    case dbds5::DedicatedLabel::Auto: return QStringLiteral("one cycle per CYCLE input edge");
    case dbds5::DedicatedLabel::Manual: return QStringLiteral("runs while the MANUAL input is on");
    case dbds5::DedicatedLabel::Error: return QStringLiteral("runs on a breaking error; last label");
    case dbds5::DedicatedLabel::Variable: return QStringLiteral("variable input (^V)");
    case dbds5::DedicatedLabel::Background: return QStringLiteral("lowest-priority task");
    default: return {};
    }
}

} // namespace

Outline bds5Outline(const QString& programText) {
    Outline out;
    const QStringList lines = programLines(programText);
    for (qsizetype n = 0; n < lines.size(); ++n) {
        const QString& text = lines[n];
        // Only a line whose first entry ends in $ can be a label: skip the rest without lexing.
        const QString trimmed = text.trimmed();
        const qsizetype firstBlank = trimmed.indexOf(QRegularExpression(QStringLiteral("\\s")));
        if (!trimmed.left(firstBlank < 0 ? trimmed.size() : firstBlank).endsWith(QLatin1Char('$'))) continue;
        const QByteArray utf8 = text.toUtf8();
        const auto lexed = dbds5::lexLine(std::string_view(utf8.constData(), std::size_t(utf8.size())));
        const auto* line = std::get_if<dbds5::LexedLine>(&lexed);
        if (!line || line->entries.empty()) continue;
        OutlineEntry entry;
        entry.line = int(n);
        entry.name = QString::fromStdString(line->entries.front().text);
        const QString comment = QString::fromStdString(line->comment).trimmed();
        if (dbds5::Bds5Program::numericLabel(*line)) {
            entry.kind = OutlineEntry::Kind::Label;
            entry.detail = comment;
        } else if (const auto which = dbds5::Bds5Program::dedicatedLabel(*line)) {
            const bool alarm = *which == dbds5::DedicatedLabel::AlarmA || *which == dbds5::DedicatedLabel::AlarmB ||
                               *which == dbds5::DedicatedLabel::AlarmC;
            entry.kind = alarm ? OutlineEntry::Kind::Handler : OutlineEntry::Kind::Task;
            if (alarm) {
                QStringList rest;
                for (std::size_t i = 1; i < line->entries.size(); ++i)
                    rest << QString::fromStdString(line->entries[i].text);
                entry.detail = rest.join(QLatin1Char(' '));
                if (!comment.isEmpty()) entry.detail += QStringLiteral(" \u2014 ") + comment;
            } else {
                entry.detail = comment.isEmpty() ? roleOf(*which) : comment;
            }
        } else {
            continue;
        }
        out.push_back(std::move(entry));
    }
    return out;
}

} // namespace editor
