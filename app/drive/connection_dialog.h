// ConnectionDialog: choose the drive to talk to — its family (BDS5 by default, SC750, PMC-960), then the
// simulated drive of that family or a serial port from the system's list or typed in (ptys such as
// /dev/pts/5) — and its baud rate. Starts from, and on OK stores,
// the choice remembered in QSettings. Use open() (non-modal to the event loop) and listen to accepted().
#pragma once

#include "connection_choice.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QPushButton;
class QRadioButton;

namespace app {

class ConnectionDialog final : public QDialog {
    Q_OBJECT
public:
    explicit ConnectionDialog(QWidget* parent = nullptr);

    ConnectionChoice choice() const;
    void setChoice(const ConnectionChoice& choice);

    void accept() override;

private:
    void refreshPorts();
    void updateEnabled();

    QComboBox* m_family;
    QLabel* m_simulatorNote;
    QLabel* m_lineNote; // the line's settings for the family chosen
    QRadioButton* m_simulator;
    QRadioButton* m_serial;
    QComboBox* m_port;
    QPushButton* m_refresh;
    QComboBox* m_baud;
    QLabel* m_portHint;
};

} // namespace app
