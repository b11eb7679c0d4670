// MPL character classes per line (digest §12 "Tokenizer character classes").
#include "mpl_line_styler.h"

#include <QSet>

#include <cctype>

namespace editor {

namespace {

char upper(char c) {
    return char(std::toupper(static_cast<unsigned char>(c)));
}
bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool isHex(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}
bool isDisplay(char c) {
    return c == '?' || c == '!' || c == '%' || c == '&';
}

constexpr std::size_t kProgramCapacity = 1940; // Pmc960Program::kCapacity

// Commands whose numbers are hex whatever THC says (digest §5.1).
bool takesHex(const QByteArray& command) {
    static const QSet<QByteArray> kHex{"B",   "F",   "E",   "Q",   "U",   "OB",  "SP",
                                       "THC", "THR", "THL", "THM", "THP", "THS", "R"};
    return kHex.contains(command) || command == "TGE" || command == "TGB";
}

// Reads one command name at i (upper case); empty if the letter starts no command.
QByteArray commandAt(const QByteArray& line, qsizetype i) {
    const char c = upper(line[i]);
    static const QByteArray kPlain = "ABCDEFGHIJLNPQRUV";
    if (kPlain.contains(c)) return QByteArray(1, c);
    const char next = i + 1 < line.size() ? upper(line[i + 1]) : 0;
    if (c == 'O' && (next == 'A' || next == 'B')) return QByteArray(1, c) + next;
    if (c == 'S' && QByteArray("BDEFILMNPSTVWY").contains(next) && next != 0) return QByteArray(1, c) + next;
    if (c == 'T') {
        if (next == 'F' || next == 'G' || isDisplay(next))
            return next == 'F' || next == 'G' ? "T" + QByteArray(1, next) : "T";
        const char third = i + 2 < line.size() ? upper(line[i + 2]) : 0;
        const QByteArray sub = next == 'H' ? "ABCILMPRS" : next == 'L' ? "BPV" : next == 'U' ? "ABHPSV" : "";
        if (!sub.isEmpty() && third != 0 && sub.contains(third)) return "T" + QByteArray(1, next) + third;
        if (!sub.isEmpty() && isDisplay(third)) return "T" + QByteArray(1, next);
    }
    return {};
}

} // namespace

QByteArray styleMplLine(const QByteArray& line) {
    QByteArray styles(line.size(), MplDefault);
    qsizetype i = 0;
    if (line.startsWith('@')) { // @<label><comment>
        styles[0] = MplLabel;
        if (line.size() > 1) styles[1] = MplLabel;
        for (qsizetype k = 2; k < line.size(); ++k) styles[k] = MplComment;
        return styles;
    }
    QByteArray command;
    while (i < line.size()) {
        const char c = line[i];
        if (c == ' ' || c == '.' || c == '\r' || c == '\n' || c == '\t') {
            ++i;
            continue;
        }
        if (command.isEmpty()) { // a command starts
            command = std::isalpha(static_cast<unsigned char>(c)) ? commandAt(line, i) : QByteArray();
            if (command.isEmpty()) {
                styles[i++] = MplError;
                continue;
            }
            for (qsizetype k = 0; k < command.size(); ++k) styles[i++] = MplCommand;
            const bool takesLabel = command == "B" || command == "F" || command == "L" || command == "P" ||
                                    command == "THI" || command.startsWith("TL");
            if (takesLabel && i < line.size() && line[i] != '\r') styles[i++] = MplLabel;
            if (command == "L" && i < line.size() && QByteArray("XYZxyz").contains(line[i])) styles[i++] = MplCommand;
            continue;
        }
        const bool hex = takesHex(command) || (command == "TG" && i > 0 && QByteArray("EBeb").contains(line[i - 1]));
        if (isDigit(c) || (hex && isHex(c))) {
            styles[i++] = MplNumber;
        } else if (c == '+' || c == '-' || c == '*' || c == ':' || c == '{' || c == '}' || c == '|') {
            styles[i++] = MplSign;
            if (command == "N" && c != '*' && c != ':') command.clear(); // N ends at its sign
        } else if (c == ',' || c == ';' || c == '^') {
            styles[i++] = MplSync;
            if (c == '^' && command == "C") command.clear();
        } else if (isDisplay(c)) {
            styles[i++] = MplDisplay;
            if (c != '%') command.clear(); // a display character ends the command
        } else if (command == "TG" && QByteArray("PVTFEBXLpvtfebxl").contains(c)) {
            styles[i++] = MplCommand; // TGP++V5--: several registers on one line
        } else if (command == "SL" && QByteArray("FRfr").contains(c)) {
            styles[i++] = MplCommand;
        } else {
            styles[i++] = MplError;
        }
    }
    return styles;
}

QList<MplDiagnostic> checkMplProgram(const QByteArray& text) {
    QList<MplDiagnostic> out;
    const QList<QByteArray> lines = text.split('\n');
    QSet<char> defined;
    for (const QByteArray& raw : lines) {
        const QByteArray line = raw.trimmed();
        if (line.size() >= 2 && line[0] == '@') defined.insert(line[1]);
    }
    std::size_t stored = 0;
    for (int n = 0; n < lines.size(); ++n) {
        QByteArray line = lines[n];
        if (line.endsWith('\r')) line.chop(1);
        stored += std::size_t(line.size() - line.count(' ')) + (line.trimmed().isEmpty() ? 0 : 1);
        const QByteArray styles = styleMplLine(line);
        for (qsizetype k = 0; k < line.size(); ++k) {
            if (styles[k] == MplError) {
                out.append({n, int(k), QStringLiteral("'%1' is no MPL command here").arg(QChar::fromLatin1(line[k]))});
                break;
            }
            const bool branch = styles[k] == MplLabel && k > 0 && styles[k - 1] == MplCommand &&
                                QByteArray("BFLbfl").contains(line[k - 1]) && line[0] != '@';
            if (branch && line[k] != '|' && !defined.contains(line[k]))
                out.append(
                    {n, int(k), QStringLiteral("label '%1' is not defined (#C2)").arg(QChar::fromLatin1(line[k]))});
            if (styles[k] == MplLabel && (line[k] < 0x22 || line[k] > 0x7A) && line[k] != '|')
                out.append({n, int(k), QStringLiteral("invalid label (#C5): labels are \" to z")});
        }
    }
    if (stored > kProgramCapacity)
        out.append({0, 0,
                    QStringLiteral("the program needs %1 bytes; the buffer holds %2 (#C1)")
                        .arg(stored)
                        .arg(kProgramCapacity)});
    return out;
}

} // namespace editor
