// CaptureLog: Motion Link's communications capture. While capturing, every byte to and from the drive is
// kept with the time it crossed; there is no size limit (chosen: Motion Link's buffer held 16 KB, ours
// grows as needed and the view shows the size). Saves and loads .CAP files. GUI thread only.
//
// .CAP format (chosen; the manual only says the capture logs received text, L1077-1081): the bytes the
// drive sent, verbatim — Latin-1, CR LF line ends, the BEL before ERR lines kept. The drive echoes what is
// typed, so the file reads like the terminal. Bytes the drive does not echo (^X, Esc, ^V, anything sent
// with ECHO 0) and the times are in the in-memory transcript only. A loaded file is one received entry.
#pragma once

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <vector>

namespace app {

class CaptureLog final : public QObject {
    Q_OBJECT
public:
    enum class Direction { Received, Sent };
    struct Entry {
        qint64 atMs = 0; // since the capture started; 0 for a loaded file
        Direction direction = Direction::Received;
        QByteArray bytes;
    };

    explicit CaptureLog(QObject* parent = nullptr);

    // START CAPTURE clears the buffer and starts logging; STOP CAPTURE stops (the buffer stays).
    void start();
    void stop();
    void clear();
    bool isCapturing() const { return m_capturing; }

    // Bytes that crossed the link; kept only while capturing.
    void addReceived(const QByteArray& bytes) { add(Direction::Received, bytes); }
    void addSent(const QByteArray& bytes) { add(Direction::Sent, bytes); }

    // Consecutive bytes in one direction form one entry until a line ends, the direction changes or the
    // line is quiet for kQuietMs.
    const std::vector<Entry>& entries() const { return m_entries; }
    qint64 receivedBytes() const { return m_received; }
    qint64 sentBytes() const { return m_sent; }

    // The .CAP contents (see above).
    QByteArray capBytes() const;
    // Both directions with times, one entry a line: "   1.234 s  >  P X1<CR>". For the view.
    QString transcript() const;

    // Error text for the user on failure, empty on success.
    QString saveCap(const QString& path) const;
    QString loadCap(const QString& path);

    static constexpr int kQuietMs = 100;

signals:
    void changed();
    void capturingChanged(bool capturing);

private:
    void add(Direction direction, const QByteArray& bytes);

    std::vector<Entry> m_entries;
    QElapsedTimer m_clock;
    bool m_capturing = false;
    qint64 m_received = 0;
    qint64 m_sent = 0;
};

} // namespace app
