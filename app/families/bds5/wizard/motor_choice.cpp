// MotorChoice: reference motors on the simulator's bench; fixed by the hardware on a real drive.
#include "motor_choice.h"

#include "families/bds5/drive_connection.h"

#include "drive_core/physics/motor_parameters.h"
#include "serialport/simulator_link.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>

namespace app {

MotorChoice::MotorChoice(DriveConnection& connection, QWidget* parent)
    : QWidget(parent), m_connection(connection), m_list(new QComboBox(this)), m_note(new QLabel(this)) {
    setObjectName(QStringLiteral("motorChoice"));
    for (const auto& motor : drive_core::physics::referenceMotors()) {
        m_list->addItem(QString::fromLatin1(motor.name.data(), qsizetype(motor.name.size())));
        m_list->setItemData(m_list->count() - 1,
                            QString::fromLatin1(motor.description.data(), qsizetype(motor.description.size())),
                            Qt::ToolTipRole);
    }
    m_note->setWordWrap(true);
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Reference motor"), m_list);
    form->addRow(m_note);
    // activated: the user's choice only, not the list following the simulator's status.
    connect(m_list, &QComboBox::activated, this, [this](int index) { choose(m_list->itemText(index)); });
    connect(&m_connection, &DriveConnection::linkChanged, this, &MotorChoice::followLink);
    connect(&m_connection, &DriveConnection::connectedChanged, this, &MotorChoice::followLink);
    followLink();
}

bool MotorChoice::isSimulated() const {
    return m_simulator != nullptr;
}

QString MotorChoice::note() const {
    return m_note->text();
}

void MotorChoice::followLink() {
    serialport::Bds5Session* session = m_connection.session();
    auto* simulator = session ? qobject_cast<serialport::SimulatorLink*>(&session->link()) : nullptr;
    if (simulator != m_simulator) {
        m_simulator = simulator;
        if (simulator) {
            connect(simulator, &serialport::SimulatorLink::simulatorStatus, this, &MotorChoice::showStatus);
            showStatus(simulator->lastStatus());
        }
    }
    m_list->setEnabled(simulator != nullptr);
    // Decision: only the simulator's motor can be swapped from here. A real BDS5 drives the motor wired to
    // it, and its motor data (IMAX, VMAX and the TL sheet's gains) are set at the factory for that motor, so
    // ServoDesk cannot choose one; the page's variables are what can be set for it.
    m_note->setText(simulator ? tr("Simulated drive: choosing a motor swaps it on the bench (as the I/O panel "
                                   "does) and powers the drive up with it; this page then reads ICONT and the "
                                   "gains again. Edits not yet sent stay in the wizard.")
                              : tr("Real drive: the motor is the one wired to the drive, and its data (IMAX, VMAX, "
                                   "the TL sheet's gains) are set at the factory, so it cannot be chosen here."));
}

void MotorChoice::choose(const QString& name) {
    if (!m_simulator) return;
    m_pending = name;
    m_simulator->control([motor = name.toStdString()](drive_core::SimulatorControls& c) { c.selectMotor(motor); });
}

void MotorChoice::showStatus(const drive_core::SimulatorStatus& status) {
    const QString name = QString::fromStdString(status.motorName);
    if (name.isEmpty()) return;
    if (!m_list->hasFocus() || m_pending.isEmpty()) {
        const QSignalBlocker quiet(m_list);
        m_list->setCurrentText(name);
    }
    if (!m_pending.isEmpty() && name == m_pending) {
        m_pending.clear();
        emit motorChanged(name);
    }
}

} // namespace app
