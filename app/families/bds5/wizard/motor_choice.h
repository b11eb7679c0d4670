// MotorChoice: the Motor Setup page's reference-motor selection. On the simulated drive it lists the
// simulator's reference motors and swaps the motor through SimulatorLink::control(), as the I/O panel's bench
// does — a bench action, not bytes on the drive's serial line; the page then reads its variables again. On
// a real drive the list is disabled: the motor is the one wired to the drive. GUI thread.
#pragma once

#include "drive_core/simulator_controls.h"

#include <QPointer>
#include <QWidget>

class QComboBox;
class QLabel;

namespace serialport {
class SimulatorLink;
}

namespace app {

class DriveConnection;

class MotorChoice final : public QWidget {
    Q_OBJECT
public:
    explicit MotorChoice(DriveConnection& connection, QWidget* parent = nullptr);

    QComboBox* list() const { return m_list; }
    QString note() const; // what the line under the list says
    bool isSimulated() const;

signals:
    // The simulated drive reports the chosen motor: it has powered up with it (ICONT and the gains anew).
    void motorChanged(const QString& name);

private:
    void followLink();
    void choose(const QString& name);
    void showStatus(const drive_core::SimulatorStatus& status);

    DriveConnection& m_connection;
    QPointer<serialport::SimulatorLink> m_simulator;
    QComboBox* m_list;
    QLabel* m_note;
    QString m_pending; // chosen, not yet reported by the simulator
};

} // namespace app
