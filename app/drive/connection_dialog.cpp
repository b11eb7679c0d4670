// ConnectionDialog: layout, port discovery, settings.
#include "connection_dialog.h"

#include "theme.h"

#include "serialport/network_link.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSerialPortInfo>
#include <QSettings>
#include <QVBoxLayout>

namespace app {

namespace {
QString portHint() {
    return ConnectionDialog::tr("Pick a port or type any device path, such as a pseudo-terminal from servodesk-sim "
                                "--pty, or a serial device server: tcp://HOST:PORT (raw) or rfc2217://HOST:PORT "
                                "(the server sets the line to the baud rate below).");
}
} // namespace

ConnectionDialog::ConnectionDialog(QWidget* parent)
    : QDialog(parent), m_family(new QComboBox(this)), m_simulatorNote(new QLabel(this)),
      m_simulator(new QRadioButton(tr("Simulated drive"), this)),
      m_serial(new QRadioButton(tr("Serial port or device server"), this)), m_port(new QComboBox(this)),
      m_refresh(new QPushButton(tr("Refresh"), this)), m_baud(new QComboBox(this)),
      m_portHint(new QLabel(this)) {
    setObjectName(QStringLiteral("connectionDialog"));
    setWindowTitle(tr("Connect to Drive"));

    auto* group = new QButtonGroup(this);
    group->addButton(m_simulator);
    group->addButton(m_serial);
    m_family->setObjectName(QStringLiteral("familyCombo"));
    m_family->addItem(tr("Kollmorgen BDS5 (Motion Link)"), int(drive_core::DriveFamily::Bds5));
    m_family->addItem(tr("Pacific Scientific SC750 (Motion Dialogue)"), int(drive_core::DriveFamily::Sc750));
    m_family->addItem(tr("Ormec PMC-960 (MPL)"), int(drive_core::DriveFamily::Pmc960));
    m_simulatorNote->setIndent(24);
    m_simulatorNote->setEnabled(false);

    m_port->setEditable(true);
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumContentsLength(24);
    m_port->lineEdit()->setPlaceholderText(QStringLiteral("/dev/ttyUSB0"));
    m_portHint->setText(portHint());
    connect(m_port, &QComboBox::editTextChanged, this, [this] { // a new text: the hint, not the last complaint
        Theme::showStatus(*m_portHint, portHint(), false);
        m_portHint->setEnabled(false);
    });
    m_portHint->setWordWrap(true);
    m_portHint->setEnabled(false);
    auto* portRow = new QHBoxLayout;
    portRow->addWidget(m_port, 1);
    portRow->addWidget(m_refresh);
    auto* serialForm = new QFormLayout;
    serialForm->setContentsMargins(24, 0, 0, 0);
    serialForm->addRow(tr("Port:"), portRow);
    serialForm->addRow(QString(), m_portHint);

    for (const int rate : ConnectionChoice::baudRates())
        m_baud->addItem(QString::number(rate), rate);
    auto* lineForm = new QFormLayout;
    lineForm->addRow(tr("Baud rate:"), m_baud);
    m_lineNote = new QLabel(this);
    m_lineNote->setObjectName(QStringLiteral("lineNote"));
    m_lineNote->setEnabled(false);
    lineForm->addRow(QString(), m_lineNote);

    auto* driveBox = new QGroupBox(tr("Drive"), this);
    auto* driveLayout = new QVBoxLayout(driveBox);
    auto* familyForm = new QFormLayout;
    familyForm->addRow(tr("Family:"), m_family);
    driveLayout->addLayout(familyForm);
    driveLayout->addSpacing(6);
    driveLayout->addWidget(m_simulator);
    driveLayout->addWidget(m_simulatorNote);
    driveLayout->addSpacing(6);
    driveLayout->addWidget(m_serial);
    driveLayout->addLayout(serialForm);
    auto* lineBox = new QGroupBox(tr("Line"), this);
    lineBox->setLayout(lineForm);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Connect"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(driveBox);
    layout->addWidget(lineBox);
    layout->addStretch(1);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::accepted, this, &ConnectionDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ConnectionDialog::reject);
    connect(m_refresh, &QPushButton::clicked, this, &ConnectionDialog::refreshPorts);
    connect(m_serial, &QRadioButton::toggled, this, &ConnectionDialog::updateEnabled);
    connect(m_family, &QComboBox::currentIndexChanged, this, &ConnectionDialog::updateEnabled);

    refreshPorts();
    QSettings settings;
    setChoice(ConnectionChoice::load(settings));
}

ConnectionChoice ConnectionDialog::choice() const {
    ConnectionChoice c;
    c.kind = m_serial->isChecked() ? ConnectionChoice::Kind::SerialPort : ConnectionChoice::Kind::Simulator;
    c.portName = m_port->currentText().trimmed();
    c.baudRate = m_baud->currentData().toInt();
    c.family = drive_core::DriveFamily(m_family->currentData().toInt());
    return c;
}

void ConnectionDialog::setChoice(const ConnectionChoice& choice) {
    (choice.kind == ConnectionChoice::Kind::SerialPort ? m_serial : m_simulator)->setChecked(true);
    m_family->setCurrentIndex(std::max(0, m_family->findData(int(choice.family))));
    if (!choice.portName.isEmpty()) m_port->setCurrentText(choice.portName);
    const int baudIndex = m_baud->findData(choice.baudRate);
    m_baud->setCurrentIndex(baudIndex >= 0 ? baudIndex : m_baud->findData(9600));
    updateEnabled();
}

void ConnectionDialog::accept() {
    const ConnectionChoice c = choice();
    if (c.kind == ConnectionChoice::Kind::SerialPort && c.portName.isEmpty()) {
        m_port->setFocus();
        return; // nothing to open yet
    }
    if (const QString problem = serialport::NetworkLink::problem(c.portName);
        c.kind == ConnectionChoice::Kind::SerialPort && !problem.isEmpty()) {
        m_portHint->setEnabled(true);
        Theme::showStatus(*m_portHint, problem, true);
        m_port->setFocus();
        return; // the dialog stays with the typed text
    }
    QSettings settings;
    c.save(settings);
    QDialog::accept();
}

void ConnectionDialog::refreshPorts() {
    const QString typed = m_port->currentText();
    m_port->clear();
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) {
        m_port->addItem(info.systemLocation());
        if (!info.description().isEmpty())
            m_port->setItemData(m_port->count() - 1, info.description(), Qt::ToolTipRole);
    }
    m_port->setCurrentText(typed);
}

void ConnectionDialog::updateEnabled() {
    const bool serial = m_serial->isChecked();
    m_port->setEnabled(serial);
    m_refresh->setEnabled(serial);
    const auto family = drive_core::DriveFamily(m_family->currentData().toInt());
    m_simulatorNote->setText(tr("A %1 simulated inside ServoDesk. No hardware needed.")
                                 .arg(ConnectionChoice::familyName(family)));
    // The PMC-960's port runs with RTS/CTS: its one-character receive buffer overruns without it (seed-pmc960
    // §4.1, connection_choice.cpp); the others use three wires.
    m_lineNote->setText(family == drive_core::DriveFamily::Pmc960
                            ? tr("8 data bits, no parity, 1 stop bit, RTS/CTS flow control.")
                            : tr("8 data bits, no parity, 1 stop bit, no flow control."));
}

} // namespace app
