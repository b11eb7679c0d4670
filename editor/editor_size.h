// The size of an editor's text measured against Motion Link's editor capacity: 2,000 lines and about
// 24,000 bytes (manual L1158). Pure; any thread.
#pragma once

#include <QString>

#include <cstdint>

namespace editor {

struct EditorSize {
    static constexpr int kMaxLines = 2000;
    static constexpr std::int64_t kMaxBytes = 24000;

    int lines = 0;
    std::int64_t bytes = 0;

    int linesLeft() const { return kMaxLines - lines; }
    std::int64_t bytesLeft() const { return kMaxBytes - bytes; }
    bool fits() const { return lines <= kMaxLines && bytes <= kMaxBytes; }
    // "37 lines, 812 bytes" — for the status bar.
    QString summary() const;
};

// Measures text as it would be written to disk: in UTF-8 (or Latin-1 when latin1 is true) with CR LF
// line ends when crlf is true.
// chosen: bytes are counted as saved, CR LF included for DOS files, since that is what filled Motion
// Link's memory; a line break after the last line does not start another line.
EditorSize measureText(const QString& text, bool crlf, bool latin1 = false);

} // namespace editor
