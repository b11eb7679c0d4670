// VariablesDock: the variable browser — every catalog variable grouped, with live values for the rows in
// view, edit in place (validated, then sent; the drive's refusal shown), search, a pinned watch list,
// changed values highlighted and "Copy as .VAR". Polls only while visible. GUI thread.
#pragma once

#include <QDockWidget>

class QLabel;
class QLineEdit;
class QCheckBox;
class QSortFilterProxyModel;
class QTabWidget;
class QTreeView;

namespace app {

class DriveConnection;
class VariableModel;
class VariableSync;

class VariablesDock final : public QDockWidget {
    Q_OBJECT
public:
    explicit VariablesDock(DriveConnection& connection, QWidget* parent = nullptr);

    VariableModel& model() const { return *m_model; }
    VariableSync& sync() const { return *m_sync; }
    QTreeView* allView() const { return m_allView; }
    QTreeView* watchView() const { return m_watchView; }
    QLineEdit* searchField() const { return m_search; }
    // The last message under the table: an edit's result, or why polling waits.
    QString statusText() const;

    // Starts editing a variable as a user double-clicking its value would; editValue() sets it directly
    // (validated and sent exactly as an in-place edit is).
    void editValue(const QString& name, const QString& text);
    // Scrolls to a variable and selects it.
    void reveal(const QString& name);
    void showWatchList(bool watch);
    // "NAME value" lines of the selected variables (or of the watch list when nothing is selected).
    QString selectionAsVar() const;

private:
    QTreeView* makeView(QSortFilterProxyModel* proxy);
    QStringList visibleNames() const;
    void showContextMenu(QTreeView* view, const QPoint& at);
    void copyAsVar();
    void setStatus(const QString& text, bool problem);
    void applyFilter(const QString& text);

    VariableModel* m_model;
    VariableSync* m_sync;
    QSortFilterProxyModel* m_allProxy;
    QSortFilterProxyModel* m_watchProxy;
    QTabWidget* m_tabs;
    QTreeView* m_allView;
    QTreeView* m_watchView;
    QLineEdit* m_search;
    QCheckBox* m_live;
    QLabel* m_status;
    QLabel* m_pause;
};

} // namespace app
