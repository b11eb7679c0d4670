// FaultLink damages bytes as told, the same way for the same seed, keeps order under delays, and a cut
// cable closes the link with a reason.
#include "serialport/fault_link.h"

#include <QSignalSpy>
#include <QTest>

using namespace serialport;

namespace {
// A link whose far end echoes every byte: what goes out comes back.
class LoopbackLink final : public Link {
public:
    void open() override {
        m_open = true;
        emit opened();
    }
    void close() override {
        m_open = false;
        emit closed();
    }
    bool isOpen() const override { return m_open; }
    void write(const QByteArray& bytes) override { emit bytesReceived(bytes); }
    QString description() const override { return QStringLiteral("loopback"); }
    int baudRate() const override { return 0; }

private:
    bool m_open = false;
};

QByteArray pattern(int n) {
    QByteArray b;
    for (int i = 0; i < n; ++i) b.append(char('A' + i % 26));
    return b;
}
} // namespace

class FaultLinkTest : public QObject {
    Q_OBJECT

private slots:
    void sameSeedSameDamage() {
        QByteArray first;
        QByteArray second;
        for (QByteArray* out : {&first, &second}) {
            LoopbackLink inner;
            FaultLink link(inner, 42, {0.01, 0.01, 0.01}, {});
            connect(&link, &Link::bytesReceived, [out](const QByteArray& b) { *out += b; });
            link.open();
            link.write(pattern(10000));
        }
        QCOMPARE(first, second);
        QVERIFY(first != pattern(10000));
    }

    void ratesAreAsAsked() {
        LoopbackLink inner;
        FaultLink link(inner, 7, {}, {0.01, 0.01, 0});
        QByteArray got;
        connect(&link, &Link::bytesReceived, [&got](const QByteArray& b) { got += b; });
        link.open();
        const QByteArray sent = pattern(200000);
        link.write(sent);
        const auto& c = link.fromDriveCounters();
        QCOMPARE(c.bytes, qint64(200000));
        QVERIFY2(c.dropped > 1700 && c.dropped < 2300, qPrintable(QString::number(c.dropped)));
        QVERIFY2(c.corrupted > 1700 && c.corrupted < 2300, qPrintable(QString::number(c.corrupted)));
        QCOMPARE(got.size(), sent.size() - c.dropped);
    }

    void corruptionFlipsOneBit() {
        LoopbackLink inner;
        FaultLink link(inner, 3, {0, 1.0, 0}, {});
        QByteArray got;
        connect(&link, &Link::bytesReceived, [&got](const QByteArray& b) { got += b; });
        link.open();
        link.write(pattern(100));
        QCOMPARE(got.size(), 100);
        const QByteArray sent = pattern(100);
        for (int i = 0; i < 100; ++i) QCOMPARE(__builtin_popcount(unsigned(uchar(got[i]) ^ uchar(sent[i]))), 1);
    }

    void delaysKeepOrder() {
        LoopbackLink inner;
        FaultLink link(inner, 5, {0, 0, 0, 30, 0.5, 40}, {});
        QByteArray got;
        connect(&link, &Link::bytesReceived, [&got](const QByteArray& b) { got += b; });
        link.open();
        QByteArray sent;
        for (int i = 0; i < 20; ++i) {
            const QByteArray chunk = QByteArray::number(i) + ',';
            sent += chunk;
            link.write(chunk);
        }
        QVERIFY(got.isEmpty()); // nothing before the delay
        QTRY_COMPARE_WITH_TIMEOUT(got, sent, 3000);
        QVERIFY(link.toDriveCounters().stalled > 0);
    }

    void cutCableClosesWithAReason() {
        LoopbackLink inner;
        FaultLink link(inner, 1, {}, {});
        link.open();
        QSignalSpy closed(&link, &Link::closed);
        QSignalSpy errors(&link, &Link::errorOccurred);
        link.cut();
        QCOMPARE(closed.count(), 1);
        QVERIFY(errors.first().first().toString().contains(QStringLiteral("cable")));
        QVERIFY(!link.isOpen());
        link.write("P 1\r");
        QCOMPARE(errors.count(), 2);
    }
};

QTEST_GUILESS_MAIN(FaultLinkTest)
#include "fault_link_test.moc"
