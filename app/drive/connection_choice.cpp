// ConnectionChoice: settings persistence and link creation.
#include "connection_choice.h"

#include "drive_core/drive_factory.h"

#include "serialport/axis_link.h"
#include "serialport/port_link.h"
#include "serialport/simulator_link.h"

#include <QCoreApplication>
#include <QSettings>

namespace app {

ConnectionChoice ConnectionChoice::load(QSettings& settings) {
    ConnectionChoice choice;
    settings.beginGroup(QStringLiteral("connection"));
    if (settings.value(QStringLiteral("kind")).toString() == QLatin1String("serial"))
        choice.kind = Kind::SerialPort;
    choice.portName = settings.value(QStringLiteral("port")).toString();
    const int baud = settings.value(QStringLiteral("baud"), choice.baudRate).toInt();
    if (baudRates().contains(baud)) choice.baudRate = baud;
    choice.family = familyFromKey(settings.value(QStringLiteral("family")).toString()).value_or(choice.family);
    settings.endGroup();
    if (choice.kind == Kind::SerialPort && choice.portName.isEmpty()) choice.kind = Kind::Simulator;
    return choice;
}

void ConnectionChoice::save(QSettings& settings) const {
    settings.beginGroup(QStringLiteral("connection"));
    settings.setValue(QStringLiteral("kind"),
                      kind == Kind::SerialPort ? QStringLiteral("serial") : QStringLiteral("simulator"));
    // Keep the last port even while the simulator is chosen, so the dialog can offer it again.
    if (!portName.isEmpty()) settings.setValue(QStringLiteral("port"), portName);
    settings.setValue(QStringLiteral("baud"), baudRate);
    settings.setValue(QStringLiteral("family"), familyKey(family));
    settings.endGroup();
}

std::unique_ptr<serialport::Link> ConnectionChoice::makeLink() const {
    if (line && !axis.isEmpty()) return std::make_unique<serialport::AxisLink>(line, family, axis);
    if (kind == Kind::SerialPort) return serialport::makePortLink(portName, baudRate, family);
    return std::make_unique<serialport::SimulatorLink>(
        family, serialport::SimulatorLink::Options{.baudRate = baudRate});
}

QString ConnectionChoice::portText() const {
    if (line && !axis.isEmpty())
        return QCoreApplication::translate("app::ConnectionChoice", "axis %1 on %2").arg(axis, line->description());
    if (kind == Kind::SerialPort)
        return QCoreApplication::translate("app::ConnectionChoice", "%1, %2 baud")
            .arg(portName)
            .arg(baudRate);
    return QCoreApplication::translate("app::ConnectionChoice", "Simulated %1, %2 baud")
        .arg(familyName(family))
        .arg(baudRate);
}

QString ConnectionChoice::familyName(drive_core::DriveFamily family) {
    return QString::fromLatin1(drive_core::familyTitle(family));
}

QString ConnectionChoice::familyKey(drive_core::DriveFamily family) {
    return QString::fromLatin1(drive_core::familyName(family));
}

std::optional<drive_core::DriveFamily> ConnectionChoice::familyFromKey(const QString& key) {
    return drive_core::familyFromName(key.toStdString());
}

} // namespace app
