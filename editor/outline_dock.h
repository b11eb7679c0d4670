// OutlineDock: the "Outline" dock (labels and tasks of the current program) and its "Go to label" action
// (Ctrl+Shift+G: shows the dock and puts the cursor in its filter; type, Enter jumps). GUI thread only.
#pragma once

#include <QDockWidget>

class QAction;
class QsciScintilla;

namespace editor {

class OutlineView;

class OutlineDock final : public QDockWidget {
    Q_OBJECT
public:
    explicit OutlineDock(QWidget* parent = nullptr);

    // Follows the current editor (call on every tab change).
    void setEditor(QsciScintilla* editor);
    OutlineView* view() const { return m_view; }
    QAction* goToLabelAction() const { return m_goToLabel; }

private:
    OutlineView* m_view;
    QAction* m_goToLabel;
};

} // namespace editor
