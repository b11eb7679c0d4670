// Pmc960StatusDock: values from the polls, lights from the input and output words, a command line.
#include "pmc960_status_dock.h"

#include "serialport/pmc960_session.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

namespace app {

// One round light: green when on, grey when off.
class Pmc960Light final : public QWidget {
public:
    explicit Pmc960Light(QWidget* parent) : QWidget(parent) { setFixedSize(kSize, kSize); }
    void setOn(bool on) {
        if (on == m_on) return;
        m_on = on;
        update();
    }
    bool isOn() const { return m_on; }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QPen(QColor(0x5f, 0x63, 0x68), 1));
        QRadialGradient glow(QPointF(kSize * 0.4, kSize * 0.35), kSize * 0.6);
        glow.setColorAt(0, m_on ? QColor(0xa8, 0xf0, 0xb0) : QColor(0xe8, 0xea, 0xed));
        glow.setColorAt(1, m_on ? QColor(0x1e, 0x8e, 0x3e) : QColor(0xa0, 0xa4, 0xa8));
        p.setBrush(glow);
        p.drawEllipse(QRectF(1.5, 1.5, kSize - 3, kSize - 3));
    }

private:
    static constexpr int kSize = 22;
    bool m_on = false;
};

namespace {
// Asks for the whole panel (so the window gives it its height when it can) but may be squeezed: then it
// scrolls.
class PanelScroll final : public QScrollArea {
public:
    using QScrollArea::QScrollArea;
    QSize sizeHint() const override {
        return widget() ? widget()->sizeHint() + QSize(verticalScrollBar()->sizeHint().width(), 0)
                        : QScrollArea::sizeHint();
    }
};

const char* const kPollLetters = "gfvisb";

QLabel* valueLabel(QWidget* parent) {
    auto* label = new QLabel(QStringLiteral("\u2014"), parent);
    QFont font(QStringLiteral("monospace"));
    font.setStyleHint(QFont::Monospace);
    font.setPointSizeF(font.pointSizeF() * 1.25);
    font.setBold(true);
    label->setFont(font);
    label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    label->setMinimumWidth(120);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

QGroupBox* lightRow(const QString& title, const QString& pattern, std::array<Pmc960Light*, 8>& lights,
                    QWidget* parent) {
    auto* box = new QGroupBox(title, parent);
    auto* grid = new QGridLayout(box);
    grid->setHorizontalSpacing(6);
    for (int i = 0; i < 8; ++i) {
        const int bit = 7 - i; // IN07' on the left, as the manual lists them
        lights[bit] = new Pmc960Light(box);
        auto* name = new QLabel(pattern.arg(bit, 2, 10, QLatin1Char('0')), box);
        name->setAlignment(Qt::AlignHCenter);
        QFont small = name->font();
        small.setPointSizeF(small.pointSizeF() * 0.85);
        name->setFont(small);
        grid->addWidget(lights[bit], 0, i, Qt::AlignHCenter);
        grid->addWidget(name, 1, i, Qt::AlignHCenter);
    }
    return box;
}

QString modeName(const QString& value) {
    switch (value.toInt()) {
    case 0: return QObject::tr("SM0 disabled");
    case 1: return QObject::tr("SM1 velocity");
    case 2: return QObject::tr("SM2 position");
    case 3: return QObject::tr("SM3 position, ext.");
    default: return value;
    }
}
} // namespace

Pmc960StatusDock::Pmc960StatusDock(QWidget* parent) : QDockWidget(tr("PMC-960 Status"), parent) {
    setObjectName(QStringLiteral("pmc960StatusDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    auto* values = new QGroupBox(tr("Motion"), body);
    auto* form = new QFormLayout(values);
    m_mode = valueLabel(values);
    m_position = valueLabel(values);
    m_following = valueLabel(values);
    m_velocity = valueLabel(values);
    m_toGo = valueLabel(values);
    m_label = valueLabel(values);
    form->addRow(tr("Servo mode"), m_mode);
    form->addRow(tr("Position (G!)"), m_position);
    form->addRow(tr("Following error (SF!)"), m_following);
    form->addRow(tr("Velocity (V!)"), m_velocity);
    form->addRow(tr("Distance to go (I!)"), m_toGo);
    form->addRow(tr("Last label (SB)"), m_label);
    layout->addWidget(values);
    layout->addWidget(lightRow(tr("Inputs (SI!)"), QStringLiteral("IN%1'"), m_inputs, body));
    layout->addWidget(lightRow(tr("Outputs (OB!)"), QStringLiteral("OUT%1"), m_outputs, body));

    m_command = new QLineEdit(body);
    m_command->setObjectName(QStringLiteral("pmc960Command"));
    m_command->setPlaceholderText(tr("MPL command, e.g. SM2 or I4000+"));
    m_reply = new QLabel(body);
    m_reply->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_reply->setWordWrap(true);
    layout->addWidget(m_command);
    layout->addWidget(m_reply);
    layout->addStretch(1);
    // Scrolled rather than squeezed: on a 768-pixel screen the panel shares its column with the Outline, and
    // its whole height would push the window past the screen.
    auto* scroll = new PanelScroll(this);
    scroll->setWidget(body);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(body->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
    setWidget(scroll);
    connect(m_command, &QLineEdit::returnPressed, this, [this] {
        sendCommand(m_command->text());
        m_command->clear();
    });

    m_idleRead.setInterval(kIdleReadMs);
    connect(&m_idleRead, &QTimer::timeout, this, &Pmc960StatusDock::readIdle);
    clear();
}

void Pmc960StatusDock::setSession(serialport::Pmc960Session* session) {
    if (m_session == session) return;
    if (m_session) {
        m_session->setStatusPolling(0, {});
        m_session->disconnect(this);
    }
    m_session = session;
    m_modeRead = m_outputsRead = m_commandSent = 0;
    clear();
    if (m_session) {
        connect(m_session, &serialport::Pmc960Session::statusPolled, this, &Pmc960StatusDock::onPolled);
        connect(m_session, &serialport::Pmc960Session::finished, this, &Pmc960StatusDock::onFinished);
        connect(m_session, &serialport::Pmc960Session::destroyed, this, [this] { m_session = nullptr; });
    }
    m_command->setEnabled(m_session != nullptr);
    updatePolling();
}

void Pmc960StatusDock::setPaused(bool paused) {
    m_paused = paused;
    updatePolling();
}

void Pmc960StatusDock::updatePolling() {
    const bool on = m_session && !m_paused;
    if (m_session) m_session->setStatusPolling(on ? kPollMs : 0, on ? QByteArray(kPollLetters) : QByteArray());
    if (on) m_idleRead.start();
    else m_idleRead.stop();
}

void Pmc960StatusDock::clear() {
    for (QLabel* label : {m_mode, m_position, m_following, m_velocity, m_toGo, m_label})
        label->setText(QStringLiteral("\u2014"));
    for (auto* light : m_inputs) light->setOn(false);
    for (auto* light : m_outputs) light->setOn(false);
    m_inputs[0]->setProperty("value", QString());
    m_outputs[0]->setProperty("value", QString());
}

void Pmc960StatusDock::setLights(std::array<Pmc960Light*, kLights>& lights, int bits, const QString& key) {
    for (int bit = 0; bit < kLights; ++bit) lights[bit]->setOn((bits >> bit) & 1);
    lights[0]->setProperty("value", key);
}

void Pmc960StatusDock::onPolled(char letter, const QString& value) {
    switch (letter) {
    case 'g': m_position->setText(value); break;
    case 'f': m_following->setText(value); break;
    case 'v': m_velocity->setText(value); break;
    case 'i': m_toGo->setText(value); break;
    case 'b': m_label->setText(value); break;
    case 's': setLights(m_inputs, value.toInt(nullptr, 16), value); break;
    default: break;
    }
}

void Pmc960StatusDock::readIdle() {
    if (!m_session || m_paused || m_session->state() != serialport::Pmc960Session::State::Ready) return;
    if (m_modeRead || m_outputsRead) return; // the last reads are still out
    m_modeRead = m_session->send("SM!");
    m_outputsRead = m_session->send("OB!");
}

void Pmc960StatusDock::onFinished(quint64 id, const serialport::Pmc960Response& response) {
    if (id == m_modeRead) {
        m_modeRead = 0;
        if (response.error == 0) m_mode->setText(modeName(response.value));
    } else if (id == m_outputsRead) {
        m_outputsRead = 0;
        if (response.error == 0) setLights(m_outputs, response.value.toInt(nullptr, 16), response.value);
    } else if (id == m_commandSent) {
        m_commandSent = 0;
        QString text = QString::fromLatin1(response.command).trimmed();
        if (!response.value.isEmpty()) text += QStringLiteral(" \u2192 ") + response.value;
        if (response.error != 0)
            text += QStringLiteral("  #%1 %2").arg(response.error, 2, 16).toUpper().arg(response.errorText);
        m_reply->setText(text);
    }
}

void Pmc960StatusDock::sendCommand(const QString& command) {
    const QString trimmed = command.trimmed();
    if (!m_session || trimmed.isEmpty()) return;
    QByteArray bytes = trimmed.toLatin1();
    static const QByteArray kSelfEnding("?!&,;");
    if (!kSelfEnding.contains(bytes.back())) bytes += '\r';
    m_reply->setText(tr("%1 \u2026").arg(trimmed));
    m_commandSent = m_session->send(bytes);
}

QString Pmc960StatusDock::lastReply() const {
    return m_reply->text();
}

QString Pmc960StatusDock::value(const QString& key) const {
    if (key == QLatin1String("position")) return m_position->text();
    if (key == QLatin1String("following")) return m_following->text();
    if (key == QLatin1String("velocity")) return m_velocity->text();
    if (key == QLatin1String("mode")) return m_mode->text();
    if (key == QLatin1String("togo")) return m_toGo->text();
    if (key == QLatin1String("label")) return m_label->text();
    if (key == QLatin1String("inputs")) return m_inputs[0]->property("value").toString();
    if (key == QLatin1String("outputs")) return m_outputs[0]->property("value").toString();
    return {};
}

} // namespace app
