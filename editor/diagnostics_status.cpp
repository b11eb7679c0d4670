// DiagnosticsStatus: a flat button with a coloured dot and the counts of the current editor's diagnostics.
#include "diagnostics_status.h"

#include "bds5_diagnostics.h"
#include "bds5_language.h"
#include "program_editor.h"

namespace editor {

DiagnosticsStatus::DiagnosticsStatus(QWidget* parent) : QToolButton(parent) {
    setObjectName(QStringLiteral("diagnosticsStatus"));
    setAutoRaise(true);
    setToolButtonStyle(Qt::ToolButtonTextOnly);
    setToolTip(tr("Errors the drive would report in this program; click to go to the next one"));
    connect(this, &QToolButton::clicked, this, &DiagnosticsStatus::goToNext);
    hide();
}

void DiagnosticsStatus::setEditor(ProgramEditor* editor) {
    disconnect(m_connection);
    m_editor = editor;
    Bds5Language* language = Bds5Language::of(editor);
    setVisible(language != nullptr);
    if (!language) return;
    Bds5Diagnostics* diagnostics = language->diagnostics();
    m_connection = connect(diagnostics, &Bds5Diagnostics::changed, this, &DiagnosticsStatus::showCounts);
    showCounts(diagnostics->errorCount(), diagnostics->adviceCount());
}

void DiagnosticsStatus::showCounts(int errors, int advice) {
    QString text;
    if (errors == 0 && advice == 0)
        text = tr("\u2713 No errors");
    else if (advice == 0)
        text = errors == 1 ? tr("\u25cf 1 error") : tr("\u25cf %1 errors").arg(errors);
    else
        text = (errors == 1 ? tr("\u25cf 1 error") : tr("\u25cf %1 errors").arg(errors)) +
               (advice == 1 ? tr(", 1 note") : tr(", %1 notes").arg(advice));
    setText(text);
    setStyleSheet(errors > 0 ? QStringLiteral("QToolButton { color: #b3261e; }")
                             : (advice > 0 ? QStringLiteral("QToolButton { color: #8a5a00; }")
                                           : QStringLiteral("QToolButton { color: #1e8e3e; }")));
}

bool DiagnosticsStatus::goToNext() {
    Bds5Language* language = Bds5Language::of(m_editor);
    if (!language) return false;
    int line = 0, index = 0;
    m_editor->getCursorPosition(&line, &index);
    int next = language->diagnostics()->nextLine(line);
    if (next < 0) next = language->diagnostics()->nextLine(-1); // wrap to the first
    if (next < 0) return false;
    m_editor->setCursorPosition(next, 0);
    m_editor->ensureLineVisible(next + 1); // and its annotation
    m_editor->setFocus(Qt::OtherFocusReason);
    return true;
}

} // namespace editor
