// Sc750OutputDock: a read-only terminal view of the program's output and an input line.
#include "sc750_output_dock.h"

#include <QFontDatabase>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QVBoxLayout>

namespace app {

Sc750OutputDock::Sc750OutputDock(QWidget* parent)
    : QDockWidget(tr("Output Window"), parent), m_view(new QPlainTextEdit), m_input(new QLineEdit) {
    setObjectName(QStringLiteral("sc750OutputDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_view->setReadOnly(true);
    m_view->setFont(mono);
    m_view->setMaximumBlockCount(kMaxBlocks);
    m_view->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_view->setPlaceholderText(tr("The program's PRINT output appears here while it runs (Compile > Run Program)."));
    m_view->setStyleSheet(QStringLiteral("QPlainTextEdit { background: #1e1f22; color: #d7f5d0; }"));
    m_input->setFont(mono);
    m_input->setPlaceholderText(tr("Type a line for the program's INPUT, then Enter"));
    auto* prompt = new QLabel(tr("Input:"), body);
    auto* row = new QHBoxLayout;
    row->addWidget(prompt);
    row->addWidget(m_input, 1);
    layout->addWidget(m_view, 1);
    layout->addLayout(row);
    setWidget(body);
    m_input->installEventFilter(this);
    m_view->installEventFilter(this);
    connect(m_input, &QLineEdit::returnPressed, this, [this] {
        emit inputTyped(m_input->text().toLatin1() + '\r');
        m_input->clear();
    });
}

bool Sc750OutputDock::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const bool selected = m_input->hasSelectedText() || m_view->textCursor().hasSelection();
        if (key->key() == Qt::Key_C && key->modifiers() == Qt::ControlModifier && !selected) {
            event->accept();
            if (event->type() == QEvent::KeyPress) emit stopRequested();
            return true;
        }
    }
    return QDockWidget::eventFilter(watched, event);
}

void Sc750OutputDock::display(const QByteArray& bytes) {
    QString text;
    for (const char c : bytes) {
        if (c == '\n') {
            if (!m_pendingCr) text += QLatin1Char('\n');
            m_pendingCr = false;
            continue;
        }
        if (m_pendingCr) m_pendingCr = false;
        if (c == '\r') {
            text += QLatin1Char('\n');
            m_pendingCr = true;
        } else if (c == '\b') {
            text += QStringLiteral("\u2190");
        } else if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') {
            text += QLatin1Char(c);
        }
    }
    QScrollBar* bar = m_view->verticalScrollBar();
    const bool atEnd = bar->value() == bar->maximum();
    m_view->moveCursor(QTextCursor::End);
    m_view->insertPlainText(text);
    if (atEnd) bar->setValue(bar->maximum());
}

void Sc750OutputDock::clear() {
    m_view->clear();
    m_pendingCr = false;
}

QString Sc750OutputDock::text() const {
    return m_view->toPlainText();
}

void Sc750OutputDock::focusInput() {
    m_input->setFocus();
}

} // namespace app
