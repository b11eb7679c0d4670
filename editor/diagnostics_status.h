// DiagnosticsStatus: the status-bar cell that counts the drive's errors in the current program
// ("2 errors", "No errors") and, when clicked, moves the cursor to the next one. Follows the editor
// setEditor() names; hidden for editors without BDS5 support. GUI thread only.
#pragma once

#include <QPointer>
#include <QToolButton>

namespace editor {

class ProgramEditor;

class DiagnosticsStatus final : public QToolButton {
    Q_OBJECT
public:
    explicit DiagnosticsStatus(QWidget* parent = nullptr);

    void setEditor(ProgramEditor* editor);
    // Moves the editor's cursor to the next line with a diagnostic (wrapping); false when there is none.
    bool goToNext();

private:
    void showCounts(int errors, int advice);

    QPointer<ProgramEditor> m_editor;
    QMetaObject::Connection m_connection;
};

} // namespace editor
