// BDS5 prompt and error-line recognition.
#include "bds5_protocol.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QRegularExpression>

namespace serialport {

QString modeName(Bds5Mode mode) {
    switch (mode) {
    case Bds5Mode::Unknown: return QStringLiteral("Unknown");
    case Bds5Mode::Interactive: return QStringLiteral("Interactive");
    case Bds5Mode::Monitor: return QStringLiteral("Monitor");
    case Bds5Mode::SingleStep: return QStringLiteral("Single-step");
    case Bds5Mode::Editor: return QStringLiteral("Editor");
    case Bds5Mode::ProgramLoad: return QStringLiteral("Program load");
    case Bds5Mode::Insert: return QStringLiteral("Editor insert");
    case Bds5Mode::Find: return QStringLiteral("Editor find");
    case Bds5Mode::Change: return QStringLiteral("Editor change");
    case Bds5Mode::Running: return QStringLiteral("Running");
    case Bds5Mode::Asleep: return QStringLiteral("Asleep (multidrop)");
    }
    return {};
}

std::optional<QString> trailingPrompt(const QString& text) {
    // Single-drop prompts: -->, ==>, s-->, s-A> ..., e->, l->, i->, f->, c->.
    // Multidrop prompts: the axis ID, the mode character, '>' (A->, A=>, As>, Ae>, ...).
    static const QRegularExpression kPrompt(
        QStringLiteral("\\r\\n(-->|==>|s-[-ABCV*]>|[elifc]->|[0-9A-Z][-=selifc]>)$"));
    const auto match = kPrompt.match(text);
    if (!match.hasMatch()) return std::nullopt;
    return match.captured(1);
}

Bds5Mode modeOfPrompt(const QString& prompt) {
    if (prompt == QLatin1String("-->")) return Bds5Mode::Interactive;
    if (prompt == QLatin1String("==>")) return Bds5Mode::Monitor;
    if (prompt.startsWith(QLatin1String("s-"))) return Bds5Mode::SingleStep;
    // Multidrop prompts start with the axis ID (a digit or capital); the mode character slides right.
    const bool multidrop = !prompt.isEmpty() && (prompt[0].isDigit() || prompt[0].isUpper());
    const QChar c = multidrop ? (prompt.size() > 1 ? prompt[1] : QChar()) : (prompt.isEmpty() ? QChar() : prompt[0]);
    switch (c.toLatin1()) {
    case '-': return Bds5Mode::Interactive;
    case '=': return Bds5Mode::Monitor;
    case 's': return Bds5Mode::SingleStep;
    case 'e': return Bds5Mode::Editor;
    case 'l': return Bds5Mode::ProgramLoad;
    case 'i': return Bds5Mode::Insert;
    case 'f': return Bds5Mode::Find;
    case 'c': return Bds5Mode::Change;
    default: return Bds5Mode::Unknown;
    }
}

std::optional<char> addressEchoEndingIn(const QString& text) {
    static const QRegularExpression kAddress(QStringLiteral("(?:^|\\n|>)ADDR *=? *(\\d{1,3})\\r\\n$"),
                                             QRegularExpression::CaseInsensitiveOption);
    const auto match = kAddress.match(text);
    if (!match.hasMatch()) return std::nullopt;
    const int id = match.captured(1).toInt();
    if ((id >= '0' && id <= '9') || (id >= 'A' && id <= 'Z')) return char(id);
    return std::nullopt;
}

// With DEP on the drive cuts its messages to 40 characters (L6104), which can leave "ERR 83 '9001'" with no
// message: the entry is still the entry, and the message comes from the catalog.
std::optional<Bds5ErrorLine> parseErrorLine(const QString& line) {
    static const QRegularExpression kError(
        QStringLiteral("^\\x07?ERR (\\d+)(?: LINE (\\d+))?(?: '(.*)')?(?:\\s+(\\S.*?))?\\s*$"));
    const auto match = kError.match(line);
    if (!match.hasMatch()) return std::nullopt;
    Bds5ErrorLine error{match.captured(1).toInt(), match.captured(2).toInt(), match.captured(3),
                        match.captured(4)};
    if (error.message.isEmpty())
        if (const auto* info = drive_core::catalog::bds5::findError(error.code))
            error.message = QString::fromUtf8(info->message.data(), qsizetype(info->message.size()));
    return error;
}

int bds5CommandSilenceMs(const QString& line, Bds5Mode mode) {
    switch (mode) {
    case Bds5Mode::ProgramLoad:
    case Bds5Mode::Insert:
    case Bds5Mode::Find:
    case Bds5Mode::Change: return 150; // stored or searched at once: only the echo and the prompt
    default: break;
    }
    const QString word = line.trimmed().section(QLatin1Char(' '), 0, 0).toUpper();
    if (word == QLatin1String("TUNE")) return 30000;                              // shakes the motor
    if (word == QLatin1String("EN") || word == QLatin1String("ENABLE")) return 5000; // "a few seconds"
    // Commands that hold the command processor: waits, program starts, label calls.
    static const QRegularExpression kHolds(QStringLiteral("^(W|RUN|GOSUB|GOTO|TIL|DUMP|PLAY|\\d+\\$)$"));
    if (kHolds.match(word).hasMatch()) return 3000;
    return 500;
}

} // namespace serialport
