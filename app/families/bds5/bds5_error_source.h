// Bds5ErrorSource: the BDS5's error log — ERR HIST read on demand, the errors the drive reports as they
// arrive (bell-led lines in its byte stream), ERR CLR. Talks only through the connection's session.
#pragma once

#include "errors/error_source.h"
#include "errors/error_stream_scanner.h"

#include "serialport/bds5_session.h"

#include <QPointer>

namespace app {

class DriveConnection;

class Bds5ErrorSource final : public ErrorSource {
    Q_OBJECT
public:
    explicit Bds5ErrorSource(DriveConnection& connection, QObject* parent = nullptr);

    void read() override;  // ERR HIST
    void clear() override; // ERR CLR, then ERR HIST to show it is empty

private:
    void follow();
    void onFinished(quint64 id, const serialport::Bds5Response& response);
    void onBytes(const QByteArray& bytes);

    DriveConnection& m_connection;
    ErrorStreamScanner m_scanner;
    QPointer<serialport::Bds5Session> m_session;
    quint64 m_historyId = 0;
};

} // namespace app
