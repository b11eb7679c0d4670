// Pmc960RunDialog: the routine list, the servo note and its SM2 check box.
#include "pmc960_run_dialog.h"

#include "editor/mpl_outline.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace app {

QList<Pmc960RunDialog::Routine> Pmc960RunDialog::routinesIn(const QString& programText) {
    QString normal = programText;
    normal.replace(QStringLiteral("\r\n"), QStringLiteral("\n")).replace(QLatin1Char('\r'), QLatin1Char('\n'));
    QList<Routine> routines;
    QString seen;
    for (const editor::OutlineEntry& entry : editor::mplOutline(normal)) {
        const QChar label = entry.name.at(0);
        if (seen.contains(label)) continue; // never reached: the label search stops at the first
        seen += label;
        routines.append({label, entry.detail});
    }
    return routines;
}

QString Pmc960RunDialog::itemText(const Routine& routine) {
    return routine.description.isEmpty() ? QString(routine.label)
                                         : QStringLiteral("%1  %2").arg(routine.label).arg(routine.description);
}

Pmc960RunDialog::Pmc960RunDialog(const QList<Routine>& routines, Servo servo, QWidget* parent)
    : QDialog(parent), m_list(new QListWidget(this)), m_servo(new QLabel(this)),
      m_enable(new QCheckBox(tr("Enable the servo first (SM2)"), this)) {
    setObjectName(QStringLiteral("pmc960RunDialog"));
    setWindowTitle(tr("Run Routine"));
    setMinimumWidth(480);
    auto* layout = new QVBoxLayout(this);

    auto* heading = new QLabel(this);
    heading->setWordWrap(true);
    heading->setText(routines.isEmpty()
                         ? tr("The program in the editor has no labels (lines such as @H...): there is no routine "
                              "to run.")
                         : tr("Routines of the program in the editor. The controller runs the program in its "
                              "buffer: if that differs, download it first (MPL > Download Program)."));
    layout->addWidget(heading);

    m_list->setObjectName(QStringLiteral("routineList"));
    for (const Routine& routine : routines) {
        auto* item = new QListWidgetItem(itemText(routine), m_list);
        item->setData(Qt::UserRole, QString(routine.label));
    }
    m_list->setCurrentRow(0);
    m_list->setVisible(!routines.isEmpty());
    layout->addWidget(m_list);

    m_servo->setObjectName(QStringLiteral("servoNote"));
    m_servo->setWordWrap(true);
    switch (servo) {
    case Servo::Disabled:
        m_servo->setText(tr("The servo is not enabled (SM0): a routine that moves is refused (#B6)."));
        break;
    case Servo::Unknown:
        m_servo->setText(tr("The servo mode has not been read yet: if the servo is off, a routine that moves is "
                            "refused (#B6)."));
        break;
    case Servo::Enabled: m_servo->setText(tr("The servo is enabled.")); break;
    }
    m_enable->setObjectName(QStringLiteral("enableServoFirst"));
    m_enable->setToolTip(tr("Send SM2 (position mode: the motor holds its position) before the routine"));
    // chosen: unchecked by default. Enabling a servo makes the motor hold (and a routine move) it: the user's call.
    m_enable->setVisible(servo != Servo::Enabled && !routines.isEmpty());
    m_servo->setVisible(!routines.isEmpty());
    layout->addWidget(m_servo);
    layout->addWidget(m_enable);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_run = buttons->addButton(tr("&Run"), QDialogButtonBox::AcceptRole);
    m_run->setObjectName(QStringLiteral("runRoutineButton"));
    m_run->setEnabled(!routines.isEmpty());
    m_run->setDefault(true); // Enter in the list runs the current routine
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_list, &QListWidget::itemDoubleClicked, this, &QDialog::accept);
    connect(this, &QDialog::accepted, this, &Pmc960RunDialog::onAccepted);
    if (!routines.isEmpty()) m_list->setFocus();
}

QString Pmc960RunDialog::servoNote() const {
    return m_servo->isHidden() ? QString() : m_servo->text();
}

void Pmc960RunDialog::onAccepted() {
    const QListWidgetItem* item = m_list->currentItem();
    if (!item) return;
    const QString label = item->data(Qt::UserRole).toString();
    if (label.size() == 1) emit runRequested(label.at(0), !m_enable->isHidden() && m_enable->isChecked());
}

} // namespace app
