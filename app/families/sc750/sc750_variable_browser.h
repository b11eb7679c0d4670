// Sc750VariableBrowser: the SC750's variable browser, the Variables dock's "All Variables" tab — every
// predefined variable and set-up parameter of the catalog, grouped, with value, unit, range, access and
// description. The rows in view are read live with G frames, one at a time, round robin (G is answered
// while a program runs); a value that changed since the last read is highlighted. A value is edited in
// place (double-click), checked against the catalog's type, access and range before a P frame goes out;
// the controller's refusal (!03 PROGRAM RUNNING while a program executes) is shown and the row read again.
// GUI thread only.
#pragma once

#include <QHash>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QTreeWidget;
class QTreeWidgetItem;

namespace app {

class Sc750Workspace;

class Sc750VariableBrowser final : public QWidget {
    Q_OBJECT
public:
    enum Column { NameColumn, ValueColumn, UnitColumn, RangeColumn, AccessColumn, DescriptionColumn, ColumnCount };
    static constexpr int kTickMs = 40; // the next read goes out at most this often

    explicit Sc750VariableBrowser(Sc750Workspace& workspace, QWidget* parent = nullptr);

    QTreeWidget* tree() const { return m_tree; }
    int variableCount() const { return int(m_items.size()); }
    QString value(const QString& name) const;
    bool isChanged(const QString& name) const;
    QString message() const;
    void setLive(bool live);
    void setFilter(const QString& text);
    // Checks text and sends it as the variable's new value: false, with the reason in message(), when the
    // catalog refuses it (nothing is sent). The controller's answer arrives later (written()).
    bool writeValue(const QString& name, const QString& text);
    // Scrolls to a variable and selects it.
    void reveal(const QString& name);

signals:
    void written(const QString& name, bool accepted);
    void watchRequested(const QString& name); // "Add to Watch": the Motion Dialogue list
    void valueRead(const QString& name, const QString& value);

private:
    void readNext();
    void read(QTreeWidgetItem* item);
    void setValue(QTreeWidgetItem* item, const QString& value);
    void showMessage(const QString& text, bool error);
    QList<QTreeWidgetItem*> rowsInView() const;
    void showContextMenu(const QPoint& at);

    Sc750Workspace& m_workspace;
    QLineEdit* m_filter;
    QCheckBox* m_live;
    QTreeWidget* m_tree;
    QLabel* m_message;
    QTimer m_tick;
    QHash<QString, QTreeWidgetItem*> m_items;
    int m_cursor = 0;       // round robin position among the rows in view
    bool m_reading = false; // a G frame is on its way
    bool m_filling = false; // itemChanged from our own updates is not a user edit
};

} // namespace app
