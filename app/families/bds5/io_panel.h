// IoPanel: the simulated drive's bench — toggle inputs I1-I16, ENABLE, MOTION, HOME and the limit
// switches, see outputs O1-O8, set load torque/inertia, a compliant coupling (two-mass resonance) and the master
// encoder frequency, choose the motor, cycle power — through SimulatorLink::control(), never through the drive's serial
// port. On a real drive it shows the inputs and outputs read through the session (P IN OUT). GUI thread.
#pragma once

#include "drive_core/simulator_controls.h"
#include "serialport/bds5_session.h"

#include <QDockWidget>
#include <QPointer>
#include <QTimer>

#include <functional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace serialport {
class SimulatorLink;
}

namespace app {

class DriveConnection;

class IoPanel final : public QDockWidget {
    Q_OBJECT
public:
    explicit IoPanel(DriveConnection& connection, QWidget* parent = nullptr);

    // The toggle for input n (1-16) and the lamp for output n (1-8), as a user sees them.
    QPushButton* inputButton(int number) const { return m_inputs.value(number - 1); }
    QPushButton* powerCycleButton() const { return m_powerCycle; }
    bool outputLit(int number) const;
    // The bench's line under the controls: "ACTIVE  pos 0.000 rev  vel 0.0 rpm  I 0.00 A  REF-MEDIUM".
    QString readoutText() const;
    // The bench's load torque field (N m), as a user types into it.
    QDoubleSpinBox* loadTorqueField() const { return m_torque; }
    QDoubleSpinBox* loadInertiaField() const { return m_inertia; }
    // The coupling's stiffness (N m/rad, 0 = rigid) and damping (N m s/rad) fields, and the resonance they make.
    QDoubleSpinBox* couplingStiffnessField() const { return m_stiffness; }
    QDoubleSpinBox* couplingDampingField() const { return m_damping; }
    QString resonanceText() const;
    bool isSimulated() const;

private:
    QWidget* makeInputs();
    QWidget* makeOutputs();
    QWidget* makeBench();
    void followLink();
    void bench(std::function<void(drive_core::SimulatorControls&)> change);
    // Each value the sender's signal carries goes to the bench's setter.
    template <typename Sender, typename Signal, typename Value>
    void toBench(Sender* sender, Signal changed, void (drive_core::SimulatorControls::*set)(Value));
    void showStatus(const drive_core::SimulatorStatus& status);
    void showOutputs(const std::vector<bool>& outputs);
    void pollRealDrive();
    void onFinished(quint64 id, const serialport::Bds5Response& response);

    DriveConnection& m_connection;
    QPointer<serialport::SimulatorLink> m_simulator;
    QPointer<serialport::Bds5Session> m_session;
    QList<QPushButton*> m_inputs;
    QList<QLabel*> m_outputs;
    std::vector<bool> m_outputState;
    QPushButton* m_enable = nullptr;
    QPushButton* m_motion = nullptr;
    QPushButton* m_home = nullptr;
    QPushButton* m_posLimit = nullptr;
    QPushButton* m_negLimit = nullptr;
    QPushButton* m_powerCycle = nullptr;
    QDoubleSpinBox* m_torque = nullptr;
    QDoubleSpinBox* m_inertia = nullptr;
    QDoubleSpinBox* m_master = nullptr;
    QDoubleSpinBox* m_stiffness = nullptr;
    QDoubleSpinBox* m_damping = nullptr;
    QLabel* m_resonance = nullptr;
    QComboBox* m_motor = nullptr;
    QLabel* m_readout = nullptr;
    QLabel* m_source = nullptr;
    QWidget* m_benchBox = nullptr;
    QTimer m_poll;
    quint64 m_pollId = 0;
};

} // namespace app
