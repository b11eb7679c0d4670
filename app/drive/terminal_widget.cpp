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
const QColor kFolded(0x3a, 0x5a, 0x8c);
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

    // Following the end is the user's choice, read from their own scrolling only (wheel, scroll bar, keys):
    // a hidden or resized terminal changes the scroll range and the position with it, which says nothing
    // about whether the user wants to see the newest line.
    QScrollBar* bar = verticalScrollBar();
    connect(bar, &QAbstractSlider::actionTriggered, this,
            [this, bar] { m_following = bar->sliderPosition() >= bar->maximum(); });
    connect(bar, &QAbstractSlider::rangeChanged, this, &TerminalWidget::followEnd);
    m_followLater.setSingleShot(true);
    m_followLater.setInterval(0);
    connect(&m_followLater, &QTimer::timeout, this, &TerminalWidget::followEnd);
}

void TerminalWidget::setColours(const QColor& background, const QColor& foreground) {
    m_background = background;
    QPalette colours = palette();
    colours.setColor(QPalette::Base, background);
    colours.setColor(QPalette::Text, foreground);
    setPalette(colours);
}

void TerminalWidget::displayBytes(const QByteArray& bytes) {
    render(m_fold ? m_fold->filter(bytes) : bytes);
}

void TerminalWidget::render(const QByteArray& bytes) {
    if (bytes.isEmpty()) return;
    QScrollBar* bar = verticalScrollBar();
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
    showWriteCursor(); // moves the view to the caret: put it back where the user had scrolled to
    bar->setValue(m_following ? bar->maximum() : scrolledTo);
}

void TerminalWidget::displayNotice(const QString& message) {
    QTextCharFormat format;
    format.setForeground(kNotice);
    format.setFontItalic(true);
    m_following = true; // a notice (link lost, a transfer's result) is shown even to a user scrolled up
    writeOwnLine(QStringLiteral("[%1]").arg(message), format);
}

int TerminalWidget::beginFold(TerminalFold::Hide hide) {
    if (m_fold) endFold(m_foldNumber, QString()); // one answer at a time: what the last fold held is shown
    m_fold.emplace(std::move(hide));
    return ++m_foldNumber;
}

void TerminalWidget::endFold(int fold, const QString& summary) {
    if (!m_fold || fold != m_foldNumber) return;
    const QByteArray held = m_fold->takeHeld();
    m_fold.reset();
    if (!summary.isEmpty()) {
        QTextCharFormat format;
        format.setForeground(kFolded);
        writeOwnLine(summary, format);
    }
    render(held);
}

void TerminalWidget::writeOwnLine(const QString& text, const QTextCharFormat& format) {
    QScrollBar* bar = verticalScrollBar();
    const int scrolledTo = bar->value();
    if (m_cursor.block().length() > 1) newLine();
    m_cursor.insertText(text, format);
    newLine();
    showWriteCursor();
    bar->setValue(m_following ? bar->maximum() : scrolledTo);
}

void TerminalWidget::followEnd() {
    if (m_following) verticalScrollBar()->setValue(verticalScrollBar()->maximum());
}

void TerminalWidget::showEvent(QShowEvent* event) {
    QPlainTextEdit::showEvent(event);
    // While hidden the view cannot know its height; once shown (and the dock has laid out), the end.
    if (m_following) m_followLater.start();
}

void TerminalWidget::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    if (m_following) m_followLater.start(); // rewrapped lines settle after the resize
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
        QScrollBar* bar = verticalScrollBar();
        const int before = bar->value();
        QPlainTextEdit::keyPressEvent(event); // scrolling, copy, select all
        if (bar->value() != before) m_following = bar->value() >= bar->maximum(); // Page Up, Ctrl+End ...
        return;
    }
    event->accept();
    send(bytes);
}

void TerminalWidget::send(const QByteArray& bytes) {
    m_following = true; // what the user types goes to the newest line: show it
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
        m_following = true;
    });
    menu->popup(event->globalPos());
}

} // namespace app
