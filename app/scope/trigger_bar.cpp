// TriggerBar: two rows of controls under the watch chart, and the settings they make.
#include "trigger_bar.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

namespace app {

namespace {
// A polled watch samples a few to a few tens of times a second: Auto forces a frame after this much sample
// time without a trigger, so a signal that never crosses still shows.
constexpr double kAutoTimeout_s = 2;
} // namespace

TriggerBar::TriggerBar(QWidget* parent)
    : QWidget(parent), m_mode(new QComboBox(this)), m_source(new QComboBox(this)), m_kind(new QComboBox(this)),
      m_slope(new QComboBox(this)), m_levelLabel(new QLabel(tr("&Level:"), this)), m_level(new QDoubleSpinBox(this)),
      m_pre(new QDoubleSpinBox(this)), m_frame(new QSpinBox(this)), m_arm(new QPushButton(tr("&Arm"), this)),
      m_state(new QLabel(this)) {
    setObjectName(QStringLiteral("triggerBar"));
    m_mode->addItem(tr("Off (rolling)"));
    m_mode->addItem(tr("Single"), int(scope::TriggerMode::Single));
    m_mode->addItem(tr("Normal"), int(scope::TriggerMode::Normal));
    m_mode->addItem(tr("Auto"), int(scope::TriggerMode::Auto));
    m_mode->setToolTip(tr("Single: one frame, then stop. Normal: a frame at every trigger. Auto: as Normal, "
                          "and a frame every %1 s without one.").arg(kAutoTimeout_s));
    m_kind->addItem(tr("Level"), int(scope::TriggerKind::Level));
    m_kind->addItem(tr("Edge"), int(scope::TriggerKind::Edge));
    m_kind->setToolTip(tr("Level: the value passes through the level. Edge: it steps by at least the given "
                          "amount between two samples, whatever its level."));
    m_slope->addItem(tr("Rising"), int(scope::TriggerSlope::Rising));
    m_slope->addItem(tr("Falling"), int(scope::TriggerSlope::Falling));
    m_slope->addItem(tr("Either"), int(scope::TriggerSlope::Either));
    m_level->setRange(-1e12, 1e12);
    m_level->setDecimals(3);
    m_level->setMinimumWidth(110);
    m_levelLabel->setBuddy(m_level);
    m_pre->setRange(0, 100);
    m_pre->setDecimals(0);
    m_pre->setValue(25);
    m_pre->setSuffix(QStringLiteral(" %"));
    m_pre->setToolTip(tr("How much of the frame comes before the trigger."));
    m_frame->setRange(4, 20000);
    m_frame->setValue(60);
    m_frame->setSuffix(tr(" samples"));
    m_frame->setToolTip(tr("Samples in a triggered frame: its length in time is this over the sample rate."));
    m_state->setWordWrap(true);
    m_state->setObjectName(QStringLiteral("triggerState"));

    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    auto addPair = [this, grid](int row, int column, const QString& text, QWidget* field) {
        auto* label = new QLabel(text, this);
        label->setBuddy(field);
        grid->addWidget(label, row, column);
        grid->addWidget(field, row, column + 1);
    };
    addPair(0, 0, tr("T&rigger:"), m_mode);
    addPair(0, 2, tr("So&urce:"), m_source);
    grid->addWidget(m_kind, 0, 4);
    grid->addWidget(m_slope, 0, 5);
    grid->addWidget(m_levelLabel, 0, 6);
    grid->addWidget(m_level, 0, 7);
    addPair(1, 0, tr("&Pre-trigger:"), m_pre);
    addPair(1, 2, tr("&Frame:"), m_frame);
    grid->addWidget(m_arm, 1, 4);
    grid->addWidget(m_state, 2, 0, 1, 9); // a line of its own: it names the condition, level and all
    grid->setColumnStretch(8, 1);

    for (QComboBox* c : {m_mode, m_source, m_kind, m_slope})
        connect(c, &QComboBox::currentIndexChanged, this, &TriggerBar::settingsChanged);
    for (QDoubleSpinBox* s : {m_level, m_pre}) connect(s, &QDoubleSpinBox::valueChanged, this, &TriggerBar::settingsChanged);
    connect(m_frame, &QSpinBox::valueChanged, this, &TriggerBar::settingsChanged);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &TriggerBar::updateFields);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &TriggerBar::updateFields);
    connect(m_arm, &QPushButton::clicked, this, &TriggerBar::armClicked);
    updateFields();
}

std::optional<scope::TriggerSettings> TriggerBar::settings() const {
    if (!m_mode->currentData().isValid()) return std::nullopt;
    scope::TriggerSettings s;
    s.mode = scope::TriggerMode(m_mode->currentData().toInt());
    s.channel = std::size_t(std::max(0, m_source->currentIndex()));
    s.kind = scope::TriggerKind(m_kind->currentData().toInt());
    s.slope = scope::TriggerSlope(m_slope->currentData().toInt());
    s.level = m_level->value();
    s.minStep = m_level->value();
    s.preTrigger_pct = m_pre->value();
    s.frameLength = std::size_t(m_frame->value());
    s.autoTimeout_s = kAutoTimeout_s;
    return s;
}

void TriggerBar::setSources(const QStringList& labels) {
    const QString was = m_source->currentText();
    const QSignalBlocker block(m_source);
    m_source->clear();
    m_source->addItems(labels);
    m_source->setCurrentIndex(std::max(0, int(labels.indexOf(was))));
}

void TriggerBar::setState(const QString& text) {
    m_state->setText(text);
}

QString TriggerBar::stateText() const {
    return m_state->text();
}

void TriggerBar::setMode(std::optional<scope::TriggerMode> mode) {
    m_mode->setCurrentIndex(mode ? m_mode->findData(int(*mode)) : 0);
}

void TriggerBar::setSource(int channel) {
    m_source->setCurrentIndex(channel);
}

void TriggerBar::setKind(scope::TriggerKind kind) {
    m_kind->setCurrentIndex(m_kind->findData(int(kind)));
}

void TriggerBar::setSlope(scope::TriggerSlope slope) {
    m_slope->setCurrentIndex(m_slope->findData(int(slope)));
}

void TriggerBar::setLevel(double level) {
    m_level->setValue(level);
}

void TriggerBar::setPreTrigger(double pct) {
    m_pre->setValue(pct);
}

void TriggerBar::setFrameSamples(int samples) {
    m_frame->setValue(samples);
}

// With the trigger off only the mode shows as set; an edge takes a least step rather than a level.
void TriggerBar::updateFields() {
    const bool on = m_mode->currentData().isValid();
    for (QWidget* w : std::initializer_list<QWidget*>{m_source, m_kind, m_slope, m_level, m_pre, m_frame, m_arm})
        w->setEnabled(on);
    const bool edge = scope::TriggerKind(m_kind->currentData().toInt()) == scope::TriggerKind::Edge;
    m_levelLabel->setText(edge ? tr("St&ep \u2265") : tr("&Level:"));
    if (edge && m_level->value() <= 0) m_level->setValue(1);
    if (!on) m_state->setText(tr("Rolling: no trigger"));
}

} // namespace app
