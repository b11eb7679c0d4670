// Sc750FunctionDialog: Compile > Real Time Function Call (L2796-L2812). Pick GO.ABS, GO.HOME, GO.INCR,
// GO.VEL, PAUSE, ABORT.MOTION or UPD.MOVE; the variables that call uses are read from the controller into
// editable fields; Call writes the changed ones and issues the function. Only while no program executes.
// Non-modal (open()); GUI thread only.
#pragma once

#include <QDialog>
#include <QMap>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace app {

class Sc750Workspace;

class Sc750FunctionDialog final : public QDialog {
    Q_OBJECT
public:
    Sc750FunctionDialog(Sc750Workspace& workspace, QWidget* parent = nullptr);

    // The variables each function uses (seed-sc750 §7.2, catalog names).
    static QStringList functions();
    static QStringList variablesOf(const QString& function);

    void selectFunction(const QString& function);
    void call();
    QString status() const;
    QLineEdit* field(const QString& variable) const { return m_fields.value(variable); }

signals:
    void called(const QString& function);

private:
    void rebuildFields();
    void setStatus(const QString& text, bool error);

    Sc750Workspace& m_workspace;
    QComboBox* m_function;
    QFormLayout* m_form;
    QLabel* m_status;
    QMap<QString, QLineEdit*> m_fields;
    QMap<QString, QString> m_read; // values as read, to write only what changed
};

} // namespace app
