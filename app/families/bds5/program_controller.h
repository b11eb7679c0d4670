// ProgramController: Motion Link's Program menu — New, From Disk, From Drive (<BDS), Download to Drive (>BDS,
// line by line, with verify and P CHECKSUM), Verify Against Drive, the strip-comments and verify options and
// the drive's editor password. Results go to the status bar and terminal; drive errors and verify
// differences are marked at their editor lines, also for errors a running program reports later
// (ERR 83 LINE n), through the line map of the last download. GUI thread only.
#pragma once

#include "serialport/bds5_program_text.h"
#include "serialport/bds5_transfer.h"

#include <QMessageBox>
#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

class QAction;
class QMenu;

namespace editor {
class ProgramEditor;
}

namespace app {

class MainWindow;

class ProgramController final : public QObject {
    Q_OBJECT
public:
    explicit ProgramController(MainWindow& window);

    QMenu* menu() const { return m_menu; }

    void newProgram();
    void openFromDisk();
    void fromDrive();
    // F5: a program the editor finds errors in is downloaded only after the user says so (Download Anyway /
    // Cancel, non-modal); the question box is downloadQuestion() while it shows.
    void download();
    QMessageBox* downloadQuestion() const { return m_downloadQuestion; }
    void verify();
    // Program > Drive Password...: asks (non-modal) for the password >BDS sends; kept in AppOptions (on disk
    // only when the user ticked "remember" in Options).
    void askPassword();

    bool stripComments() const;
    void setStripComments(bool strip);
    // P CHECKSUM recorded after the last verified download (L9953-9984).
    std::optional<quint32> recordedChecksum() const { return m_checksum; }

signals:
    void transferFinished(const serialport::Bds5TransferResult& result); // after the result is shown

private:
    void startDownload(editor::ProgramEditor* editor);
    void askPasswordThen(std::function<void()> then);
    void watchDriveOutput(const QByteArray& bytes);
    void markDriveError(const serialport::Bds5ErrorLine& error);
    void finishDownload(editor::ProgramEditor* editor, const serialport::Bds5ProgramText& program,
                        const serialport::Bds5TransferResult& result);
    void finishVerify(editor::ProgramEditor* editor, const serialport::Bds5ProgramText& program,
                      const serialport::Bds5TransferResult& result);
    void showResult(const serialport::Bds5TransferResult& result);

    MainWindow& m_window;
    QMenu* m_menu;
    QAction* m_stripAction;
    QAction* m_verifyAction;
    std::optional<quint32> m_checksum;
    QPointer<QMessageBox> m_downloadQuestion;
    // What the drive holds, as far as the IDE knows: the last program downloaded or uploaded, its line map
    // and the editor it came from, for errors a running program reports later.
    std::optional<serialport::Bds5ProgramText> m_driveProgram;
    QPointer<editor::ProgramEditor> m_driveProgramEditor;
    QString m_driveOutputLine; // drive output since the last line end
};

} // namespace app
