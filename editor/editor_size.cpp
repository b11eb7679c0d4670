// Counting lines and bytes the way Motion Link's SHOW SIZE OF EDITOR did.
#include "editor_size.h"

#include <QCoreApplication>
#include <QLocale>

namespace editor {

QString EditorSize::summary() const {
    const QLocale locale;
    return QCoreApplication::translate("editor", "%1 lines, %2 bytes")
        .arg(locale.toString(lines), locale.toString(qlonglong(bytes)));
}

EditorSize measureText(const QString& text, bool crlf, bool latin1) {
    // One pass, no copies: this runs on every keystroke for the status bar.
    EditorSize size;
    const qsizetype length = text.size();
    if (length == 0) return size;
    std::int64_t bytes = 0;
    int breaks = 0;
    for (qsizetype i = 0; i < length; ++i) {
        const char16_t c = text[i].unicode();
        if (c == u'\r' || c == u'\n') {
            if (c == u'\r' && i + 1 < length && text[i + 1] == QLatin1Char('\n')) ++i;
            ++breaks;
        } else if (latin1 || c < 0x80) {
            bytes += 1;
        } else if (c < 0x800) {
            bytes += 2;
        } else if (QChar::isHighSurrogate(c)) {
            bytes += 4; // with its low surrogate
            ++i;
        } else {
            bytes += 3;
        }
    }
    const char16_t last = text[length - 1].unicode();
    const bool endsWithBreak = last == u'\n' || last == u'\r';
    size.lines = breaks + (endsWithBreak ? 0 : 1);
    size.bytes = bytes + std::int64_t(breaks) * (crlf ? 2 : 1);
    return size;
}

} // namespace editor
