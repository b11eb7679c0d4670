// Pmc960Upload: Program > Upload from the PMC-960: P! lists the whole program buffer (each line after CR LF,
// then the prompt; L1398-1439) and the listing becomes editor text, one buffer line per line.
#pragma once

#include "pmc960_session.h"

#include <QObject>
#include <QStringList>

namespace serialport {

class Pmc960Upload final : public QObject {
    Q_OBJECT
public:
    explicit Pmc960Upload(Pmc960Session& session, QObject* parent = nullptr);

    void start(int timeoutMs = 10000);
    // The buffer lines of a P! response's text ("\r\n@T\r\nI+,...").
    static QStringList linesFromListing(const QByteArray& text);

signals:
    void done(bool ok, const QStringList& lines, const QString& reason);

private:
    Pmc960Session& m_session;
    quint64 m_waiting = 0;
};

} // namespace serialport
