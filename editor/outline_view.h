// OutlineView: the "Outline" dock's content — the labels and tasks of the program in the current editor,
// with a filter field that doubles as "Go to label" (type, Enter jumps). Follows whichever editor
// setEditor() names (the composition root calls it when the current tab changes). GUI thread only.
#pragma once

#include "bds5_outline.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

class QLineEdit;
class QTreeWidget;
class QTreeWidgetItem;
class QsciScintilla;

namespace editor {

class OutlineView final : public QWidget {
    Q_OBJECT
public:
    static constexpr int kRefreshMs = 300; // after the last change of the text

    explicit OutlineView(QWidget* parent = nullptr);

    // Follows editor (nullptr: shows nothing). The outline is rebuilt at once.
    void setEditor(QsciScintilla* editor);
    QsciScintilla* editor() const { return m_editor; }

    // Go to label: clears and focuses the filter field.
    void focusFilter();
    // Moves the editor's cursor to the label's line and gives it focus. False if no entry is named so.
    bool jumpTo(const QString& labelName);

    const std::vector<Bds5OutlineEntry>& entries() const { return m_entries; }
    QTreeWidget* tree() const { return m_tree; }
    QLineEdit* filterField() const { return m_filter; }

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
    QTimer m_timer;
    std::vector<Bds5OutlineEntry> m_entries;
};

} // namespace editor
