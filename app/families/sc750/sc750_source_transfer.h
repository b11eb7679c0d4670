// Sc750SourceTransfer: Options > Download Source File and Upload Source File (L462-L474): the .BAS text
// into the controller's non-volatile memory (T size,crc; t offset,hex in 64-byte chunks; Q) and back
// (u offset until an empty chunk), with progress. One transfer per object; it deletes itself when done.
// Asynchronous through Sc750Workspace::send; GUI thread only.
#pragma once

#include <QByteArray>
#include <QObject>

namespace app {

class Sc750Workspace;

class Sc750SourceTransfer final : public QObject {
    Q_OBJECT
public:
    static constexpr int kChunkBytes = 64; // PROTOCOL.md §4

    explicit Sc750SourceTransfer(Sc750Workspace& workspace);

    void download(const QByteArray& source);
    void upload();
    void cancel(); // at the next answer
    bool isCancelled() const { return m_cancelled; }

signals:
    void progress(qint64 done, qint64 total); // total is 0 while uploading (the size is not known)
    // ok: downloaded / uploaded; bytes holds the uploaded text. Otherwise message says why.
    void finished(bool ok, const QByteArray& bytes, const QString& message);

private:
    void sendChunk();
    void askChunk();
    void finish(bool ok, const QString& message);

    Sc750Workspace& m_workspace;
    QByteArray m_bytes;
    qint64 m_offset = 0;
    bool m_cancelled = false;
};

} // namespace app
