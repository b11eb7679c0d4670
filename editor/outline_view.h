// OutlineView: the "Outline" dock's content — the labels and entry points of the program in the current
// editor, found by the language installed in it (LanguageSupport::outline: BDS5, MPL or ServoBASIC), with a
// filter field that doubles as "Go to label" (type, Enter jumps). When there is nothing to list, a line
// says why (plain text, or a program without labels). Follows whichever editor setEditor() names (the
// composition root calls it when the current tab changes) and the language installed in it later.
// GUI thread only.
#pragma once

#include "outline.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

class QLabel;
class QLineEdit;
class QTreeWidget;
class QTreeWidgetItem;
class QsciScintilla;

namespace editor {

class OutlineView final : public QWidget {
    Q_OBJECT
public:
    static constexpr int kRefreshMs = 300; // after the last change of the text that kept its line count

    explicit OutlineView(QWidget* parent = nullptr);

    // Follows editor (nullptr: shows nothing). The outline is rebuilt at once.
    void setEditor(QsciScintilla* editor);
    QsciScintilla* editor() const { return m_editor; }

    // Go to label: clears and focuses the filter field.
    void focusFilter();
    // Moves the editor's cursor to the label's line and gives it focus. False if no entry is named so.
    bool jumpTo(const QString& labelName);

    const Outline& entries() const { return m_entries; }
    QTreeWidget* tree() const { return m_tree; }
    QLineEdit* filterField() const { return m_filter; }
    // Why the list is empty ("Plain text has no outline."); hidden while it lists something.
    QLabel* emptyNote() const { return m_empty; }

    // Rebuilds from the editor's text now (normally on a timer after edits).
    void refresh();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void applyFilter();
    void jumpToItem(QTreeWidgetItem* item);
    void followCursor();

    QPointer<QsciScintilla> m_editor;
    QMetaObject::Connection m_textConnection;
    QMetaObject::Connection m_cursorConnection;
    QLineEdit* m_filter;
    QTreeWidget* m_tree;
    QLabel* m_empty;
    QTimer m_timer;
    Outline m_entries;
    int m_lineCount = 0; // the editor's lines when the list was built
};

} // namespace editor
