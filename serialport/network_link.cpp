// NetworkLink: a serial device server over TCP, raw or RFC 2217.
#include "network_link.h"

#include <QRegularExpression>

namespace serialport {

namespace {
const QRegularExpression kUrl(QStringLiteral("^(tcp|rfc2217)://([^:/]+|\\[[^\\]]+\\]):(\\d{1,5})$"),
                              QRegularExpression::CaseInsensitiveOption);

QByteArray bytes(const std::string& s) {
    return QByteArray(s.data(), qsizetype(s.size()));
}
} // namespace

std::optional<NetworkLink::Address> NetworkLink::parse(const QString& url) {
    const QRegularExpressionMatch m = kUrl.match(url.trimmed());
    if (!m.hasMatch()) return std::nullopt;
    const int port = m.captured(3).toInt();
    if (port < 1 || port > 65535) return std::nullopt;
    QString host = m.captured(2);
    if (host.startsWith(QLatin1Char('['))) host = host.mid(1, host.size() - 2);
    const Protocol protocol =
        m.captured(1).compare(QLatin1String("tcp"), Qt::CaseInsensitive) == 0 ? Protocol::Raw : Protocol::Rfc2217;
    return Address{protocol, host, quint16(port)};
}

QString NetworkLink::problem(const QString& url) {
    const QString text = url.trimmed();
    const bool looksLikeOne = text.startsWith(QLatin1String("tcp://"), Qt::CaseInsensitive) ||
                              text.startsWith(QLatin1String("rfc2217://"), Qt::CaseInsensitive);
    if (!looksLikeOne || parse(text)) return {};
    return tr("%1 is not a serial device server's address: write tcp://HOST:PORT or rfc2217://HOST:PORT "
              "(port 1-65535)")
        .arg(text);
}

NetworkLink::NetworkLink(Address address, int baudRate, QObject* parent)
    : Link(parent), m_address(std::move(address)), m_baudRate(baudRate) {
    m_negotiation.setSingleShot(true);
    connect(&m_socket, &QTcpSocket::connected, this, &NetworkLink::onConnected);
    connect(&m_socket, &QTcpSocket::readyRead, this, &NetworkLink::onReadyRead);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError) {
        if (!m_closing) fail(m_socket.errorString());
    });
    connect(&m_socket, &QTcpSocket::disconnected, this, [this] {
        if (m_open && !m_closing) fail(tr("the serial device server closed the connection"));
    });
    connect(&m_negotiation, &QTimer::timeout, this, [this] {
        fail(tr("no RFC 2217 answer in %1 s: is it a raw TCP port? (try tcp://)").arg(kNegotiationMs / 1000));
    });
}

NetworkLink::~NetworkLink() {
    m_socket.disconnect(this);
    m_socket.abort();
}

void NetworkLink::open() {
    m_decoder = {};
    m_open = m_comPortAccepted = m_baudAnswered = false;
    m_socket.connectToHost(m_address.host, m_address.port);
}

void NetworkLink::close() {
    const bool wasOpen = m_open;
    m_open = false;
    m_negotiation.stop();
    m_closing = true; // what abort() reports is ours, not a failure
    m_socket.abort();
    m_closing = false;
    if (wasOpen) emit closed();
}

bool NetworkLink::isOpen() const {
    return m_open;
}

void NetworkLink::write(const QByteArray& data) {
    if (!m_open) {
        emit errorOccurred(tr("%1 is not connected").arg(description()));
        return;
    }
    if (m_address.protocol == Protocol::Raw) m_socket.write(data);
    else m_socket.write(bytes(rfc2217::escape(std::string_view(data.constData(), std::size_t(data.size())))));
}

QString NetworkLink::description() const {
    const QString scheme = m_address.protocol == Protocol::Raw ? QStringLiteral("tcp") : QStringLiteral("rfc2217");
    return m_address.protocol == Protocol::Raw
               ? QStringLiteral("%1://%2:%3").arg(scheme, m_address.host).arg(m_address.port)
               : QStringLiteral("%1://%2:%3 %4 8N1").arg(scheme, m_address.host).arg(m_address.port).arg(m_baudRate);
}

void NetworkLink::onConnected() {
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    if (m_address.protocol == Protocol::Raw) {
        m_open = true;
        emit opened();
        return;
    }
    // Binary both ways, no go-ahead, Com Port Control; then the line: baud rate, 8 data bits, no parity, 1 stop.
    using namespace rfc2217;
    std::string hello = option(kWill, kBinary) + option(kDo, kBinary) + option(kWill, kSuppressGoAhead) +
                        option(kDo, kSuppressGoAhead) + option(kWill, kComPortOption);
    hello += subnegotiation(kSetBaudRate, u32(std::uint32_t(m_baudRate)));
    hello += subnegotiation(kSetDataSize, std::string(1, char(8)));
    hello += subnegotiation(kSetParity, std::string(1, char(kParityNone)));
    hello += subnegotiation(kSetStopSize, std::string(1, char(kStopOne)));
    m_socket.write(bytes(hello));
    m_negotiation.start(kNegotiationMs);
}

void NetworkLink::onReadyRead() {
    const QByteArray received = m_socket.readAll();
    if (m_address.protocol == Protocol::Raw) {
        if (m_open) emit bytesReceived(received);
        return;
    }
    std::vector<rfc2217::Decoder::Command> commands;
    const std::string data =
        m_decoder.feed(std::string_view(received.constData(), std::size_t(received.size())), commands);
    for (const auto& command : commands) negotiated(command);
    if (m_open && !data.empty()) emit bytesReceived(bytes(data));
}

void NetworkLink::negotiated(const rfc2217::Decoder::Command& c) {
    using namespace rfc2217;
    const bool ours = c.option == kBinary || c.option == kSuppressGoAhead || c.option == kComPortOption;
    if ((c.verb == kDo || c.verb == kWill) && !ours) // the server asks for an option we do not speak
        m_socket.write(bytes(option(c.verb == kDo ? kWont : kDont, c.option)));
    if (c.verb == kDo && c.option == kComPortOption) m_comPortAccepted = true;
    if (c.verb == kDont && c.option == kComPortOption)
        return fail(tr("the server at %1 does not do RFC 2217 (try tcp://)").arg(description()));
    if (c.verb == kSb && c.option == kComPortOption && !c.value.empty() &&
        static_cast<unsigned char>(c.value[0]) == kSetBaudRate + kServerOffset) {
        m_baudAnswered = true;
        const std::uint32_t rate = u32(std::string_view(c.value).substr(1));
        if (rate != 0 && int(rate) != m_baudRate)
            return fail(tr("the server set the line to %1 baud, not %2").arg(rate).arg(m_baudRate));
    }
    if (!m_open && m_comPortAccepted && m_baudAnswered) {
        m_negotiation.stop();
        m_open = true;
        emit opened();
    }
}

void NetworkLink::fail(const QString& why) {
    const bool wasOpen = m_open;
    m_open = false;
    m_negotiation.stop();
    m_closing = true;
    m_socket.abort();
    m_closing = false;
    emit errorOccurred(tr("%1: %2").arg(description(), why));
    if (wasOpen) emit closed();
}

} // namespace serialport
