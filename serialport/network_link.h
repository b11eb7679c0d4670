// A Link to a serial device server on Ethernet (issue 21): tcp://HOST:PORT, the server's raw socket (the
// line's settings are the server's own), or rfc2217://HOST:PORT, Telnet Com Port Control, which sets the
// line to the baud rate asked for, 8N1, before the link counts as open. QTcpSocket; GUI thread only.
#pragma once

#include "link.h"
#include "rfc2217.h"

#include <QTcpSocket>
#include <QTimer>

#include <optional>

namespace serialport {

class NetworkLink final : public Link {
    Q_OBJECT
public:
    enum class Protocol { Raw, Rfc2217 };
    struct Address {
        Protocol protocol = Protocol::Raw;
        QString host;
        quint16 port = 0;
    };
    // "tcp://HOST:PORT" or "rfc2217://HOST:PORT"; nullopt for anything else (a serial port's name).
    static std::optional<Address> parse(const QString& url);
    // The reason a tcp:// or rfc2217:// text is not a usable address ("" when it is, or is no URL at all).
    static QString problem(const QString& url);

    static constexpr int kNegotiationMs = 5000; // the server's answers to the RFC 2217 set-up

    NetworkLink(Address address, int baudRate, QObject* parent = nullptr);
    ~NetworkLink() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray& bytes) override;
    QString description() const override;
    int baudRate() const override { return m_baudRate; }
    // A network hop can hold bytes longer than a USB adapter: a few characters' time, at least 40 ms.
    int quietMs() const override { return std::max(40, 30 * 1000 / std::max(m_baudRate, 1)); }

private:
    void onConnected();
    void onReadyRead();
    void fail(const QString& why);
    void negotiated(const rfc2217::Decoder::Command& command);

    QTcpSocket m_socket;
    QTimer m_negotiation;
    Address m_address;
    int m_baudRate;
    rfc2217::Decoder m_decoder;
    bool m_open = false;             // opened() was emitted
    bool m_closing = false;          // inside our own abort()
    bool m_comPortAccepted = false;  // the server said DO COM-PORT-OPTION
    bool m_baudAnswered = false;     // ... and answered SET-BAUDRATE
};

} // namespace serialport
