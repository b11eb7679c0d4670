// VariableBrowser: the variable browser of every family — the catalog grouped (VariableModel), live values
// for the rows in view (VariableSync), edit in place (checked by the family's rules, then sent; the drive's
// refusal shown), search, a pinned watch list and changed values highlighted, and Copy as the family's own
// variable file (.VAR, .PRM, the PMC-960's MPL lines).
// Polls only while visible. The BDS5's Variables dock holds one; the SC750's Variables dock has one as its
// All Variables tab. GUI thread.
#pragma once

#include "session_host.h"
#include "variable_rules.h"

#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTabWidget;
class QTreeView;

namespace app {

class VariableModel;
class VariableSync;

class VariableBrowser final : public QWidget {
    Q_OBJECT
public:
    explicit VariableBrowser(SessionHost host, QWidget* parent = nullptr);

    VariableModel& model() const { return *m_model; }
    VariableSync& sync() const { return *m_sync; }
    QTreeView* allView() const { return m_allView; }
    QTreeView* watchView() const { return m_watchView; }
    QLineEdit* searchField() const { return m_search; }
    QPushButton* copyButton() const { return m_copy; }
    // The last message under the table: an edit's result, a refusal, or the hint.
    QString statusText() const;
    // The value as the drive printed it ("" until read).
    QString value(const QString& name) const;
    bool isChanged(const QString& name) const;

    // Sets a value as a user typing it into its cell: false, with the reason in statusText(), when the rules
    // refuse it (nothing is sent). The drive's answer arrives later (written()).
    bool editValue(const QString& name, const QString& text);
    // Scrolls to a variable and selects it.
    void reveal(const QString& name);
    void showWatchList(bool watch);
    void setLive(bool live);
    // Reads the rows in view and the watch list once (Refresh), or every variable (a connection's first read).
    void refresh();
    void readAll();
    void setFilter(const QString& text);
    // The family's variable file (VariableRules::fileText: .VAR, .PRM, MPL lines) of the selected variables, or
    // of the watch list when nothing is selected; what Copy as puts on the clipboard.
    VariableRules::FileText selectionAsFile() const;
    // A context-menu action that hands a name on (the SC750's "Add to the Variables list"); "" for none.
    void setListAction(const QString& text) { m_listAction = text; }

signals:
    void written(const QString& name, bool accepted);
    void listRequested(const QString& name);

private:
    QTreeView* makeView(QSortFilterProxyModel* proxy);
    QStringList visibleNames() const;
    void showContextMenu(QTreeView* view, const QPoint& at);
    void copyAsFile();
    void setStatus(const QString& text, bool problem);

    VariableModel* m_model;
    VariableSync* m_sync;
    QSortFilterProxyModel* m_allProxy;
    QSortFilterProxyModel* m_watchProxy;
    QTabWidget* m_tabs;
    QTreeView* m_allView;
    QTreeView* m_watchView;
    QLineEdit* m_search;
    QCheckBox* m_live;
    QPushButton* m_copy;
    QPushButton* m_refresh;
    QLabel* m_status;
    QLabel* m_pause;
    QString m_listAction;
};

} // namespace app
