// A Link over QSerialPort: real drives on /dev/ttyUSB0 and friends, and pseudo-terminals.
#pragma once

#include "link.h"

#include <QSerialPort>

namespace serialport {

class SerialPortLink final : public Link {
    Q_OBJECT
public:
    // portName: "ttyUSB0", "/dev/ttyUSB0" or a pty path "/dev/pts/5". 8N1, no flow control (BDS5 §2.1).
    SerialPortLink(QString portName, int baudRate, QObject* parent = nullptr);
    ~SerialPortLink() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray& bytes) override;
    QString description() const override;
    int baudRate() const override { return m_baudRate; }

private:
    void onError(QSerialPort::SerialPortError error);

    QSerialPort m_port;
    QString m_portName;
    int m_baudRate;
};

} // namespace serialport
