// EditorSizeDialog: SHOW SIZE OF EDITOR (^Q^O, manual L1158) — lines and bytes used against Motion
// Link's 2,000 lines / 24,000 bytes, and what is left, kept up to date while it stays open. Non-modal:
// show() it. GUI thread only.
#pragma once

#include "editor_size.h"

#include <QDialog>
#include <QPointer>

class QLabel;
class QProgressBar;
class QsciScintilla;

namespace editor {

class EditorSizeDialog final : public QDialog {
    Q_OBJECT
public:
    explicit EditorSizeDialog(QWidget* parent = nullptr);

    // The editor measured from now on (follows edits); nullptr shows nothing.
    void setEditor(QsciScintilla* editor, const QString& name);
    EditorSize size() const { return m_size; }
    // The dialog's figures as text, one line each (for tests and the clipboard).
    QString figuresText() const;

private:
    void refresh();

    QPointer<QsciScintilla> m_editor;
    QMetaObject::Connection m_textConnection;
    EditorSize m_size;
    QLabel* m_title;
    QProgressBar* m_linesBar;
    QProgressBar* m_bytesBar;
    QLabel* m_lines;
    QLabel* m_bytes;
    QLabel* m_verdict;
};

} // namespace editor
