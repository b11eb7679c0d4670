// EditorSizeDialog: layout and live refresh.
#include "editor_size_dialog.h"

#include <Qsci/qsciscintilla.h>

#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QVBoxLayout>

namespace editor {

EditorSizeDialog::EditorSizeDialog(QWidget* parent)
    : QDialog(parent), m_title(new QLabel(this)), m_linesBar(new QProgressBar(this)),
      m_bytesBar(new QProgressBar(this)), m_lines(new QLabel(this)), m_bytes(new QLabel(this)),
      m_verdict(new QLabel(this)) {
    setObjectName(QStringLiteral("editorSizeDialog"));
    setWindowTitle(tr("Size of Editor"));
    m_lines->setObjectName(QStringLiteral("sizeLines"));
    m_bytes->setObjectName(QStringLiteral("sizeBytes"));
    m_verdict->setObjectName(QStringLiteral("sizeVerdict"));
    m_linesBar->setRange(0, EditorSize::kMaxLines);
    m_bytesBar->setRange(0, int(EditorSize::kMaxBytes));
    m_linesBar->setTextVisible(false);
    m_bytesBar->setTextVisible(false);
    m_verdict->setWordWrap(true);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Lines:"), this), 0, 0);
    grid->addWidget(m_linesBar, 0, 1);
    grid->addWidget(m_lines, 0, 2);
    grid->addWidget(new QLabel(tr("Bytes:"), this), 1, 0);
    grid->addWidget(m_bytesBar, 1, 1);
    grid->addWidget(m_bytes, 1, 2);
    grid->setColumnMinimumWidth(1, 220);
    layout->addLayout(grid);
    layout->addWidget(m_verdict);
    auto* note = new QLabel(tr("Motion Link's editor held up to 2,000 lines and about 24,000 bytes. The "
                               "drive's own program memory is smaller: ask the drive with SIZE."),
                            this);
    note->setWordWrap(true);
    note->setStyleSheet(QStringLiteral("color: #5f6368;"));
    layout->addWidget(note);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
}

void EditorSizeDialog::setEditor(QsciScintilla* editor, const QString& name) {
    disconnect(m_textConnection);
    m_editor = editor;
    m_title->setText(tr("<b>%1</b>").arg(name.toHtmlEscaped()));
    if (editor) m_textConnection = connect(editor, &QsciScintilla::textChanged, this, &EditorSizeDialog::refresh);
    refresh();
}

QString EditorSizeDialog::figuresText() const {
    return m_lines->text() + QLatin1Char('\n') + m_bytes->text() + QLatin1Char('\n') + m_verdict->text();
}

void EditorSizeDialog::refresh() {
    m_size = m_editor ? measureText(m_editor->text(), m_editor->eolMode() == QsciScintilla::EolWindows) : EditorSize{};
    const QLocale locale;
    m_linesBar->setValue(qMin(m_size.lines, EditorSize::kMaxLines));
    m_bytesBar->setValue(int(qMin(m_size.bytes, EditorSize::kMaxBytes)));
    m_lines->setText(tr("%1 of %2 lines used, %3 left")
                         .arg(locale.toString(m_size.lines), locale.toString(EditorSize::kMaxLines),
                              locale.toString(qMax(0, m_size.linesLeft()))));
    m_bytes->setText(tr("%1 of %2 bytes used, %3 left")
                         .arg(locale.toString(qlonglong(m_size.bytes)),
                              locale.toString(qlonglong(EditorSize::kMaxBytes)),
                              locale.toString(qlonglong(qMax<std::int64_t>(0, m_size.bytesLeft())))));
    m_verdict->setText(m_size.fits() ? tr("The program fits in Motion Link's editor.")
                                     : tr("Too large for Motion Link's editor: shorten it or split it."));
    m_verdict->setStyleSheet(m_size.fits() ? QString() : QStringLiteral("color: #b3261e; font-weight: bold;"));
}

} // namespace editor
