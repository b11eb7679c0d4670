// TerminalWidget: byte rendering and key mapping.
#include "terminal_widget.h"

#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QFontDatabase>
#include <QMenu>
#include <QScrollBar>
#include <QTextBlock>
#include <QTimer>

namespace app {

namespace {
const QColor kBackground(0xfb, 0xfb, 0xf7);
const QColor kForeground(0x1c, 0x1c, 0x1c);
const QColor kBellFlash(0xff, 0xe4, 0xa8);
const QColor kNotice(0x7a, 0x7a, 0x86);
constexpr int kBellFlashMs = 150;
constexpr int kFontPointSize = 11;

bool isPrintableLatin1(char16_t u) {
    return (u >= 0x20 && u < 0x7f) || (u >= 0xa0 && u <= 0xff);
}
} // namespace

TerminalWidget::TerminalWidget(QWidget* parent) : QPlainTextEdit(parent) {
    setObjectName(QStringLiteral("terminal"));
    setReadOnly(true);
    // Selectable by keyboard too, so the caret shows where the drive's next character will appear.
    setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    setUndoRedoEnabled(false);
    setMaximumBlockCount(kMaxLines);
    setWordWrapMode(QTextOption::WrapAnywhere);
    setFocusPolicy(Qt::StrongFocus);
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSize(kFontPointSize);
    font.setStyleHint(QFont::Monospace);
    setFont(font);
    QPalette colours = palette();
    colours.setColor(QPalette::Base, kBackground);
    colours.setColor(QPalette::Text, kForeground);
    setPalette(colours);
    setCursorWidth(fontMetrics().horizontalAdvance(QLatin1Char('M')));
    document()->setDocumentMargin(6);
    m_cursor = QTextCursor(document());
    m_cursor.movePosition(QTextCursor::End);
}

void TerminalWidget::displayBytes(const QByteArray& bytes) {
    QScrollBar* bar = verticalScrollBar();
    const bool followTail = bar->value() >= bar->maximum() - 1;
    const int scrolledTo = bar->value();
    QString run;
    m_cursor.beginEditBlock();
    for (const char byte : bytes) {
        const auto c = char16_t(uchar(byte));
        if (isPrintableLatin1(c)) {
            run += QChar(c);
            continue;
        }
        if (!run.isEmpty()) writePrintable(std::exchange(run, {}));
        switch (c) {
        case u'\r':
            m_cursor.movePosition(QTextCursor::StartOfBlock);
            break;
        case u'\n':
            newLine();
            break;
        case u'\b':
            eraseBack();
            break;
        case u'\a':
            bell();
            break;
        default:
            break; // other control characters have no visible effect on a BDS5 terminal
        }
    }
    if (!run.isEmpty()) writePrintable(run);
    m_cursor.endEditBlock();
    showWriteCursor();
    bar->setValue(followTail ? bar->maximum() : scrolledTo);
}

void TerminalWidget::displayNotice(const QString& message) {
    if (m_cursor.block().length() > 1) newLine();
    QTextCharFormat format;
    format.setForeground(kNotice);
    format.setFontItalic(true);
    m_cursor.insertText(QStringLiteral("[%1]").arg(message), format);
    newLine();
    showWriteCursor();
    verticalScrollBar()->setValue(verticalScrollBar()->maximum());
}

void TerminalWidget::writePrintable(const QString& run) {
    // Overwrite what is under the cursor (after a lone CR), append past the end of the line.
    const int rest = m_cursor.block().length() - 1 - m_cursor.positionInBlock();
    if (rest > 0)
        m_cursor.movePosition(QTextCursor::Right, QTextCursor::KeepAnchor, std::min(rest, int(run.size())));
    m_cursor.insertText(run, QTextCharFormat());
}

void TerminalWidget::newLine() {
    m_cursor.movePosition(QTextCursor::EndOfBlock);
    m_cursor.insertBlock(QTextBlockFormat(), QTextCharFormat());
}

void TerminalWidget::eraseBack() {
    if (m_cursor.positionInBlock() > 0) m_cursor.deletePreviousChar();
}

void TerminalWidget::bell() {
    QApplication::beep();
    QPalette flash = palette();
    flash.setColor(QPalette::Base, kBellFlash);
    setPalette(flash);
    QTimer::singleShot(kBellFlashMs, this, [this] {
        QPalette normal = palette();
        normal.setColor(QPalette::Base, kBackground);
        setPalette(normal);
    });
}

void TerminalWidget::showWriteCursor() {
    if (textCursor().hasSelection()) return; // do not take a selection away from the user
    QTextCursor caret = m_cursor;
    caret.clearSelection();
    setTextCursor(caret);
}

QByteArray TerminalWidget::bytesForKey(const QKeyEvent* event) {
    const Qt::KeyboardModifiers mods =
        event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier);
    if (mods == Qt::ControlModifier) {
        // The BDS5's attention characters: ^X stops motion and the program, ^V is the multidrop wake-up.
        if (event->key() == Qt::Key_X) return QByteArrayLiteral("\x18");
        if (event->key() == Qt::Key_V) return QByteArrayLiteral("\x16");
        return {};
    }
    if (mods != Qt::NoModifier) return {};
    switch (event->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
        return QByteArrayLiteral("\r");
    case Qt::Key_Backspace:
        return QByteArrayLiteral("\b");
    case Qt::Key_Escape:
        return QByteArrayLiteral("\x1b");
    default:
        break;
    }
    QByteArray bytes;
    for (const QChar ch : event->text())
        if (isPrintableLatin1(ch.unicode())) bytes.append(char(ch.unicode()));
    return bytes;
}

bool TerminalWidget::event(QEvent* event) {
    // Keys the drive needs (Esc, ^X, ^V, plain characters) must reach keyPressEvent, not a shortcut.
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (!bytesForKey(key).isEmpty() || key->matches(QKeySequence::Paste)) {
            event->accept();
            return true;
        }
    }
    return QPlainTextEdit::event(event);
}

void TerminalWidget::keyPressEvent(QKeyEvent* event) {
    if (event->modifiers() == (Qt::ControlModifier | Qt::ShiftModifier) && event->key() == Qt::Key_V) {
        pasteToDrive();
        return;
    }
    if (event->modifiers() == Qt::ShiftModifier && event->key() == Qt::Key_Insert) {
        pasteToDrive();
        return;
    }
    const QByteArray bytes = bytesForKey(event);
    if (bytes.isEmpty()) {
        QPlainTextEdit::keyPressEvent(event); // scrolling, copy, select all
        return;
    }
    event->accept();
    emit bytesTyped(bytes);
}

void TerminalWidget::pasteToDrive() {
    QString text = QApplication::clipboard()->text();
    text.replace(QStringLiteral("\r\n"), QStringLiteral("\r")).replace(QLatin1Char('\n'), QLatin1Char('\r'));
    QByteArray bytes;
    for (const QChar ch : text)
        if (ch == QLatin1Char('\r') || isPrintableLatin1(ch.unicode())) bytes.append(char(ch.unicode()));
    if (!bytes.isEmpty()) emit bytesTyped(bytes);
}

void TerminalWidget::contextMenuEvent(QContextMenuEvent* event) {
    auto* menu = new QMenu(this);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    QAction* copy = menu->addAction(tr("&Copy"), this, &QPlainTextEdit::copy);
    copy->setEnabled(textCursor().hasSelection());
    menu->addAction(tr("&Paste to Drive"), this, &TerminalWidget::pasteToDrive);
    menu->addSeparator();
    menu->addAction(tr("Select &All"), this, &QPlainTextEdit::selectAll);
    menu->addAction(tr("C&lear"), this, [this] {
        clear();
        m_cursor = QTextCursor(document());
    });
    menu->popup(event->globalPos());
}

} // namespace app
