// IoPanel: bench controls for a simulated drive, I/O readout for a real one.
#include "io_panel.h"

#include "drive_connection.h"

#include "drive_core/physics/motor_parameters.h"
#include "serialport/simulator_link.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QVBoxLayout>

namespace app {

namespace {
constexpr int kInputs = 16;
constexpr int kOutputs = 8;
constexpr int kRealPollMs = 500;

QString lampStyle(bool on) {
    return on ? QStringLiteral("QLabel{background:#34a853;color:white;border-radius:4px;padding:4px;font-weight:bold}")
              : QStringLiteral("QLabel{background:#e0e0e0;color:#5f6368;border-radius:4px;padding:4px}");
}

QPushButton* toggle(const QString& text, QWidget* parent) {
    auto* button = new QPushButton(text, parent);
    button->setCheckable(true);
    button->setMinimumWidth(44);
    button->setStyleSheet(QStringLiteral("QPushButton:checked{background:#1a73e8;color:white;font-weight:bold}"));
    return button;
}
} // namespace

template <typename Sender, typename Signal, typename Value>
void IoPanel::toBench(Sender* sender, Signal changed, void (drive_core::SimulatorControls::*set)(Value)) {
    connect(sender, changed, this, [this, set](Value v) { bench([set, v](drive_core::SimulatorControls& c) { (c.*set)(v); }); });
}

IoPanel::IoPanel(DriveConnection& connection, QWidget* parent)
    : QDockWidget(tr("I/O Panel"), parent), m_connection(connection) {
    setObjectName(QStringLiteral("ioPanel"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    m_source = new QLabel(body);
    m_source->setWordWrap(true);
    layout->addWidget(m_source);
    layout->addWidget(makeInputs());
    layout->addWidget(makeOutputs());
    m_benchBox = makeBench();
    layout->addWidget(m_benchBox);
    m_readout = new QLabel(body);
    m_readout->setStyleSheet(QStringLiteral("font-family:monospace"));
    layout->addWidget(m_readout);
    layout->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setWidget(body);
    setWidget(scroll);
    m_outputState.assign(kOutputs, false);

    connect(&m_connection, &DriveConnection::linkChanged, this, &IoPanel::followLink);
    connect(&m_connection, &DriveConnection::connectedChanged, this, &IoPanel::followLink);
    connect(&m_poll, &QTimer::timeout, this, &IoPanel::pollRealDrive);
    m_poll.start(kRealPollMs);
    followLink();
}

QWidget* IoPanel::makeInputs() {
    auto* box = new QGroupBox(tr("Inputs"), this);
    auto* grid = new QGridLayout(box);
    for (int i = 1; i <= kInputs; ++i) {
        QPushButton* button = toggle(QStringLiteral("I%1").arg(i), box);
        button->setObjectName(QStringLiteral("input%1").arg(i));
        grid->addWidget(button, (i - 1) / 8, (i - 1) % 8);
        connect(button, &QPushButton::toggled, this,
                [this, i](bool on) { bench([i, on](drive_core::SimulatorControls& c) { c.setInput(i, on); }); });
        m_inputs << button;
    }
    m_enable = toggle(tr("ENABLE"), box);
    m_motion = toggle(tr("MOTION"), box);
    m_home = toggle(tr("HOME"), box);
    m_posLimit = toggle(tr("+LIMIT"), box);
    m_negLimit = toggle(tr("\u2212LIMIT"), box);
    m_posLimit->setToolTip(tr("Pressed: the positive travel limit switch is tripped"));
    m_negLimit->setToolTip(tr("Pressed: the negative travel limit switch is tripped"));
    m_enable->setChecked(true);
    m_motion->setChecked(true);
    const QList<QPushButton*> dedicated{m_enable, m_motion, m_home, m_posLimit, m_negLimit};
    for (int k = 0; k < dedicated.size(); ++k) grid->addWidget(dedicated[k], 2, k < 3 ? k : k + 3);
    toBench(m_enable, &QPushButton::toggled, &drive_core::SimulatorControls::setEnableInput);
    toBench(m_motion, &QPushButton::toggled, &drive_core::SimulatorControls::setMotionInput);
    toBench(m_home, &QPushButton::toggled, &drive_core::SimulatorControls::setHomeSwitch);
    auto limits = [this] {
        const bool pos = m_posLimit->isChecked(), neg = m_negLimit->isChecked();
        bench([pos, neg](drive_core::SimulatorControls& c) { c.setLimitSwitches(pos, neg); });
    };
    connect(m_posLimit, &QPushButton::toggled, this, limits);
    connect(m_negLimit, &QPushButton::toggled, this, limits);
    return box;
}

QWidget* IoPanel::makeOutputs() {
    auto* box = new QGroupBox(tr("Outputs"), this);
    auto* row = new QHBoxLayout(box);
    for (int o = 1; o <= kOutputs; ++o) {
        auto* lamp = new QLabel(QStringLiteral("O%1").arg(o), box);
        lamp->setAlignment(Qt::AlignCenter);
        lamp->setMinimumWidth(36);
        lamp->setStyleSheet(lampStyle(false));
        row->addWidget(lamp);
        m_outputs << lamp;
    }
    return box;
}

QWidget* IoPanel::makeBench() {
    auto* box = new QGroupBox(tr("Bench (simulated drive only)"), this);
    auto* form = new QFormLayout(box);
    m_torque = new QDoubleSpinBox(box);
    m_torque->setRange(-100, 100);
    m_torque->setDecimals(2);
    m_torque->setSuffix(QStringLiteral(" N\u00b7m"));
    m_inertia = new QDoubleSpinBox(box);
    m_inertia->setRange(0, 1);
    m_inertia->setDecimals(5);
    m_inertia->setSingleStep(0.0001);
    m_inertia->setSuffix(QStringLiteral(" kg\u00b7m\u00b2"));
    // The coupling: 0 N m/rad is rigid. Up to 2000 N m/rad puts a resonance anywhere from a few Hz to well
    // past the drive's 500 Hz Nyquist limit with the reference motors and loads.
    m_stiffness = new QDoubleSpinBox(box);
    m_stiffness->setObjectName(QStringLiteral("couplingStiffness"));
    m_stiffness->setRange(0, 2000);
    m_stiffness->setDecimals(1);
    m_stiffness->setSingleStep(10);
    m_stiffness->setSuffix(QStringLiteral(" N\u00b7m/rad"));
    m_stiffness->setSpecialValueText(tr("rigid"));
    m_stiffness->setToolTip(tr("A compliant coupling between motor and load: the load becomes a second mass on a "
                               "spring, with a resonance the velocity loop can excite. 0 = rigid."));
    m_damping = new QDoubleSpinBox(box);
    m_damping->setObjectName(QStringLiteral("couplingDamping"));
    m_damping->setRange(0, 10);
    m_damping->setDecimals(4);
    m_damping->setSingleStep(0.001);
    m_damping->setSuffix(QStringLiteral(" N\u00b7m\u00b7s/rad"));
    m_resonance = new QLabel(tr("rigid: no resonance"), box);
    m_resonance->setObjectName(QStringLiteral("couplingResonance"));
    m_master = new QDoubleSpinBox(box);
    m_master->setRange(-1e6, 1e6);
    m_master->setDecimals(0);
    m_master->setSuffix(tr(" counts/s"));
    m_motor = new QComboBox(box);
    for (const auto& motor : drive_core::physics::referenceMotors())
        m_motor->addItem(QString::fromLatin1(motor.name.data(), qsizetype(motor.name.size())));
    m_powerCycle = new QPushButton(tr("Power Cycle"), box);
    form->addRow(tr("Load torque"), m_torque);
    form->addRow(tr("Load inertia"), m_inertia);
    form->addRow(tr("Coupling stiffness"), m_stiffness);
    form->addRow(tr("Coupling damping"), m_damping);
    form->addRow(tr("Resonance"), m_resonance);
    form->addRow(tr("Master encoder"), m_master);
    form->addRow(tr("Motor"), m_motor);
    form->addRow(QString(), m_powerCycle);
    toBench(m_torque, &QDoubleSpinBox::valueChanged, &drive_core::SimulatorControls::setLoadTorque_Nm);
    toBench(m_inertia, &QDoubleSpinBox::valueChanged, &drive_core::SimulatorControls::setLoadInertia_kgm2);
    auto coupling = [this] {
        const double k = m_stiffness->value(), d = m_damping->value();
        bench([k, d](drive_core::SimulatorControls& c) { c.setLoadCoupling(k, d); });
    };
    connect(m_stiffness, &QDoubleSpinBox::valueChanged, this, coupling);
    connect(m_damping, &QDoubleSpinBox::valueChanged, this, coupling);
    toBench(m_master, &QDoubleSpinBox::valueChanged, &drive_core::SimulatorControls::setMasterFrequency_Hz);
    connect(m_motor, &QComboBox::currentTextChanged, this, [this](const QString& name) {
        bench([name = name.toStdString()](drive_core::SimulatorControls& c) { c.selectMotor(name); });
    });
    connect(m_powerCycle, &QPushButton::clicked, this,
            [this] { bench([](drive_core::SimulatorControls& c) { c.powerCycle(); }); });
    return box;
}

bool IoPanel::isSimulated() const {
    return m_simulator != nullptr;
}

QString IoPanel::resonanceText() const {
    return m_resonance->text();
}

QString IoPanel::readoutText() const {
    return m_readout->text();
}

bool IoPanel::outputLit(int number) const {
    return number >= 1 && number <= int(m_outputState.size()) && m_outputState[std::size_t(number - 1)];
}

void IoPanel::followLink() {
    serialport::Bds5Session* session = m_connection.session();
    auto* simulator = session ? qobject_cast<serialport::SimulatorLink*>(&session->link()) : nullptr;
    if (session != m_session) {
        m_session = session;
        if (session) connect(session, &serialport::Bds5Session::finished, this, &IoPanel::onFinished);
    }
    if (simulator != m_simulator) {
        m_simulator = simulator;
        if (simulator) connect(simulator, &serialport::SimulatorLink::simulatorStatus, this, &IoPanel::showStatus);
    }
    m_benchBox->setEnabled(simulator != nullptr);
    for (QPushButton* b : {m_enable, m_motion, m_home, m_posLimit, m_negLimit}) b->setEnabled(simulator != nullptr);
    for (QPushButton* b : m_inputs) b->setEnabled(simulator != nullptr);
    m_source->setText(simulator ? tr("Simulated drive: the buttons drive its input pins directly, as a test "
                                     "bench would; nothing goes over the serial line.")
                                : tr("Real drive: inputs and outputs as read from the drive (P IN OUT)."));
}

void IoPanel::bench(std::function<void(drive_core::SimulatorControls&)> change) {
    if (m_simulator) m_simulator->control(std::move(change));
}

void IoPanel::showStatus(const drive_core::SimulatorStatus& status) {
    for (int i = 0; i < int(m_inputs.size()) && i < int(status.inputs.size()); ++i) {
        const QSignalBlocker quiet(m_inputs[i]);
        m_inputs[i]->setChecked(status.inputs[std::size_t(i)]);
    }
    const std::pair<QPushButton*, bool> dedicated[] = {{m_enable, status.enableInput},
                                                       {m_motion, status.motionInput},
                                                       {m_home, status.homeSwitch},
                                                       {m_posLimit, status.positiveLimit},
                                                       {m_negLimit, status.negativeLimit}};
    for (const auto& [button, on] : dedicated) {
        const QSignalBlocker quiet(button);
        button->setChecked(on);
    }
    // The bench's own values, unless the user is changing them right now.
    auto follow = [](QDoubleSpinBox* box, double value) {
        if (box->hasFocus()) return;
        const QSignalBlocker quiet(box);
        box->setValue(value);
    };
    follow(m_torque, status.loadTorque_Nm);
    follow(m_inertia, status.loadInertia_kgm2);
    follow(m_master, status.masterFrequency_Hz);
    follow(m_stiffness, status.couplingStiffness_NmPerRad);
    follow(m_damping, status.couplingDamping_NmPerRadPerS);
    m_resonance->setText(status.resonance_Hz > 0
                             ? tr("%1 Hz (motor and load on the spring)").arg(status.resonance_Hz, 0, 'f', 1)
                             : tr("rigid: no resonance"));
    if (const QString motor = QString::fromStdString(status.motorName); !motor.isEmpty() && !m_motor->hasFocus()) {
        const QSignalBlocker quiet(m_motor);
        m_motor->setCurrentText(motor);
    }
    showOutputs(status.outputs);
    m_readout->setText(tr("%1%2  pos %3 rev  vel %4 rpm  I %5 A  %6")
                           .arg(status.active ? tr("ACTIVE") : tr("inactive"), status.fault ? tr(" FAULT") : QString())
                           .arg(status.position_rev, 0, 'f', 3)
                           .arg(status.velocity_rpm, 0, 'f', 1)
                           .arg(status.current_a, 0, 'f', 2)
                           .arg(QString::fromStdString(status.motorName)));
}

void IoPanel::showOutputs(const std::vector<bool>& outputs) {
    for (int o = 0; o < int(m_outputs.size()) && o < int(outputs.size()); ++o) {
        if (m_outputState[std::size_t(o)] == outputs[std::size_t(o)]) continue;
        m_outputState[std::size_t(o)] = outputs[std::size_t(o)];
        m_outputs[o]->setStyleSheet(lampStyle(outputs[std::size_t(o)]));
    }
}

void IoPanel::pollRealDrive() {
    if (m_simulator || !isVisible() || !m_session || m_pollId) return;
    if (m_session->mode() != serialport::Bds5Mode::Interactive ||
        m_session->state() != serialport::Bds5Session::State::Ready)
        return;
    m_pollId = m_session->send(QStringLiteral("P IN OUT"), serialport::Bds5Session::Echo::Quiet);
}

void IoPanel::onFinished(quint64 id, const serialport::Bds5Response& response) {
    if (id != m_pollId) return;
    m_pollId = 0;
    static const QRegularExpression kBlanks(QStringLiteral("\\s+"));
    const QStringList words = response.lines.join(QLatin1Char(' ')).split(kBlanks, Qt::SkipEmptyParts);
    if (words.size() != 2) return;
    const int in = words[0].toInt(), out = words[1].toInt();
    for (int i = 0; i < int(m_inputs.size()); ++i) {
        const QSignalBlocker quiet(m_inputs[i]);
        m_inputs[i]->setChecked(in & (1 << i));
    }
    std::vector<bool> outputs;
    for (int o = 0; o < kOutputs; ++o) outputs.push_back(out & (1 << o));
    showOutputs(outputs);
}

} // namespace app
