// Sc750StatusDisplay: status polling and the catalog's FAULTCODE display characters and meanings.
#include "sc750_status_display.h"

#include "sc750_debugger.h"
#include "sc750_seven_segment.h"
#include "sc750_workspace.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "serialport/sc750_session.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>

namespace app {

namespace cat = drive_core::catalog::sc750;

namespace {
QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}
} // namespace

Sc750StatusDisplay::Sc750StatusDisplay(Sc750Workspace& workspace, QWidget* parent)
    : QWidget(parent), m_workspace(workspace), m_digit(new Sc750SevenSegment(this)), m_meaning(new QLabel(this)) {
    setObjectName(QStringLiteral("sc750StatusDisplay"));
    m_digit->setObjectName(QStringLiteral("sc750StatusDigit"));
    m_meaning->setObjectName(QStringLiteral("sc750StatusMeaning"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 1, 4, 1);
    layout->setSpacing(6);
    layout->addWidget(m_digit);
    layout->addWidget(m_meaning);
    m_digit->setFixedWidth(26); // the digit then fills the status bar's height
    showDisconnected();

    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, &Sc750StatusDisplay::tick);
    m_poll.start();
    // A program started, stopped, ended or failed: the display follows without waiting for the next poll.
    connect(&workspace.debugger(), &Sc750Debugger::stateChanged, this, &Sc750StatusDisplay::request);
    connect(&workspace, &FamilyWorkspace::statusChanged, this, [this] {
        if (m_workspace.session()) return;
        m_asking = false; // the workspace dropped its waiting handlers with the session
        showDisconnected();
    });
}

QString Sc750StatusDisplay::meaning() const {
    return m_meaning->text();
}

void Sc750StatusDisplay::setModel(const QString& model) {
    m_model = model;
    if (!m_lastPayload.isEmpty()) show(m_lastPayload);
}

void Sc750StatusDisplay::tick() {
    serialport::Sc750Session* session = m_workspace.session();
    if (!session || !isVisible()) return;
    // Between other commands (a download's, the variable browser's, Watch Variables') only once a second.
    if (session->busy() && m_sinceAnswer.isValid() && m_sinceAnswer.elapsed() < kQuietMs) return;
    request();
}

void Sc750StatusDisplay::request() {
    if (!m_workspace.session() || m_workspace.debugger().state() == Sc750Debugger::State::Downloading) return;
    if (m_asking && m_sinceRequest.elapsed() < kLostMs) return;
    m_asking = true;
    m_sinceRequest.start();
    QPointer<Sc750StatusDisplay> self(this);
    m_workspace.send(
        '?', {},
        [self](const serialport::Sc750Reply& reply) {
            if (!self) return;
            self->m_asking = false;
            self->m_sinceAnswer.start();
            self->show(reply.payload);
        },
        [self](const QString&) {
            if (self) self->m_asking = false; // the display keeps what it showed; the next tick asks again
        });
}

void Sc750StatusDisplay::show(const QString& payload) {
    // "<state>,<line>,<faultcode>,<dp>,<configured>" (PROTOCOL.md §4)
    const QStringList parts = payload.split(QLatin1Char(','));
    bool ok = false;
    const int code = parts.value(2).toInt(&ok);
    if (parts.size() < 5 || !ok) return;
    m_lastPayload = payload;
    const bool configured = parts.value(4) != QLatin1String("0");
    m_digit->setDecimalPoint(parts.value(3) == QLatin1String("1"));
    QString meaning;
    QString tip = tr("The SC750's front-panel display, read with the status request every %1 ms.\n").arg(kPollMs);
    if (!configured && (code == cat::kFaultNone || code == cat::kFaultEnabled)) {
        // A fault outranks "U C": it is what stopped the controller (DECISIONS 45).
        m_digit->setCharacters(text(cat::kUnconfiguredDisplay));
        meaning = tr("Unconfigured controller");
        tip += tr("\"%1\": run Controller Set Up (L1555).").arg(text(cat::kUnconfiguredDisplay));
    } else if (const cat::FaultInfo* info = cat::findFault(code)) {
        m_digit->setCharacters(text(info->display));
        const bool sc754Up = m_model.toInt() >= 754; // SC754/755/756 name a few codes differently
        meaning = text(sc754Up || info->sc752.empty() ? info->sc754 : info->sc752);
        tip += tr("FAULTCODE %1, display \"%2\" (%3).").arg(code).arg(text(info->display), text(info->manualLines));
    } else {
        m_digit->setCharacters(QStringLiteral("-")); // not in the manual's table
        meaning = tr("FAULTCODE %1").arg(code);
        tip += tr("FAULTCODE %1 is not in the manual's table (L1522-L1588).").arg(code);
    }
    if (m_digit->decimalPoint()) tip += QLatin1Char('\n') + tr("Decimal point: a program is running (L2676).");
    m_meaning->setText(meaning);
    setToolTip(tip);
}

void Sc750StatusDisplay::showDisconnected() {
    m_lastPayload.clear();
    m_digit->setCharacters({});
    m_digit->setDecimalPoint(false);
    m_meaning->setText(tr("Not connected"));
    setToolTip(tr("The SC750's front-panel display: dark until a controller is connected."));
}

} // namespace app
