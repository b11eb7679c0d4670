// TuningPanel: layout and wiring; the gains, the test move, the runs table.
#include "tuning_panel.h"

#include "app/scope/bode_view.h"
#include "scope/measurements_table.h"
#include "scope/scope_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace app {

namespace {
constexpr int kSliderSteps = 1000; // a real-valued gain's slider; an integer one moves by one up to this many
const QString kConfirmed = QStringLiteral("\u2713");
const QString kRefused = QStringLiteral("\u2717");
const QString kSent = QStringLiteral("\u2026");

int sliderSteps(const TuningGain& g) {
    const double span = g.maximum - g.minimum;
    return g.decimals == 0 && span <= kSliderSteps ? int(span) : kSliderSteps;
}
} // namespace

TuningPanel::TuningPanel(Tuner* tuner, QWidget* parent)
    : QWidget(parent), m_tuner(tuner), m_view(new ScopeView(this)), m_runsTable(new QTableWidget(this)) {
    tuner->setParent(this);
    setObjectName(QStringLiteral("tuningPanel"));
    // The runs table measures each run's step; the scope's own table would measure the whole record, the
    // move back included.
    m_view->measurements()->hide();
    auto* controls = new QWidget;
    m_controls = new QVBoxLayout(controls);
    m_controls->setContentsMargins(4, 4, 4, 4);
    m_controls->addWidget(buildGains());
    m_controls->addWidget(buildTestMove());
    m_controls->addStretch(1);

    m_runsTable->setObjectName(QStringLiteral("tuningRuns"));
    setUpRunsTable(m_runsTable, QStringList{tr("Run"), tr("Gains changed"), tr("Overshoot %"), tr("Rise (ms)"),
                                            tr("Settle (ms)")} +
                                    m_tuner->extraColumns());
    m_undo = new QPushButton(tr("Undo to Selected Run's Gains"), this);
    QList<QPushButton*> buttons{m_undo};
    if (m_tuner->gainsFile()) {
        auto* save = new QPushButton(tr("Save Gains..."), this);
        connect(save, &QPushButton::clicked, this, &TuningPanel::saveGainsAs);
        buttons << save;
    }
    auto* bode = new QPushButton(tr("Frequency Response..."), this);
    const auto [input, output] = m_tuner->bodeProbes();
    bode->setToolTip(tr("The velocity loop's Bode plot (%1 \u2192 %2) of the selected run, or the last").arg(input, output));
    buttons << bode;
    layOutTuningFrame(this, controls, m_view, m_runsTable, buttons);

    connect(m_undo, &QPushButton::clicked, this, [this] {
        if (const int run = selectedRunNumber(m_runsTable)) m_tuner->undoTo(run);
    });
    connect(bode, &QPushButton::clicked, this, &TuningPanel::frequencyResponse);
    connect(m_runsTable, &QTableWidget::itemSelectionChanged, this, [this] {
        updateButtons();
        if (m_bode && m_bode->isVisible()) showBode();
    });
    connect(m_tuner, &Tuner::gainAnswered, this, [this](const QString& name, double value, const QString& refusal) {
        if (refusal.isEmpty()) showGain(name, value); // also when the change came from elsewhere (undo, TUNE)
        markGain(name, refusal);
        if (!refusal.isEmpty()) setStatus(tr("The drive refused %1: %2").arg(name, refusal));
    });
    connect(m_tuner, &Tuner::gainValuesRead, this, [this](const QMap<QString, double>& gains) {
        for (auto it = gains.begin(); it != gains.end(); ++it) {
            showGain(it.key(), it.value());
            markGain(it.key(), {});
        }
    });
    connect(m_tuner, &Tuner::proposalChanged, this, &TuningPanel::updateProposal);
    connect(m_tuner, &Tuner::runStarted, this, [this](int n) { setStatus(m_tuner->runStartText(n)); });
    connect(m_tuner, &Tuner::progress, this, [this](int done, int total) {
        m_progress->show();
        m_progress->setMaximum(std::max(total, 1));
        m_progress->setValue(done);
    });
    connect(m_tuner, &Tuner::runShown, this, &TuningPanel::addRun);
    connect(m_tuner, &Tuner::runFailed, this, &TuningPanel::setStatus);
    connect(m_tuner, &Tuner::message, this, &TuningPanel::setStatus);
    connect(m_tuner, &Tuner::stateChanged, this, &TuningPanel::updateButtons);
    applyMove();
    updateProposal();
    updateButtons();
}

QWidget* TuningPanel::buildGains() {
    const auto [box, form] = addControlGroup(this, tr("Gains"));
    for (const TuningGain& g : m_tuner->tunerGains()) addGain(box, form, g);
    int widest = 0; // every value as wide as the widest ("0.174000 A/(rad/s)"), so that the sliders line up
    for (const QDoubleSpinBox* spin : std::as_const(m_editors)) widest = std::max(widest, spin->sizeHint().width());
    for (QDoubleSpinBox* spin : std::as_const(m_editors)) spin->setMinimumWidth(widest);
    addReadGains({box, form}, m_tuner);
    if (const QString note = m_tuner->gainsNote(); !note.isEmpty()) {
        auto* label = new QLabel(note, box);
        label->setWordWrap(true);
        form->addRow(label);
    }
    return box;
}

void TuningPanel::addGain(QWidget* box, QFormLayout* form, const TuningGain& g) {
    auto* row = new QHBoxLayout;
    auto* mark = new QLabel(box);
    mark->setFixedWidth(16);
    m_marks.insert(g.name, mark);
    const QString tip =
        g.parameter == g.name ? g.description : QStringLiteral("%1 (%2): %3").arg(g.name, g.parameter, g.description);
    if (g.isSwitch) {
        auto* check = new QCheckBox(tr("on"), box);
        check->setObjectName(QStringLiteral("gain_") + g.name);
        check->setToolTip(tip);
        m_switches.insert(g.name, check);
        row->addWidget(check);
        row->addStretch(1);
        connect(check, &QCheckBox::toggled, this, [this, name = g.name](bool on) {
            if (m_showing) return;
            m_marks.value(name)->setText(kSent);
            m_tuner->writeGain(name, on ? 1 : 0);
        });
    } else {
        auto* slider = new QSlider(Qt::Horizontal, box);
        slider->setRange(0, sliderSteps(g));
        auto* spin = new QDoubleSpinBox(box);
        spin->setObjectName(QStringLiteral("gain_") + g.name);
        spin->setDecimals(g.decimals);
        spin->setRange(g.minimum, g.maximum);
        spin->setKeyboardTracking(false); // one change per Enter or arrow, never per keystroke
        spin->setAccelerated(true);
        spin->setMinimumWidth(90);
        if (!g.unit.isEmpty()) spin->setSuffix(QLatin1Char(' ') + g.unit);
        spin->setToolTip(tip);
        slider->setToolTip(tip);
        m_editors.insert(g.name, spin);
        m_sliders.insert(g.name, slider);
        row->addWidget(slider, 1);
        row->addWidget(spin);
        const auto valueAt = [g, slider](int step) {
            return g.minimum + (g.maximum - g.minimum) * step / std::max(slider->maximum(), 1);
        };
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, name = g.name, g, slider](double value) {
            const QSignalBlocker block(slider);
            slider->setValue(int(std::lround((value - g.minimum) / std::max(g.maximum - g.minimum, 1e-12) *
                                             slider->maximum())));
            if (m_showing) return;
            m_marks.value(name)->setText(kSent);
            m_tuner->writeGain(name, value);
        });
        connect(slider, &QSlider::valueChanged, this, [slider, spin, valueAt](int step) {
            if (!slider->isSliderDown()) spin->setValue(valueAt(step)); // keyboard and page steps
        });
        connect(slider, &QSlider::sliderReleased, this,
                [slider, spin, valueAt] { spin->setValue(valueAt(slider->value())); }); // a drag sends on release
    }
    row->addWidget(mark);
    form->addRow(g.name, row);
}

QWidget* TuningPanel::buildTestMove() {
    const auto [box, form] = addControlGroup(this, tr("Test move"));
    m_move = new QComboBox(box);
    for (const TunerMove& m : m_tuner->tunerMoves()) {
        m_move->addItem(m.name);
        m_move->setItemData(m_move->count() - 1, m.tip, Qt::ToolTipRole);
    }
    m_amplitude = new QSpinBox(box);
    m_amplitude->setRange(1, 1'000'000);
    const int first = m_tuner->tunerMoves().value(0).amplitude;
    m_amplitude->setValue(first > 0 ? first : 1000);
    m_hold = new QSpinBox(box);
    m_hold->setRange(10, 10'000);
    m_hold->setValue(m_tuner->defaultHoldMs());
    m_hold->setSuffix(tr(" ms"));
    m_hold->setToolTip(tr("How long the move runs before it goes back, and how long the response is watched after."));
    auto* amplitudeRow = new QHBoxLayout;
    amplitudeRow->addWidget(m_amplitude, 1);
    m_proposal = new QLabel(box);
    m_proposal->setObjectName(QStringLiteral("tuningProposal"));
    m_proposal->setWordWrap(true);
    if (!m_tuner->proposalText().isEmpty()) {
        auto* propose = new QPushButton(tr("Propose"), box);
        propose->setToolTip(tr("Set the amplitude proposed from the drive's values."));
        amplitudeRow->addWidget(propose);
        connect(propose, &QPushButton::clicked, this, &TuningPanel::useProposedAmplitude);
    }
    m_moveText = new QLabel(box);
    m_moveText->setWordWrap(true);
    form->addRow(tr("Preset"), m_move);
    form->addRow(tr("Amplitude"), amplitudeRow);
    form->addRow(m_proposal);
    form->addRow(tr("Hold"), m_hold);
    form->addRow(m_moveText);
    connect(m_move, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (m_showing) return applyMove();
        m_followProposal = true; // a preset chosen by the user gets its proposal, or the family's amplitude
        if (const int amplitude = m_tuner->tunerMoves().value(index).amplitude; amplitude > 0) {
            const QSignalBlocker block(m_amplitude);
            m_amplitude->setValue(amplitude);
        }
        applyMove();
        updateProposal();
    });
    connect(m_amplitude, &QSpinBox::valueChanged, this, [this] {
        if (!m_showing) m_followProposal = false; // the user's own amplitude stays
        applyMove();
    });
    connect(m_hold, &QSpinBox::valueChanged, this, [this] {
        applyMove();
        updateProposal();
    });
    m_run = addRunButtons(box, form, m_tuner);
    m_progress = new QProgressBar(box);
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(8);
    m_progress->hide(); // until a family reports a run's progress
    form->addRow(m_progress);
    m_status = addStatusLine(box, form, QStringLiteral("tuningStatus"));
    m_warning = new QLabel(box);
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("color: #b3261e"));
    m_warning->hide();
    form->addRow(m_warning);
    return box;
}

void TuningPanel::addControls(QWidget* group) {
    m_controls->insertWidget(m_controls->count() - 1, group); // above the stretch
}

void TuningPanel::showGain(const QString& name, double value) {
    m_showing = true;
    if (QDoubleSpinBox* spin = m_editors.value(name)) spin->setValue(value);
    if (QCheckBox* check = m_switches.value(name)) check->setChecked(value != 0);
    m_showing = false;
}

void TuningPanel::markGain(const QString& name, const QString& refusal) {
    QLabel* mark = m_marks.value(name);
    if (!mark) return;
    mark->setText(refusal.isEmpty() ? kConfirmed : kRefused);
    mark->setStyleSheet(refusal.isEmpty() ? QStringLiteral("color: #1e8e3e") : QStringLiteral("color: #b3261e"));
    mark->setToolTip(refusal.isEmpty() ? tr("The drive holds this value.") : refusal);
}

QString TuningPanel::gainMark(const QString& name) const {
    const QLabel* mark = m_marks.value(name);
    if (!mark) return {};
    return mark->text() == kRefused ? mark->text() + QLatin1Char(' ') + mark->toolTip() : mark->text();
}

void TuningPanel::applyMove() {
    m_tuner->setMove(m_move->currentIndex(), m_amplitude->value(), m_hold->value());
    const TunerMove move = m_tuner->tunerMoves().value(m_move->currentIndex());
    m_amplitude->setSuffix(move.unit.isEmpty() ? QString() : QLatin1Char(' ') + move.unit);
    m_amplitude->setToolTip(move.tip);
    m_moveText->setText(m_tuner->moveText());
}

void TuningPanel::setMove(int index, int amplitude, int holdMs) {
    m_followProposal = false;
    m_showing = true;
    m_move->setCurrentIndex(index);
    m_amplitude->setValue(amplitude);
    m_hold->setValue(holdMs);
    m_showing = false;
    applyMove();
}

void TuningPanel::useProposedAmplitude() {
    m_followProposal = true;
    updateProposal();
}

// The proposal line follows every gain; the Amplitude field takes the proposal once and keeps it (a gain change
// re-proposing it made run 1 J 2596, run 2 J 1298, run 3 J 3750: overlays of different moves).
void TuningPanel::updateProposal() {
    const QString text = m_tuner->proposalText();
    m_proposal->setText(text);
    m_proposal->setVisible(!text.isEmpty());
    const auto proposed = m_tuner->proposedAmplitude();
    if (!proposed || !m_followProposal) return;
    m_followProposal = false;
    m_tuner->proposalTaken();
    m_showing = true;
    m_amplitude->setValue(*proposed);
    m_showing = false;
    applyMove();
}

QString TuningPanel::proposalText() const {
    return m_proposal->text();
}

QString TuningPanel::warningText() const {
    return m_warning->isHidden() ? QString() : m_warning->text(); // also while the dock is closed
}

void TuningPanel::addRun(const TunerRow& run) {
    m_view->showCapture(run.capture, true);
    const QString changed = QString::fromStdString(run.capture.title).section(QStringLiteral(": "), 1);
    RunRow row;
    row.cells = QStringList{QString::number(run.number),
                            changed.isEmpty() ? (run.number == 1 ? tr("(first)") : tr("(none)")) : changed,
                            run.metrics.hasStep ? QString::number(run.metrics.overshoot_pct, 'f', 1)
                                                : QStringLiteral("\u2014"),
                            milliseconds(run.metrics.rise_s), milliseconds(run.metrics.settling_s)} +
                run.extraCells;
    row.leftAligned = {1};
    for (int c = 5; c < row.cells.size(); ++c) { // numbers right, words left
        bool number = false;
        row.cells[c].toDouble(&number);
        if (!number && row.cells[c] != QStringLiteral("\u2014")) row.leftAligned << c;
    }
    row.fault = run.fault;
    appendRun(m_runsTable, row);
    m_progress->setValue(m_progress->maximum());
    m_warning->setText(run.warning);
    m_warning->setVisible(!run.warning.isEmpty());
    if (m_bode && m_bode->isVisible() && m_runsTable->currentRow() < 0) showBode(); // follows the newest run
    setStatus(run.status);
}

BodeView* TuningPanel::frequencyResponse() {
    if (!m_bode) m_bode = new BodeView(this);
    showBode();
    m_bode->show();
    m_bode->raise();
    return m_bode;
}

void TuningPanel::showBode() {
    const auto [input, output] = m_tuner->bodeProbes();
    const int selected = selectedRunNumber(m_runsTable);
    const int count = m_runsTable->rowCount();
    const int number = selected > 0 ? selected : count > 0 ? m_runsTable->item(count - 1, 0)->text().toInt() : 0;
    const scope::Capture* capture = m_tuner->runCapture(number);
    if (!capture)
        return m_bode->showNothing(tr("No run yet: Run Once, then the frequency response of its %1 \u2192 %2.")
                                       .arg(input, output));
    if (!m_bode->showCapture(*capture, input, output))
        m_bode->showNothing(tr("Run %1 did not record %2 and %3: choose a preset that does (\"Step for frequency "
                               "response\") and Run Once.")
                                .arg(number)
                                .arg(input, output));
}

void TuningPanel::updateButtons() {
    m_run.update(m_tuner->isRunning(), m_tuner->isContinuous(), m_tuner->canStop());
    m_undo->setEnabled(m_runsTable->currentRow() >= 0);
}

void TuningPanel::setStatus(const QString& text) {
    m_status->setText(text);
}

QString TuningPanel::statusText() const {
    return m_status->text();
}

void TuningPanel::saveGainsAs() {
    const auto file = m_tuner->gainsFile();
    if (!file) return setStatus(tr("This drive has no file for its gains."));
    if (file->text.isEmpty()) return setStatus(tr("Nothing to save yet: Read from Drive first."));
    auto* dialog = new QFileDialog(this, tr("Save Gains"), file->defaultName, file->filter);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(file->defaultName.section(QLatin1Char('.'), -1));
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
        const auto now = m_tuner->gainsFile(); // the gains as they are when the user picks the file
        QFile out(path);
        const bool ok = now && !now->text.isEmpty() && out.open(QIODevice::WriteOnly | QIODevice::Truncate) && out.write(now->text.toLatin1()) >= 0;
        setStatus(ok ? tr("Saved the gains to %1.").arg(path) : tr("Cannot write %1.").arg(path));
    });
    dialog->open();
}

} // namespace app
