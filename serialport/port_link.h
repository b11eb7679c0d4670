// The link a port name stands for, in the IDE and the CLI alike: "tcp://HOST:PORT" and "rfc2217://HOST:PORT"
// reach a serial device server (NetworkLink); anything else is a serial port or a pty (SerialPortLink), with
// RTS/CTS for the PMC-960, whose one-character receive buffer overruns without it (seed-pmc960 §4.1). Over
// a device server the server's own port settings carry the flow control.
#pragma once

#include "link.h"

#include "drive_core/drive.h"

#include <memory>

namespace serialport {

std::unique_ptr<Link> makePortLink(const QString& port, int baudRate, drive_core::DriveFamily family);

} // namespace serialport
