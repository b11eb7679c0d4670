// OutlineView: a filter field over a two-column tree (label, note); a click or Enter jumps to the line,
// and the entry whose section holds the cursor stays selected.
#include "outline_view.h"

#include "language_support.h"

#include <Qsci/qsciscintilla.h>

#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace editor {

namespace {
constexpr int kLineRole = Qt::UserRole + 1;
}

OutlineView::OutlineView(QWidget* parent)
    : QWidget(parent), m_filter(new QLineEdit(this)), m_tree(new QTreeWidget(this)), m_empty(new QLabel(this)) {
    setObjectName(QStringLiteral("outlineView"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    m_filter->setPlaceholderText(tr("Go to label\u2026 (Ctrl+Shift+G)"));
    m_filter->setClearButtonEnabled(true);
    m_filter->installEventFilter(this);
    layout->addWidget(m_filter);

    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Label"), tr("Line"), tr("Note")});
    m_tree->setRootIsDecorated(false);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    m_tree->header()->setStretchLastSection(true);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    layout->addWidget(m_tree);
    m_empty->setObjectName(QStringLiteral("outlineEmptyNote"));
    m_empty->setWordWrap(true);
    m_empty->setForegroundRole(QPalette::PlaceholderText);
    m_empty->hide();
    layout->addWidget(m_empty);

    m_timer.setSingleShot(true);
    m_timer.setInterval(kRefreshMs);
    connect(&m_timer, &QTimer::timeout, this, &OutlineView::refresh);
    connect(m_filter, &QLineEdit::textChanged, this, &OutlineView::applyFilter);
    connect(m_filter, &QLineEdit::returnPressed, this, [this] {
        for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
            if (QTreeWidgetItem* item = m_tree->topLevelItem(i); !item->isHidden()) {
                jumpToItem(item);
                return;
            }
    });
    connect(m_tree, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) { jumpToItem(item); });
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) { jumpToItem(item); });
}

void OutlineView::setEditor(QsciScintilla* editor) {
    if (editor == m_editor) return;
    disconnect(m_textConnection);
    disconnect(m_cursorConnection);
    if (m_editor) m_editor->removeEventFilter(this);
    m_editor = editor;
    if (editor) {
        editor->installEventFilter(this); // a language installed or taken out later: see eventFilter
        // Lines added or removed move every entry below them: the list is rebuilt at once, so it never shows
        // a wrong line. Other edits wait for the pause in typing.
        m_textConnection = connect(editor, &QsciScintilla::textChanged, this, [this] {
            if (m_editor && m_editor->lines() != m_lineCount) refresh();
            else m_timer.start();
        });
        m_cursorConnection = connect(editor, &QsciScintilla::cursorPositionChanged, this, &OutlineView::followCursor);
    }
    refresh();
}

void OutlineView::refresh() {
    m_timer.stop();
    m_lineCount = m_editor ? m_editor->lines() : 0;
    const LanguageSupport* language = LanguageSupport::of(m_editor);
    m_entries = language ? language->outline(m_editor->text()) : Outline{};
    m_empty->setText(!m_editor   ? tr("No program is open.")
                     : language ? language->noOutline()
                                : tr("Plain text has no outline: labels are listed for a drive program."));
    m_empty->setVisible(m_entries.empty());
    m_tree->clear();
    QList<QTreeWidgetItem*> items;
    for (const OutlineEntry& e : m_entries) {
        auto* item = new QTreeWidgetItem({e.name, QString::number(e.line + 1), e.detail});
        item->setData(0, kLineRole, e.line);
        item->setTextAlignment(1, Qt::AlignRight | Qt::AlignVCenter);
        if (e.kind != OutlineEntry::Kind::Label) {
            QFont bold = item->font(0);
            bold.setBold(true);
            item->setFont(0, bold);
        }
        item->setToolTip(0, tr("Line %1").arg(e.line + 1));
        items << item;
    }
    m_tree->addTopLevelItems(items);
    applyFilter();
    followCursor();
}

void OutlineView::applyFilter() {
    const QString needle = m_filter->text().trimmed();
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_tree->topLevelItem(i);
        item->setHidden(!needle.isEmpty() && !item->text(0).contains(needle, Qt::CaseInsensitive) &&
                        !item->text(2).contains(needle, Qt::CaseInsensitive));
    }
}

void OutlineView::focusFilter() {
    m_filter->clear();
    m_filter->setFocus(Qt::ShortcutFocusReason);
}

bool OutlineView::jumpTo(const QString& labelName) {
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (QTreeWidgetItem* item = m_tree->topLevelItem(i);
            item->text(0).compare(labelName, Qt::CaseInsensitive) == 0) {
            jumpToItem(item);
            return true;
        }
    return false;
}

void OutlineView::jumpToItem(QTreeWidgetItem* item) {
    if (!item || !m_editor) return;
    const int line = item->data(0, kLineRole).toInt();
    m_editor->setCursorPosition(line, 0);
    m_editor->ensureLineVisible(line);
    // Put the label near the top, with a little context above it.
    m_editor->setFirstVisibleLine(qMax(0, line - 3));
    m_editor->setFocus(Qt::OtherFocusReason);
}

void OutlineView::followCursor() {
    if (!m_editor) return;
    int line = 0, index = 0;
    m_editor->getCursorPosition(&line, &index);
    QTreeWidgetItem* current = nullptr;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_tree->topLevelItem(i);
        if (item->data(0, kLineRole).toInt() > line) break;
        current = item;
    }
    const QSignalBlocker block(m_tree);
    m_tree->setCurrentItem(current);
    if (!current) m_tree->clearSelection();
}

bool OutlineView::eventFilter(QObject* watched, QEvent* event) {
    // A language is a child of its editor: one installed (or taken out) after setEditor changes the outline.
    // At ChildAdded the child is still being built, so any new or removed child asks for a refresh.
    if (watched == m_editor && (event->type() == QEvent::ChildAdded || event->type() == QEvent::ChildRemoved)) {
        m_timer.start();
        return false;
    }
    if (watched == m_filter && event->type() == QEvent::KeyPress) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Escape && m_editor) {
            m_filter->clear();
            m_editor->setFocus(Qt::OtherFocusReason);
            return true;
        }
        if (key->key() == Qt::Key_Down) { // from the field into the list
            m_tree->setFocus(Qt::OtherFocusReason);
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace editor
