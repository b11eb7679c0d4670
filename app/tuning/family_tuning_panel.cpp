// FamilyTuningPanel: layout and wiring; the runs table.
#include "family_tuning_panel.h"

#include "tuning_frame.h"

#include "app/scope/bode_view.h"
#include "scope/measurements_table.h"
#include "scope/scope_view.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

namespace {
const QStringList kRunColumns = {QStringLiteral("Run"),       QStringLiteral("Gains changed"),
                                 QStringLiteral("Overshoot %"), QStringLiteral("Rise (ms)"),
                                 QStringLiteral("Settle (ms)"), QStringLiteral("Sampled")};
} // namespace

FamilyTuningPanel::FamilyTuningPanel(TuningProfile profile, QWidget* parent)
    : QWidget(parent), m_runner(new FamilyTuningRunner(std::move(profile), this)), m_view(new ScopeView(this)),
      m_runsTable(new QTableWidget(this)) {
    setObjectName(QStringLiteral("familyTuningPanel"));
    // The runs table measures each run's step; the scope's own table would measure the whole record, the
    // move back included.
    m_view->measurements()->hide();
    auto* controls = new QWidget;
    auto* left = new QVBoxLayout(controls);
    left->setContentsMargins(4, 4, 4, 4);
    left->addWidget(buildGains());
    left->addWidget(buildTestMove());
    left->addStretch(1);

    m_runsTable->setObjectName(QStringLiteral("familyTuningRuns"));
    setUpRunsTable(m_runsTable, kRunColumns);
    m_undo = new QPushButton(tr("Undo to Selected Run's Gains"), this);
    m_bodeButton = new QPushButton(tr("Frequency Response..."), this);
    m_bodeButton->setToolTip(tr("The velocity loop's Bode plot (%1 \u2192 %2) of the selected run, or the last")
                                 .arg(m_runner->profile().command, m_runner->profile().monitor));
    layOutTuningFrame(this, controls, m_view, m_runsTable, {m_undo, m_bodeButton});

    connect(m_undo, &QPushButton::clicked, this, [this] {
        if (const int run = selectedRunNumber(m_runsTable)) m_runner->undoTo(run);
    });
    connect(m_bodeButton, &QPushButton::clicked, this, &FamilyTuningPanel::frequencyResponse);
    connect(m_runsTable, &QTableWidget::itemSelectionChanged, this, [this] {
        updateButtons();
        if (m_bode && m_bode->isVisible()) showBode();
    });
    connect(m_runner, &FamilyTuningRunner::gainConfirmed, this,
            [this](const QString& name, double value) { showGain(name, value, QStringLiteral("\u2713")); });
    connect(m_runner, &FamilyTuningRunner::gainRefused, this, [this](const QString& name, const QString& why) {
        if (QLabel* mark = m_marks.value(name)) {
            mark->setText(QStringLiteral("\u2717"));
            mark->setToolTip(why);
        }
        setStatus(tr("The drive refused %1: %2").arg(name, why));
    });
    connect(m_runner, &FamilyTuningRunner::gainsRead, this, [this](const QMap<QString, double>& gains) {
        for (auto it = gains.begin(); it != gains.end(); ++it) showGain(it.key(), it.value(), QStringLiteral("\u2713"));
        setStatus(tr("Read %n gain(s) from the drive.", nullptr, int(gains.size())));
    });
    connect(m_runner, &FamilyTuningRunner::runStarted, this, [this](int n) {
        setStatus(tr("Run %1: %2, %3 %4, held %5 ms\u2026")
                      .arg(n)
                      .arg(m_runner->move().name)
                      .arg(m_runner->amplitude())
                      .arg(m_runner->move().amplitudeUnit)
                      .arg(m_runner->holdMs()));
    });
    connect(m_runner, &FamilyTuningRunner::runFinished, this, &FamilyTuningPanel::addRun);
    connect(m_runner, &FamilyTuningRunner::runFailed, this,
            [this](const QString& why) { setStatus(tr("Not run: %1").arg(why)); });
    connect(m_runner, &FamilyTuningRunner::message, this, &FamilyTuningPanel::setStatus);
    connect(m_runner, &FamilyTuningRunner::stateChanged, this, &FamilyTuningPanel::updateButtons);
    applyMove();
    updateButtons();
    setStatus(tr("Not connected."));
}

QWidget* FamilyTuningPanel::buildGains() {
    const auto [box, form] = addControlGroup(this, tr("Gains"));
    for (const TuningGain& g : m_runner->profile().gains) {
        auto* spin = new QDoubleSpinBox(box);
        spin->setObjectName(QStringLiteral("gain_") + g.name);
        spin->setDecimals(g.decimals);
        spin->setRange(g.minimum, g.maximum);
        spin->setKeyboardTracking(false); // one change per Enter or arrow, never per keystroke
        if (!g.unit.isEmpty()) spin->setSuffix(QLatin1Char(' ') + g.unit);
        spin->setToolTip(g.parameter == g.name ? g.description : QStringLiteral("%1 (%2): %3").arg(g.name, g.parameter, g.description));
        auto* mark = new QLabel(box);
        mark->setMinimumWidth(16);
        auto* row = new QHBoxLayout;
        row->addWidget(spin, 1);
        row->addWidget(mark);
        form->addRow(g.name, row);
        m_editors.insert(g.name, spin);
        m_marks.insert(g.name, mark);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, name = g.name](double value) {
            if (m_showing) return;
            m_marks.value(name)->setText(QStringLiteral("\u2026"));
            m_runner->setGain(name, value);
        });
    }
    addReadGains({box, form}, m_runner);
    auto* note = new QLabel(m_runner->profile().prepareNote, box);
    note->setWordWrap(true);
    form->addRow(note);
    return box;
}

QWidget* FamilyTuningPanel::buildTestMove() {
    const auto [box, form] = addControlGroup(this, tr("Test move"));
    m_move = new QComboBox(box);
    for (const TuningMove& m : m_runner->profile().moves) m_move->addItem(m.name);
    m_amplitude = new QSpinBox(box);
    m_amplitude->setRange(1, 1'000'000);
    m_hold = new QSpinBox(box);
    m_hold->setRange(20, 5000);
    m_hold->setValue(300);
    m_hold->setSuffix(tr(" ms"));
    m_hold->setToolTip(tr("How long the move runs before it goes back, and how long the response is watched after."));
    m_moveText = new QLabel(box);
    m_moveText->setWordWrap(true);
    form->addRow(tr("Preset"), m_move);
    form->addRow(tr("Amplitude"), m_amplitude);
    form->addRow(tr("Hold"), m_hold);
    form->addRow(m_moveText);
    connect(m_move, &QComboBox::currentIndexChanged, this, [this](int index) {
        m_amplitude->setValue(m_runner->profile().moves.value(index).amplitude);
        applyMove();
    });
    m_amplitude->setValue(m_runner->profile().moves.value(0).amplitude);
    connect(m_amplitude, &QSpinBox::valueChanged, this, &FamilyTuningPanel::applyMove);
    connect(m_hold, &QSpinBox::valueChanged, this, &FamilyTuningPanel::applyMove);
    m_run = addRunButtons(box, form, m_runner);
    m_status = addStatusLine(box, form, QStringLiteral("familyTuningStatus"));
    return box;
}

void FamilyTuningPanel::attach(serialport::DriveSession* session, serialport::Link* link) {
    m_runner->attach(session, link);
    setStatus(session ? tr("Connected: reading the gains\u2026") : tr("Not connected."));
    if (session) m_runner->readGains();
    updateButtons();
}

void FamilyTuningPanel::applyMove() {
    m_runner->setMove(m_move->currentIndex(), m_amplitude->value(), m_hold->value());
    const TuningMove& move = m_runner->move();
    m_amplitude->setSuffix(QLatin1Char(' ') + move.amplitudeUnit);
    m_moveText->setText(move.description + QStringLiteral(".\n") +
                        m_runner->profile().lines(move.start, m_amplitude->value()).join(QStringLiteral(", ")) +
                        QStringLiteral(" \u2192 ") +
                        m_runner->profile().lines(move.back, m_amplitude->value()).join(QStringLiteral(", ")));
}

void FamilyTuningPanel::showGain(const QString& name, double value, const QString& mark) {
    if (QDoubleSpinBox* spin = m_editors.value(name)) {
        m_showing = true;
        spin->setValue(value);
        m_showing = false;
    }
    if (QLabel* label = m_marks.value(name)) {
        label->setText(mark);
        label->setToolTip(tr("The drive holds this value."));
    }
}

QString FamilyTuningPanel::gainMark(const QString& name) const {
    const QLabel* mark = m_marks.value(name);
    if (!mark) return {};
    return mark->text() == QStringLiteral("\u2717") ? mark->text() + QLatin1Char(' ') + mark->toolTip() : mark->text();
}

void FamilyTuningPanel::addRun(const FamilyTuningRun& run) {
    m_view->showCapture(run.capture, true);
    const QString changed = QString::fromStdString(run.capture.title).section(QStringLiteral(": "), 1);
    RunRow row;
    row.cells = {QString::number(run.number),
                 changed.isEmpty() ? (run.number == 1 ? tr("(first)") : tr("(none)")) : changed,
                 run.metrics.hasStep ? QString::number(run.metrics.overshoot_pct, 'f', 1) : QStringLiteral("\u2014"),
                 milliseconds(run.metrics.rise_s),
                 milliseconds(run.metrics.settling_s),
                 run.fault.isEmpty() ? run.source : tr("FAULT %1; %2").arg(run.fault, run.source)};
    row.leftAligned = {1, 5};
    if (!run.fault.isEmpty()) row.fault = tr("The drive faulted during this run: %1").arg(run.fault);
    appendRun(m_runsTable, row);
    if (m_bode && m_bode->isVisible() && m_runsTable->currentRow() < 0) showBode(); // follows the newest run
    if (!run.fault.isEmpty())
        return setStatus(tr("Run %1: the drive faulted — %2. The response is shown up to the fault; the next run "
                            "clears it first (%3).")
                             .arg(run.number)
                             .arg(run.fault, m_runner->profile().clearFault.join(QStringLiteral(", "))));
    if (!run.metrics.hasStep)
        return setStatus(tr("Run %1: the response did not move — is the drive enabled and the move allowed?").arg(run.number));
    setStatus(tr("Run %1: overshoot %2 %, rise %3 ms, settle %4 ms.")
                  .arg(run.number)
                  .arg(run.metrics.overshoot_pct, 0, 'f', 1)
                  .arg(milliseconds(run.metrics.rise_s), milliseconds(run.metrics.settling_s)));
}

BodeView* FamilyTuningPanel::frequencyResponse() {
    if (!m_bode) m_bode = new BodeView(this);
    showBode();
    m_bode->show();
    m_bode->raise();
    return m_bode;
}

void FamilyTuningPanel::showBode() {
    const QList<FamilyTuningRun>& runs = m_runner->runs();
    if (runs.isEmpty())
        return m_bode->showNothing(tr("No run yet: Run Once, then the frequency response of its %1 \u2192 %2.")
                                       .arg(m_runner->profile().command, m_runner->profile().monitor));
    const int selected = selectedRunNumber(m_runsTable);
    const int number = selected > 0 ? selected : runs.back().number;
    for (const FamilyTuningRun& run : runs)
        if (run.number == number)
            m_bode->showCapture(run.capture, m_runner->profile().command, m_runner->profile().monitor);
}

void FamilyTuningPanel::updateButtons() {
    m_run.update(m_runner->isRunning(), m_runner->isContinuous(), m_runner->isContinuous());
    m_undo->setEnabled(m_runsTable->currentRow() >= 0);
}

void FamilyTuningPanel::setStatus(const QString& text) {
    m_status->setText(text);
}

QString FamilyTuningPanel::statusText() const {
    return m_status->text();
}

} // namespace app
