// Bds5BusScan: which axes answer on a BDS5 multidrop line (issue 21). Each ID in turn is called with '\' and
// the ID (L5449-5451, L10013-10038); an axis that is there wakes and answers with its prompt, whose first
// character is its ID and whose second says its mode (Table 4.17: "B->" interactive, "B=>" monitor, "Be>"
// the editor). A prompt is credited to the ID it carries, so an answer that comes late still counts for its
// own axis. The line is left with every axis asleep ('\' alone). Works on any Link, without a session (no
// axis answers until called). GUI thread only.
#pragma once

#include "drive_timeout.h"

#include <QList>
#include <QObject>
#include <QString>

namespace serialport {

class Link;

class Bds5BusScan final : public QObject {
    Q_OBJECT
public:
    struct Axis {
        QChar id;
        QString prompt; // "B->"
        QString mode;   // "interactive", "monitor", "editor", ...
    };
    // Every ID a BDS5 axis can have: 0-9, then A-Z (L5416-5424).
    static QString allIds();

    // ids: the IDs to call, in order; waitMs: how long an ID may take to answer before the next is called.
    Bds5BusScan(Link& link, QString ids, int waitMs, QObject* parent = nullptr);

    void start(); // the link must be open
    const QList<Axis>& axes() const { return m_axes; }

signals:
    void progress(int called, int total);
    void finished(const QList<serialport::Bds5BusScan::Axis>& axes); // in ID order

private:
    void callNext();
    void onBytes(const QByteArray& bytes);

    Link& m_link;
    QString m_ids;
    int m_waitMs;
    DriveTimeout m_wait;
    int m_next = 0;
    QByteArray m_received;
    QList<Axis> m_axes;
    bool m_done = false;
};

} // namespace serialport
