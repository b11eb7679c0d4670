// Pmc960ProgramTransfer: the MPL menu's download and upload, reported in the status bar and terminal.
#include "pmc960_program_transfer.h"

#include "pmc960_workspace.h"

#include "editor_area.h"
#include "main_window.h"
#include "transfer_reporter.h"

#include "drive_core/catalog/pmc960_catalog.h"
#include "editor/program_editor.h"
#include "serialport/pmc960_upload.h"

#include <QStatusBar>

namespace app {

Pmc960ProgramTransfer::Pmc960ProgramTransfer(Pmc960Workspace& workspace)
    : QObject(&workspace), m_workspace(workspace) {}

QString Pmc960ProgramTransfer::describeError(int code) {
    const auto* info = drive_core::catalog::pmc960::findError(code);
    const QString hex = QStringLiteral("#%1").arg(code, 2, 16, QLatin1Char('0')).toUpper();
    if (!info) return tr("%1 (not in the PMC-960's error list)").arg(hex);
    return QStringLiteral("%1 %2: %3")
        .arg(hex, QString::fromUtf8(info->message.data(), qsizetype(info->message.size())),
             QString::fromUtf8(info->meaning.data(), qsizetype(info->meaning.size())));
}

int Pmc960ProgramTransfer::editorLineOf(const QString& text, int index) {
    QString normal = text;
    normal.replace(QStringLiteral("\r\n"), QStringLiteral("\n")).replace(QLatin1Char('\r'), QLatin1Char('\n'));
    const QStringList lines = normal.split(QLatin1Char('\n'));
    int sent = 0;
    for (int i = 0; i < lines.size(); ++i) {
        if (lines.at(i).trimmed().isEmpty() || serialport::Pmc960Download::programLines(lines.at(i)).isEmpty())
            continue;
        if (sent++ == index) return i + 1;
    }
    return 0;
}

bool Pmc960ProgramTransfer::canStart() {
    QString why;
    if (!m_workspace.session()) why = tr("Not connected to a PMC-960: Drive > Connect first.");
    else if (m_busy) why = tr("A program transfer is already running.");
    if (why.isEmpty()) return true;
    m_workspace.window().statusBar()->showMessage(why, TransferReporter::kStatusMs);
    return false;
}

void Pmc960ProgramTransfer::setBusy(bool busy) {
    if (m_busy == busy) return;
    m_busy = busy;
    emit busyChanged(busy);
}

void Pmc960ProgramTransfer::report(const QString& message, bool error) {
    m_lastMessage = message;
    emit m_workspace.message(error ? tr("Error: %1").arg(message) : message);
}

void Pmc960ProgramTransfer::download(editor::ProgramEditor* editor) {
    if (!editor || !canStart()) return;
    forgetProgram(); // P{} erases the buffer first: until the checksum says so, nothing is known to be in it
    const QString text = editor->text();
    auto* job = new serialport::Pmc960Download(*m_workspace.session(), text, this);
    m_download = job;
    const int total = int(job->lines().size());
    setBusy(true);
    m_progress = new TransferDialog(tr("Download Program"), tr("lines"), [job] { job->cancel(); }, &m_workspace.window());
    m_progress->setStage(tr("Downloading %n line(s) to the PMC-960 program buffer\u2026", nullptr, total));
    m_progress->showProgress(0, total);
    auto sent = std::make_shared<int>(0);
    connect(job, &serialport::Pmc960Download::progress, this, [this, sent](int lines, int) {
        *sent = lines;
        if (m_progress) m_progress->showProgress(lines, m_download ? m_download->lines().size() : 0);
    });
    QPointer<editor::ProgramEditor> target(editor);
    connect(job, &serialport::Pmc960Download::done, this,
            [this, job, target, text, sent](const serialport::Pmc960DownloadResult& result) {
                job->deleteLater();
                finishDownload(result, target, text, *sent);
            });
    job->start();
}

void Pmc960ProgramTransfer::finishDownload(const serialport::Pmc960DownloadResult& result,
                                           QPointer<editor::ProgramEditor> editor, const QString& text,
                                           int linesSent) {
    int line = 0;
    if (result.ok) {
        m_downloaded = text;
        m_downloadedEditor = editor;
        report(tr("Downloaded %n line(s) to the PMC-960; checksum 0x%1 verified.", nullptr, linesSent)
                   .arg(result.driveChecksum, 4, 16, QLatin1Char('0')),
               false);
    } else if (result.cancelled) {
        report(tr("Download cancelled after %n line(s); the program buffer holds them.", nullptr, linesSent), true);
    } else if (result.error != 0) {
        line = editorLineOf(text, linesSent); // the line being sent when the controller refused
        report(line > 0 ? tr("The PMC-960 refused line %1: %2").arg(line).arg(describeError(result.error))
                        : tr("The PMC-960 refused the download: %1").arg(describeError(result.error)),
               true);
        if (editor && line > 0) TransferReporter::showLine(*editor, line);
    } else {
        report(tr("Download failed: %1").arg(result.reason), true);
    }
    if (m_progress) {
        using Outcome = TransferDialog::Outcome;
        m_progress->finish(result.ok ? Outcome::Done
                           : result.cancelled ? Outcome::Cancelled
                           : result.error != 0 ? Outcome::Refused
                                               : Outcome::Failed,
                           m_lastMessage);
    }
    setBusy(false);
    emit downloadFinished(result, line);
}

editor::ProgramEditor* Pmc960ProgramTransfer::downloadedEditor() const {
    return m_downloadedEditor;
}

void Pmc960ProgramTransfer::forgetProgram() {
    m_downloaded.clear();
    m_downloadedEditor.clear();
}

void Pmc960ProgramTransfer::cancelDownload() {
    if (m_download) m_download->cancel();
}

void Pmc960ProgramTransfer::upload() {
    if (!canStart()) return;
    auto* job = new serialport::Pmc960Upload(*m_workspace.session(), this);
    setBusy(true);
    connect(job, &serialport::Pmc960Upload::done, this,
            [this, job](bool ok, const QStringList& lines, const QString& reason) {
                job->deleteLater();
                editor::ProgramEditor* tab = nullptr;
                if (ok) {
                    QString text = lines.join(QLatin1Char('\n'));
                    if (!text.isEmpty()) text += QLatin1Char('\n');
                    tab = TransferReporter::openNewDocument(m_workspace.window(), QStringLiteral("pmc960-program.mpl"),
                                                            text);
                    report(tr("Uploaded %n line(s) from the PMC-960 program buffer.", nullptr, int(lines.size())),
                           false);
                } else {
                    report(tr("Upload failed: %1").arg(reason), true);
                }
                setBusy(false);
                emit uploadFinished(ok, tab);
            });
    job->start();
}

} // namespace app
