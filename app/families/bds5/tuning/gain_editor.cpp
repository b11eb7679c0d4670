// GainEditor: spin box + slider, or a check box.
#include "gain_editor.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>

namespace app {

namespace {
// Sliders over huge ranges (KP to 32767) are coarse; keep them to what tuning uses, the spin box goes on.
constexpr int kSliderCeiling = 32767;
} // namespace

GainEditor::GainEditor(const GainInfo& info, QWidget* parent)
    : QWidget(parent), m_info(info), m_mark(new QLabel(this)) {
    setObjectName(QStringLiteral("gain_") + info.name);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    setToolTip(info.description);
    if (info.isSwitch) {
        m_check = new QCheckBox(tr("on"), this);
        layout->addWidget(m_check);
        layout->addStretch(1);
        connect(m_check, &QCheckBox::toggled, this, [this](bool on) { emit edited(m_info.name, on ? 1 : 0); });
    } else {
        m_slider = new QSlider(Qt::Horizontal, this);
        m_slider->setRange(info.minimum, std::min(info.maximum, kSliderCeiling));
        m_spin = new QSpinBox(this);
        m_spin->setRange(info.minimum, info.maximum);
        m_spin->setKeyboardTracking(false);
        m_spin->setAccelerated(true);
        if (!info.unit.isEmpty()) m_spin->setSuffix(QLatin1Char(' ') + info.unit);
        m_spin->setMinimumWidth(90);
        layout->addWidget(m_slider, 1);
        layout->addWidget(m_spin);
        connect(m_spin, &QSpinBox::valueChanged, this, [this](int v) {
            const QSignalBlocker block(m_slider);
            m_slider->setValue(v);
            emit edited(m_info.name, v);
        });
        connect(m_slider, &QSlider::valueChanged, this, [this](int v) {
            if (m_slider->isSliderDown()) return;
            m_spin->setValue(v); // keyboard and page steps; a drag sends on release
        });
        connect(m_slider, &QSlider::sliderReleased, this, [this] { m_spin->setValue(m_slider->value()); });
    }
    m_mark->setFixedWidth(16);
    layout->addWidget(m_mark);
    setValue(info.powerUp);
}

int GainEditor::value() const {
    return m_check ? int(m_check->isChecked()) : m_spin->value();
}

void GainEditor::setValue(int value) {
    if (m_check) {
        const QSignalBlocker block(m_check);
        m_check->setChecked(value != 0);
        return;
    }
    const QSignalBlocker blockSpin(m_spin);
    const QSignalBlocker blockSlider(m_slider);
    m_spin->setValue(value);
    m_slider->setValue(value);
}

void GainEditor::setConfirmed(bool confirmed, const QString& why) {
    m_mark->setText(confirmed ? QStringLiteral("\u2713") : QStringLiteral("\u26a0"));
    m_mark->setStyleSheet(confirmed ? QStringLiteral("color: #1e8e3e") : QStringLiteral("color: #b3261e"));
    m_mark->setToolTip(confirmed ? tr("The drive accepted %1 = %2").arg(m_info.name).arg(value()) : why);
}

} // namespace app
