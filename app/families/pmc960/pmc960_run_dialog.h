// Pmc960RunDialog: MPL > Run Routine's choice — the labels of the program in the editor, each with the rest
// of its @-line as a description, and, while the servo is not known to be on, "Enable the servo first
// (SM2)". It only chooses; Pmc960RoutineRunner sends. GUI thread only.
#pragma once

#include <QDialog>
#include <QList>

class QCheckBox;
class QLabel;
class QListWidget;
class QPushButton;

namespace app {

class Pmc960RunDialog final : public QDialog {
    Q_OBJECT
public:
    // One routine: the label B<label> names, and what its @-line says ("Hello: set up, then three turns").
    struct Routine {
        QChar label;
        QString description;
    };
    // What the status panel last read with SM!: nothing yet, SM0, or SM1-SM3.
    enum class Servo { Unknown, Disabled, Enabled };

    Pmc960RunDialog(const QList<Routine>& routines, Servo servo, QWidget* parent = nullptr);

    // The routines of an MPL program: every line "@<label>..." whose label is not '.' (a comment line) and
    // is one the controller accepts (22H-7AH), first occurrence only (the controller's label search stops
    // there). Spaces are not stored, so they are ignored before the label; '_' reads as a space.
    static QList<Routine> routinesIn(const QString& programText);
    // As the list shows it: "H  Hello: set up, then three turns forward".
    static QString itemText(const Routine& routine);

    QListWidget* list() const { return m_list; }
    QCheckBox* enableServoFirst() const { return m_enable; }
    QPushButton* runButton() const { return m_run; }
    QString servoNote() const;

signals:
    // Accepted with a routine chosen (Run, Enter or a double-click).
    void runRequested(QChar label, bool enableServoFirst);

private:
    void onAccepted();

    QListWidget* m_list;
    QLabel* m_servo;
    QCheckBox* m_enable;
    QPushButton* m_run;
};

} // namespace app
