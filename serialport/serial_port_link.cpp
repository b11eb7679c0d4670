// QSerialPort-backed link.
#include "serial_port_link.h"

namespace serialport {

SerialPortLink::SerialPortLink(QString portName, int baudRate, FlowControl flow, QObject* parent)
    : Link(parent), m_portName(std::move(portName)), m_baudRate(baudRate), m_flow(flow) {
    connect(&m_port, &QSerialPort::readyRead, this, [this] { emit bytesReceived(m_port.readAll()); });
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialPortLink::onError);
}

SerialPortLink::~SerialPortLink() { m_port.close(); }

void SerialPortLink::open() {
    if (m_port.isOpen()) return;
    m_port.setPortName(m_portName);
    m_port.setBaudRate(m_baudRate);
    m_port.setDataBits(QSerialPort::Data8);
    m_port.setParity(QSerialPort::NoParity);
    m_port.setStopBits(QSerialPort::OneStop);
    m_port.setFlowControl(m_flow == FlowControl::Hardware ? QSerialPort::HardwareControl : QSerialPort::NoFlowControl);
    if (!m_port.open(QIODevice::ReadWrite)) {
        // onError has already reported the reason through errorOccurred.
        return;
    }
    emit opened();
}

void SerialPortLink::close() {
    if (!m_port.isOpen()) return;
    m_port.close();
    emit closed();
}

bool SerialPortLink::isOpen() const { return m_port.isOpen(); }

void SerialPortLink::write(const QByteArray& bytes) {
    if (!m_port.isOpen()) {
        emit errorOccurred(tr("%1 is not open: nothing was sent").arg(m_portName));
        return;
    }
    m_port.write(bytes);
}

QString SerialPortLink::description() const {
    return QStringLiteral("%1 %2 8N1%3")
        .arg(m_portName)
        .arg(m_baudRate)
        .arg(m_flow == FlowControl::Hardware ? QStringLiteral(" RTS/CTS") : QString());
}

void SerialPortLink::onError(QSerialPort::SerialPortError error) {
    if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError) return;
    const QString reason = m_port.errorString();
    emit errorOccurred(tr("%1: %2").arg(m_portName, reason));
    // The device went away (a USB adapter unplugged, the pty's far end gone): reads report a resource
    // error, writes a write error (EIO). Either way nothing more will pass: close, so the owner can
    // reconnect.
    const bool gone = error == QSerialPort::ResourceError || error == QSerialPort::WriteError ||
                      error == QSerialPort::ReadError;
    if (gone && m_port.isOpen()) {
        m_port.close();
        emit closed();
    }
}

} // namespace serialport
