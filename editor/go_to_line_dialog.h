// GoToLineDialog: GOTO A LINE NUMBER (^Q^I, manual L1157) with Motion Link's question "count comment
// lines?": a drive's "LINE n" counts only code lines when the program was sent without comments. Shows
// which editor line the number lands on before the user accepts. Open it with open(), never exec().
// GUI thread only.
#pragma once

#include "line_numbering.h"

#include <QDialog>
#include <QStringList>

class QLabel;
class QRadioButton;
class QSpinBox;
class QsciScintilla;

namespace editor {

class GoToLineDialog final : public QDialog {
    Q_OBJECT
public:
    static inline const QString kCountingSettingsKey = QStringLiteral("editor/goToLineCountsComments");

    // Starts at the cursor's line, counted the way the user chose last time (QSettings).
    GoToLineDialog(QsciScintilla& editor, QWidget* parent = nullptr);

    void setLineNumber(int line);
    void setCounting(LineCounting counting);
    LineCounting counting() const;
    // The 0-based editor line the number lands on, or -1 when there is no such line.
    int targetEditorLine() const;

    // Moves the editor's cursor to the target line (when there is one) and closes.
    void accept() override;

private:
    void updatePreview();

    QsciScintilla& m_editor;
    QStringList m_lines;
    QSpinBox* m_line;
    QRadioButton* m_countAll;
    QRadioButton* m_skipComments;
    QLabel* m_preview;
};

} // namespace editor
