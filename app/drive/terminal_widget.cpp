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
    setColours(kBackground, kForeground);
    setCursorWidth(fontMetrics().horizontalAdvance(QLatin1Char('M')));
    document()->setDocumentMargin(6);
    m_cursor = QTextCursor(document());
    m_cursor.movePosition(QTextCursor::End);
}

void TerminalWidget::setColours(const QColor& background, const QColor& foreground) {
    m_background = background;
    QPalette colours = palette();
    colours.setColor(QPalette::Base, background);
    colours.setColor(QPalette::Text, foreground);
    setPalette(colours);
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
        normal.setColor(QPalette::Base, m_background);
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
        const bool historyKey = key->modifiers() == Qt::NoModifier &&
                                (key->key() == Qt::Key_F3 || key->key() == Qt::Key_Up || key->key() == Qt::Key_Down);
        if (historyKey || !bytesForKey(key).isEmpty() || key->matches(QKeySequence::Paste)) {
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
    if (event->modifiers() == Qt::NoModifier) {
        switch (event->key()) {
        case Qt::Key_F3: // Motion Link's LAST COMMAND: the newest line again, ready to edit or send
            m_history.resetBrowsing(); // and browse from the newest line: Up goes on to older ones
            replaceTypedLine(m_history.previous(m_typed));
            return;
        case Qt::Key_Up:
            replaceTypedLine(m_history.previous(m_typed));
            return;
        case Qt::Key_Down:
            replaceTypedLine(m_history.next(m_typed));
            return;
        default:
            break;
        }
    }
    const QByteArray bytes = bytesForKey(event);
    if (bytes.isEmpty()) {
        QPlainTextEdit::keyPressEvent(event); // scrolling, copy, select all
        return;
    }
    event->accept();
    send(bytes);
}

void TerminalWidget::send(const QByteArray& bytes) {
    // Follow the line as the drive will have it, so history can replace it with backspaces.
    for (const char byte : bytes) {
        switch (byte) {
        case '\r':
            m_history.add(std::exchange(m_typed, {}));
            break;
        case '\b':
            m_typed.chop(1);
            break;
        case '\x18':
        case '\x1b':
            m_typed.clear();
            m_history.resetBrowsing();
            break;
        default:
            if (isPrintableLatin1(char16_t(uchar(byte)))) m_typed += QChar(char16_t(uchar(byte)));
            break;
        }
    }
    if (bytes == "\x18" || bytes == "\x1b") emit urgentBytesTyped(bytes);
    else emit bytesTyped(bytes);
}

void TerminalWidget::discardTypedLine() {
    m_history.resetBrowsing();
    if (!m_typed.isEmpty()) send(QByteArray(m_typed.size(), '\b'));
}

void TerminalWidget::replaceTypedLine(const QString& line) {
    // No local echo: erase what the drive echoed with backspaces, then type the line again.
    QByteArray bytes(m_typed.size(), '\b');
    for (const QChar ch : line)
        if (isPrintableLatin1(ch.unicode())) bytes.append(char(ch.unicode()));
    if (!bytes.isEmpty()) send(bytes);
}

void TerminalWidget::pasteToDrive() {
    QString text = QApplication::clipboard()->text();
    text.replace(QStringLiteral("\r\n"), QStringLiteral("\r")).replace(QLatin1Char('\n'), QLatin1Char('\r'));
    QByteArray bytes;
    for (const QChar ch : text)
        if (ch == QLatin1Char('\r') || isPrintableLatin1(ch.unicode())) bytes.append(char(ch.unicode()));
    if (!bytes.isEmpty()) send(bytes);
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
