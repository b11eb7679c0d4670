// Sc750VariablesDock: Motion Dialogue's Variables window (L2746-L2786) as a dock: type a name (a program
// variable, "A(3)", or a predefined variable/parameter) and Enter reads it into the list; editing a value
// writes it, which the controller allows only while no program executes; Refresh reads every row again, as
// does the program stopping (at a breakpoint, by Stop, at its end or an error).
// Its second tab is the variable browser of every predefined variable (the family-neutral VariableBrowser).
// GUI thread only.
#pragma once

#include <QDockWidget>

class QCompleter;
class QLabel;
class QLineEdit;
class QPushButton;
class QTabWidget;
class QTableWidget;

namespace app {

class VariableBrowser;
class Sc750Workspace;

class Sc750VariablesDock final : public QDockWidget {
    Q_OBJECT
public:
    Sc750VariablesDock(Sc750Workspace& workspace, QWidget* parent = nullptr);

    // Adds the name to the list (once) and reads its value from the controller.
    void readVariable(const QString& name);
    // Writes NAME=value; the row shows the value the controller reports back.
    void writeVariable(const QString& name, const QString& value);
    void refresh();
    // Writes are refused while a program runs; the value column is read-only then.
    void setWritable(bool writable);
    void focusName();
    // Shows the dock on its All Variables tab.
    void showAllVariables();
    VariableBrowser* browser() const { return m_browser; }

    // The value shown for name ("" when not listed or not read yet), and the last error, for tests.
    QString value(const QString& name) const;
    QString lastMessage() const;
    QTableWidget* table() const { return m_table; }

signals:
    void valueRead(const QString& name, const QString& value);

private:
    int rowOf(const QString& name) const;
    int ensureRow(const QString& name);
    void setValue(const QString& name, const QString& value);
    void showMessage(const QString& text, bool error);
    void updateCompletions();

    Sc750Workspace& m_workspace;
    QLineEdit* m_name;
    QCompleter* m_completer;
    QTableWidget* m_table;
    QTabWidget* m_tabs = nullptr;
    VariableBrowser* m_browser = nullptr;
    QPushButton* m_refresh;
    QLabel* m_message;
    bool m_writable = true;
    bool m_filling = false; // itemChanged from our own updates is not a user edit
};

} // namespace app
