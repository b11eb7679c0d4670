// OutlineDock: a dock around OutlineView plus the Go to label action.
#include "outline_dock.h"

#include "outline_view.h"

#include <Qsci/qsciscintilla.h>

#include <QAction>

namespace editor {

OutlineDock::OutlineDock(QWidget* parent)
    : QDockWidget(tr("Outline"), parent), m_view(new OutlineView(this)),
      m_goToLabel(new QAction(tr("Go to La&bel..."), this)) {
    setObjectName(QStringLiteral("outlineDock"));
    setWidget(m_view);
    m_goToLabel->setShortcut(QKeySequence(tr("Ctrl+Shift+G")));
    m_goToLabel->setShortcutContext(Qt::WindowShortcut);
    m_goToLabel->setStatusTip(tr("Jump to a label or task of the program: type part of its name, then Enter"));
    connect(m_goToLabel, &QAction::triggered, this, [this] {
        show();
        raise();
        m_view->focusFilter();
    });
}

void OutlineDock::setEditor(QsciScintilla* editor) {
    m_view->setEditor(editor);
}

} // namespace editor
