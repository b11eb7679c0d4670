// Pmc960ProgramTransfer: MPL > Download Program and Upload Program. A download sends the current editor's
// text to the program buffer with a progress dialog (Cancel leaves the controller's editor with ESC) and
// checks the communications checksum; a refusal is reported with the controller's #xx code, the catalog's
// words and the editor line it happened on. An upload opens the buffer in a new .mpl tab. GUI thread only.
#pragma once

#include "transfer_dialog.h"

#include "serialport/pmc960_download.h"

#include <QObject>
#include <QPointer>

namespace editor {
class ProgramEditor;
}

namespace app {

class Pmc960Workspace;

class Pmc960ProgramTransfer final : public QObject {
    Q_OBJECT
public:
    explicit Pmc960ProgramTransfer(Pmc960Workspace& workspace);

    // Both refuse (with a status-bar message) while disconnected or while another transfer runs.
    void download(editor::ProgramEditor* editor);
    void upload();
    bool isBusy() const { return m_busy; }
    // The user's Stop: a running download writes ESC at once and ends cancelled (Pmc960Download::cancel).
    // An upload only reads and runs to its end.
    void cancelDownload();
    // The last transfer's summary as shown to the user ("Downloaded 7 lines; checksum 0x1A2B verified").
    QString lastMessage() const { return m_lastMessage; }
    // The progress dialog of the running download (the tour grabs it), else nullptr.
    TransferDialog* progressDialog() const { return m_progress; }
    // The program the controller holds as far as this connection knows: the text of the last download its
    // checksum verified, and the editor it came from (which may have been edited or closed since). Null before
    // one, once another starts (P{} erases the buffer), and after forgetProgram() (a new connection).
    QString downloadedProgram() const { return m_downloaded; }
    editor::ProgramEditor* downloadedEditor() const;
    void forgetProgram();

    // "#C1 Program buffer full: <the manual's meaning>" for a controller error code.
    static QString describeError(int code);
    // The 1-based editor line holding the index-th line the download sends (blank lines are not sent).
    static int editorLineOf(const QString& text, int index);

signals:
    void busyChanged(bool busy);
    // editorLine: 1-based line of the downloaded editor where the controller refused, 0 if none.
    void downloadFinished(const serialport::Pmc960DownloadResult& result, int editorLine);
    void uploadFinished(bool ok, editor::ProgramEditor* tab);

private:
    bool canStart();
    void setBusy(bool busy);
    void finishDownload(const serialport::Pmc960DownloadResult& result, QPointer<editor::ProgramEditor> editor,
                        const QString& text, int linesSent);
    void report(const QString& message, bool error);

    Pmc960Workspace& m_workspace;
    QPointer<TransferDialog> m_progress;
    QPointer<serialport::Pmc960Download> m_download;
    QString m_lastMessage;
    QString m_downloaded;
    QPointer<editor::ProgramEditor> m_downloadedEditor;
    bool m_busy = false;
};

} // namespace app
