// TuningPanel: layout and wiring; the runs table.
#include "tuning_panel.h"

#include "app/tuning/tuning_frame.h"

#include "families/bds5/drive_connection.h"
#include "gain_editor.h"
#include "main_window.h"
#include "app/scope/scope_controller.h"
#include "app/scope/scope_view.h"

#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

namespace {
const QStringList kRunColumns = {QStringLiteral("Run"),         QStringLiteral("Gains changed"),
                                 QStringLiteral("Overshoot %"), QStringLiteral("Rise (ms)"),
                                 QStringLiteral("Settle (ms)"), QStringLiteral("SS error"),
                                 QStringLiteral("Cycle (s)"),   QStringLiteral("\u00d7 ideal")};
const int kBandwidths[] = {5, 10, 15, 20, 25, 30, 40, 50}; // Hz, the values TUNE allows (L6283)

} // namespace

TuningPanel::TuningPanel(MainWindow& window, QWidget* parent)
    : QWidget(parent), m_window(window), m_runner(new TuningRunner(window.connection(), this)),
      m_view(new ScopeView(this)), m_runsTable(new QTableWidget(this)) {
    setObjectName(QStringLiteral("tuningPanel"));
    auto* controls = new QWidget;
    auto* left = new QVBoxLayout(controls);
    left->setContentsMargins(4, 4, 4, 4);
    left->addWidget(buildGains());
    left->addWidget(buildTestMove());
    left->addWidget(buildTune());
    left->addStretch(1);

    m_runsTable->setObjectName(QStringLiteral("tuningRuns"));
    setUpRunsTable(m_runsTable, kRunColumns);
    m_undo = new QPushButton(tr("Undo to Selected Run's Gains"), this);
    auto* save = new QPushButton(tr("Save Gains .VAR..."), this);
    auto* bode = new QPushButton(tr("Frequency Response..."), this);
    layOutTuningFrame(this, controls, m_view, m_runsTable, {m_undo, save, bode});

    connect(m_undo, &QPushButton::clicked, this, [this] {
        if (const int run = selectedRunNumber(m_runsTable)) m_runner->undoTo(run);
    });
    connect(save, &QPushButton::clicked, this, &TuningPanel::saveGainsAs);
    connect(bode, &QPushButton::clicked, this, [this] { m_window.scopeController().frequencyResponse(); });
    connect(m_runner, &TuningRunner::gainConfirmed, this, [this](const QString& name, int value) {
        if (GainEditor* e = m_editors.value(name)) {
            e->setValue(value); // also when the change came from elsewhere (undo, a preset)
            e->setConfirmed(true);
        }
    });
    connect(m_runner, &TuningRunner::gainRefused, this, [this](const QString& name, const QString& why) {
        if (GainEditor* e = m_editors.value(name)) e->setConfirmed(false, why);
        setStatus(tr("The drive refused %1: %2").arg(name, why));
    });
    connect(m_runner, &TuningRunner::gainsRead, this, [this](const QMap<QString, int>& gains) {
        for (auto it = gains.begin(); it != gains.end(); ++it)
            if (GainEditor* e = m_editors.value(it.key())) {
                e->setValue(it.value());
                e->setConfirmed(true);
            }
    });
    connect(m_runner, &TuningRunner::runStarted, this,
            [this](int n) { setStatus(tr("Run %1: %2").arg(n).arg(m_runner->testMove().description())); });
    connect(m_runner, &TuningRunner::progress, this, [this](int done, int total) {
        m_progress->setMaximum(std::max(total, 1));
        m_progress->setValue(done);
    });
    connect(m_runner, &TuningRunner::runFinished, this, &TuningPanel::addRun);
    connect(m_runner, &TuningRunner::runFailed, this, &TuningPanel::setStatus);
    connect(m_runner, &TuningRunner::softLimitsInTheWay, this, &TuningPanel::askAboutSoftLimits);
    connect(m_runner, &TuningRunner::message, this, &TuningPanel::setStatus);
    connect(m_runner, &TuningRunner::stateChanged, this, &TuningPanel::updateButtons);
    // The editors show the drive's gains from the start (the read waits in the session's queue).
    connect(&window.connection(), &DriveConnection::connectedChanged, m_runner, [this](bool connected) {
        if (connected) m_runner->readGains();
    });
    applyTestMove();
    updateProposal();
    updateButtons();
}

QWidget* TuningPanel::buildGains() {
    const auto [box, form] = addControlGroup(this, tr("Gains"));
    for (const GainInfo& g : tuningGains()) {
        auto* editor = new GainEditor(g, box);
        m_editors.insert(g.name, editor);
        form->addRow(g.name, editor);
        connect(editor, &GainEditor::edited, m_runner, &TuningRunner::setGain);
    }
    addReadGains({box, form}, m_runner);
    return box;
}

QWidget* TuningPanel::buildTestMove() {
    const auto [box, form] = addControlGroup(this, tr("Test move"));
    m_moveKind = new QComboBox(box);
    for (const auto kind : {TestMove::Kind::VelocityStep, TestMove::Kind::PositionStep, TestMove::Kind::BackAndForth,
                            TestMove::Kind::FrequencyStep})
        m_moveKind->addItem(TestMove::kindName(kind), int(kind));
    m_amplitude = new QSpinBox(box);
    m_amplitude->setRange(1, 1'000'000);
    m_amplitude->setValue(1000);
    m_amplitude->setToolTip(tr("Velocity (J) or counts (MI). Proposed from the drive's ILIM, IMAX, KV, ACC and "
                               "units so that ICMD stays at most about half of ILIM."));
    m_duration = new QSpinBox(box);
    m_duration->setRange(10, 10'000);
    m_duration->setValue(150);
    m_duration->setSuffix(tr(" ms"));
    auto* propose = new QPushButton(tr("Propose"), box);
    propose->setToolTip(tr("Set the amplitude proposed from the drive's values."));
    auto* amplitudeRow = new QHBoxLayout;
    amplitudeRow->addWidget(m_amplitude, 1);
    amplitudeRow->addWidget(propose);
    m_proposal = new QLabel(box);
    m_proposal->setObjectName(QStringLiteral("tuningProposal"));
    m_proposal->setWordWrap(true);
    form->addRow(tr("Preset"), m_moveKind);
    form->addRow(tr("Amplitude"), amplitudeRow);
    form->addRow(m_proposal);
    form->addRow(tr("Hold"), m_duration);
    connect(propose, &QPushButton::clicked, this, &TuningPanel::useProposedAmplitude);
    connect(m_moveKind, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_settingFields) m_followProposal = true; // a preset chosen by the user gets its proposal
        updateProposal();
        applyTestMove();
    });
    connect(m_amplitude, &QSpinBox::valueChanged, this, [this] {
        if (!m_settingFields) m_followProposal = false; // the user's own amplitude stays
        applyTestMove();
    });
    connect(m_duration, &QSpinBox::valueChanged, this, [this] {
        // The user's new hold: the position step's speed goes with it (the amplitude stays).
        if (!m_settingFields && !m_runner->driveValues().isEmpty())
            m_moveVelocity = TestMove::proposedMoveVelocity(m_duration->value(), proposalValues());
        updateProposal();
        applyTestMove();
    });
    connect(m_runner, &TuningRunner::driveValuesRead, this, &TuningPanel::updateProposal);
    connect(m_runner, &TuningRunner::gainConfirmed, this, &TuningPanel::updateProposal);
    m_run = addRunButtons(box, form, m_runner);
    m_progress = new QProgressBar(box);
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(8);
    form->addRow(m_progress);
    m_status = addStatusLine(box, form, QStringLiteral("tuningStatus"));
    m_warning = new QLabel(box);
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("color: #b3261e"));
    m_warning->hide();
    form->addRow(m_warning);
    return box;
}

QWidget* TuningPanel::buildTune() {
    const auto [box, form] = addControlGroup(this, tr("TUNE (self-tuning)"));
    m_bandwidth = new QComboBox(box);
    for (const int hz : kBandwidths) m_bandwidth->addItem(tr("%1 Hz").arg(hz), hz);
    m_bandwidth->setCurrentIndex(5); // 30 Hz, the manual's example
    m_stability = new QComboBox(box);
    m_stability->addItem(tr("1 \u2014 slightly overdamped"), 1);
    m_stability->addItem(tr("2 \u2014 critically damped"), 2);
    m_stability->addItem(tr("3 \u2014 slightly underdamped"), 3);
    m_stability->setCurrentIndex(1);
    form->addRow(tr("Bandwidth"), m_bandwidth);
    form->addRow(tr("Stability"), m_stability);
    auto* warning = new QLabel(tr("<b>Warning:</b> the drive will be enabled and the motor will turn. TUNE shakes "
                                  "the motor vigorously at about 15 Hz and full torque: secure the motor, and "
                                  "reduce ILIM first if the machine could be damaged or overspeed (restore it "
                                  "afterwards)."),
                               box);
    warning->setWordWrap(true);
    form->addRow(warning);
    auto* tune = new QPushButton(tr("TUNE"), box);
    connect(tune, &QPushButton::clicked, this,
            [this] { m_runner->tune(m_bandwidth->currentData().toInt(), m_stability->currentData().toInt()); });
    form->addRow(tune);
    return box;
}

void TuningPanel::applyTestMove() {
    TestMove move;
    move.kind = TestMove::Kind(m_moveKind->currentData().toInt());
    move.amplitude = m_amplitude->value();
    move.durationMs = m_duration->value();
    if (move.kind == TestMove::Kind::PositionStep) move.moveVelocity = m_moveVelocity;
    m_runner->setTestMove(move);
    m_moveKind->setToolTip(move.plan().recordLine() + QStringLiteral(" \u2014 ") + move.description());
}

void TuningPanel::setTestMove(const TestMove& move) {
    m_followProposal = false;
    m_settingFields = true;
    m_moveKind->setCurrentIndex(m_moveKind->findData(int(move.kind)));
    m_amplitude->setValue(move.amplitude);
    m_duration->setValue(move.durationMs);
    m_settingFields = false;
    m_moveVelocity = move.moveVelocity > 0 || m_runner->driveValues().isEmpty()
                         ? move.moveVelocity
                         : TestMove::proposedMoveVelocity(move.durationMs, proposalValues());
    applyTestMove();
}

TestMove::DriveValues TuningPanel::proposalValues() const {
    TestMove::DriveValues values = m_runner->driveValues();
    for (const char* name : {"ILIM", "KV"}) // the gains as last sent win over the values as last read
        if (m_runner->gains().contains(QLatin1String(name)))
            values[QLatin1String(name)] = m_runner->gains().value(QLatin1String(name));
    return values;
}

int TuningPanel::proposedAmplitude() const {
    return TestMove::proposedAmplitude(TestMove::Kind(m_moveKind->currentData().toInt()), m_duration->value(),
                                       proposalValues());
}

void TuningPanel::useProposedAmplitude() {
    m_followProposal = true;
    updateProposal();
}

// The "Proposed:" line follows every gain; the Amplitude field takes the proposal once and keeps it (a gain change
// re-proposing it made run 1 J 2596, run 2 J 1298, run 3 J 3750: overlays of different moves).
void TuningPanel::updateProposal() {
    const int proposed = proposedAmplitude();
    const bool known = !m_runner->driveValues().isEmpty();
    m_proposal->setText(known ? tr("Proposed: %1, so that ICMD stays at most about half of ILIM.").arg(proposed)
                              : tr("Proposed amplitude: once the drive's values are read."));
    if (known && m_followProposal) {
        m_followProposal = false;
        m_moveVelocity = TestMove::proposedMoveVelocity(m_duration->value(), proposalValues());
        m_settingFields = true;
        m_amplitude->setValue(proposed);
        m_settingFields = false;
    }
    applyTestMove();
}

QString TuningPanel::proposalText() const {
    return m_proposal->text();
}

QMessageBox* TuningPanel::softLimitsQuestion() const {
    return m_limitsQuestion;
}

// Non-modal: the run waits in the runner until the answer (or Stop) comes.
void TuningPanel::askAboutSoftLimits(const QString& why) {
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Software Travel Limits"),
                                why + QStringLiteral("\n\n") +
                                    tr("At power-up PMAX and PMIN are only +-100 counts. Set them for the machine "
                                       "to keep the limits on, or turn the limits off for this test: ServoDesk "
                                       "sends PLIM=0 before the run and PLIM=1 once it is over."),
                                QMessageBox::Cancel, &m_window);
    box->setObjectName(QStringLiteral("softLimitsQuestion"));
    QPushButton* off = box->addButton(tr("Turn off the soft limits (PLIM=0) for the test"), QMessageBox::AcceptRole);
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    m_limitsQuestion = box;
    connect(box, &QMessageBox::finished, this, [this, box, off](int) {
        if (!m_runner->isWaitingForAnswer()) return; // stopped meanwhile
        if (box->clickedButton() == off) return m_runner->runWithoutSoftLimits();
        m_runner->stop();
        setStatus(tr("Not run: the test move would pass the software travel limits. Set PMAX and PMIN for the "
                     "machine, or run again and turn the limits off for the test."));
    });
    setStatus(tr("Waiting: the test move would pass the software travel limits (PMAX/PMIN)."));
    box->open();
}

QString TuningPanel::warningText() const {
    return m_warning->isHidden() ? QString() : m_warning->text(); // also while the dock is closed
}

void TuningPanel::addRun(const TuningRun& run) {
    m_view->showCapture(run.capture, true);
    const QString changed = QString::fromStdString(run.capture.title).section(QStringLiteral(": "), 1);
    RunRow row;
    row.cells = {QString::number(run.number),
                 changed.isEmpty() ? tr("(first)") : changed,
                 run.metrics.hasStep ? QString::number(run.metrics.overshoot_pct, 'f', 1) : QStringLiteral("\u2014"),
                 milliseconds(run.metrics.rise_s),
                 milliseconds(run.metrics.settling_s),
                 run.metrics.steadyStateError ? QString::number(*run.metrics.steadyStateError, 'f', 1)
                                              : QStringLiteral("\u2014"),
                 QString::number(run.cycle_s, 'f', 2),
                 QString::number(run.cycle_s / std::max(run.ideal_s, 1e-9), 'f', 2)};
    row.leftAligned = {1};
    appendRun(m_runsTable, row);
    m_progress->setValue(m_progress->maximum());
    m_warning->setVisible(run.currentSaturated);
    m_warning->setText(tr("ICMD reached ILIM in run %1: the current saturated, so the step shows the current "
                          "limit rather than the loop. Lower the amplitude.")
                           .arg(run.number));
    QString status = tr("Run %1: overshoot %2 %, rise %3 ms, settle %4 ms.")
                         .arg(run.number)
                         .arg(run.metrics.overshoot_pct, 0, 'f', 1)
                         .arg(milliseconds(run.metrics.rise_s), milliseconds(run.metrics.settling_s));
    if (run.softLimitsOff) status += tr(" The soft limits were off for it (PLIM=0); PLIM=1 follows the runs.");
    setStatus(status);
}

void TuningPanel::updateButtons() {
    if (m_limitsQuestion && !m_runner->isWaitingForAnswer()) m_limitsQuestion->close(); // Stop answered it
    m_run.update(m_runner->isRunning(), m_runner->isContinuous(), m_runner->isRunning());
}

void TuningPanel::setStatus(const QString& text) {
    m_status->setText(text);
}

QString TuningPanel::statusText() const {
    return m_status->text();
}

void TuningPanel::saveGainsAs() {
    auto* dialog = new QFileDialog(this, tr("Save Gains"), QStringLiteral("gains.var"),
                                   tr("Variable sets (*.var *.VAR);;All files (*)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("var"));
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
        QFile file(path);
        const bool ok =
            file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(m_runner->gainsAsVar().toLatin1()) >= 0;
        setStatus(ok ? tr("Saved the gains to %1.").arg(path) : tr("Cannot write %1.").arg(path));
    });
    dialog->open();
}

} // namespace app
