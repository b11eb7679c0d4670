// GoToLineDialog: layout, preview and the jump.
#include "go_to_line_dialog.h"

#include <Qsci/qsciscintilla.h>

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace editor {

GoToLineDialog::GoToLineDialog(QsciScintilla& editor, QWidget* parent)
    : QDialog(parent), m_editor(editor), m_lines(splitLines(editor.text())), m_line(new QSpinBox(this)),
      m_countAll(new QRadioButton(tr("&Count comment lines \u2014 line numbers as in the editor"), this)),
      m_skipComments(new QRadioButton(
          tr("&Don't count comment lines \u2014 for a drive's LINE n when the program was sent without "
             "comments"),
          this)),
      m_preview(new QLabel(this)) {
    setObjectName(QStringLiteral("goToLineDialog"));
    setWindowTitle(tr("Go to Line"));
    m_line->setObjectName(QStringLiteral("lineNumber"));
    m_preview->setObjectName(QStringLiteral("goToLinePreview"));
    m_preview->setTextFormat(Qt::PlainText);
    m_line->setRange(1, qMax(1, int(m_lines.size())));

    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    form->addRow(tr("&Line number:"), m_line);
    layout->addLayout(form);
    layout->addWidget(m_countAll);
    layout->addWidget(m_skipComments);
    layout->addWidget(m_preview);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::accepted, this, &GoToLineDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &GoToLineDialog::reject);
    connect(m_line, &QSpinBox::valueChanged, this, &GoToLineDialog::updatePreview);
    connect(m_countAll, &QRadioButton::toggled, this, &GoToLineDialog::updatePreview);

    const bool countAll = QSettings().value(kCountingSettingsKey, true).toBool();
    (countAll ? m_countAll : m_skipComments)->setChecked(true);
    int line = 0;
    int index = 0;
    editor.getCursorPosition(&line, &index);
    const int current = driveLineForEditorLine(m_lines, line, counting());
    setLineNumber(current > 0 ? current : 1);
    m_line->selectAll();
    updatePreview();
}

void GoToLineDialog::setLineNumber(int line) {
    m_line->setValue(line);
}

void GoToLineDialog::setCounting(LineCounting counting) {
    (counting == LineCounting::AllLines ? m_countAll : m_skipComments)->setChecked(true);
}

LineCounting GoToLineDialog::counting() const {
    return m_countAll->isChecked() ? LineCounting::AllLines : LineCounting::WithoutComments;
}

int GoToLineDialog::targetEditorLine() const {
    return editorLineForDriveLine(m_lines, m_line->value(), counting());
}

void GoToLineDialog::accept() {
    QSettings().setValue(kCountingSettingsKey, counting() == LineCounting::AllLines);
    const int target = targetEditorLine();
    if (target >= 0) {
        m_editor.setCursorPosition(target, 0);
        m_editor.ensureLineVisible(target);
        m_editor.setFocus();
    }
    QDialog::accept();
}

void GoToLineDialog::updatePreview() {
    const int target = targetEditorLine();
    const int total = driveLineCount(m_lines, counting());
    if (target < 0) {
        m_preview->setText(tr("There are only %n counted lines.", nullptr, total));
        return;
    }
    QString text = m_lines.value(target).trimmed();
    if (text.size() > 48) text = text.left(47) + QChar(0x2026);
    m_preview->setText(tr("Editor line %1:  %2").arg(target + 1).arg(text));
}

} // namespace editor
