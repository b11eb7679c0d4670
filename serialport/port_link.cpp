// makePortLink: a port name to its link.
#include "port_link.h"

#include "network_link.h"
#include "serial_port_link.h"

namespace serialport {

std::unique_ptr<Link> makePortLink(const QString& port, int baudRate, drive_core::DriveFamily family) {
    if (const auto address = NetworkLink::parse(port)) return std::make_unique<NetworkLink>(*address, baudRate);
    const auto flow = family == drive_core::DriveFamily::Pmc960 ? SerialPortLink::FlowControl::Hardware
                                                                : SerialPortLink::FlowControl::None;
    return std::make_unique<SerialPortLink>(port, baudRate, flow);
}

} // namespace serialport
