// A Link over QSerialPort: real drives on /dev/ttyUSB0 and friends, and pseudo-terminals.
#pragma once

#include "link.h"

#include <QSerialPort>

#include <algorithm>

namespace serialport {

class SerialPortLink final : public Link {
    Q_OBJECT
public:
    // None: the BDS5 and SC750 (three-wire RS-232, BDS5 §2.1). Hardware: RTS/CTS, for the PMC-960, whose
    // one-byte receive buffer overruns unless the host waits while CTS is off (seed-pmc960 §4.1).
    enum class FlowControl { None, Hardware };

    // portName: "ttyUSB0", "/dev/ttyUSB0" or a pty path "/dev/pts/5". 8N1.
    SerialPortLink(QString portName, int baudRate, FlowControl flow = FlowControl::None, QObject* parent = nullptr);
    ~SerialPortLink() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray& bytes) override;
    QString description() const override;
    int baudRate() const override { return m_baudRate; }
    FlowControl flowControl() const { return m_flow; }
    // Three characters' time at the baud rate, and never under the 16 ms a USB adapter may hold bytes.
    int quietMs() const override { return std::max(20, 30 * 1000 / std::max(m_baudRate, 1)); }

private:
    void onError(QSerialPort::SerialPortError error);

    QSerialPort m_port;
    QString m_portName;
    int m_baudRate;
    FlowControl m_flow;
};

} // namespace serialport
