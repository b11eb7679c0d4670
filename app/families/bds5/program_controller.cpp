// ProgramController: the Program menu and its transfers.
#include "program_controller.h"

#include "settings/app_options.h"
#include "editing/document_controller.h"
#include "drive_connection.h"
#include "editing/editor_area.h"
#include "main_window.h"
#include "transfer/transfer_dialog.h"
#include "transfer/transfer_markers.h"
#include "transfer/transfer_reporter.h"

#include "drive_core/bds5/bds5_checker.h"
#include "editor/program_editor.h"
#include "serialport/bds5_download.h"
#include "serialport/bds5_upload.h"
#include "serialport/bds5_verify.h"

#include <QInputDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>

namespace app {

namespace {
const QString kStripKey = QStringLiteral("program/stripComments");
const QString kVerifyKey = QStringLiteral("program/verifyAfterDownload");
constexpr int kNoEditorLine = 0;
using Status = serialport::Bds5TransferResult::Status;
} // namespace

ProgramController::ProgramController(MainWindow& window)
    : QObject(&window), m_window(window), m_menu(new QMenu(tr("&Program"), &window)) {
    m_menu->setObjectName(QStringLiteral("programMenu"));
    m_menu->addAction(tr("&New Program"), this, &ProgramController::newProgram);
    m_menu->addAction(tr("From &Disk..."), this, &ProgramController::openFromDisk);
    m_menu->addAction(tr("From D&rive"), this, &ProgramController::fromDrive);
    m_menu->addSeparator();
    // chosen: F5, the usual "send/run" key of IDEs; Motion Link's own ^T is the editor's delete-word.
    m_menu->addAction(tr("Down&load to Drive"), QKeySequence(Qt::Key_F5), this, &ProgramController::download);
    m_menu->addAction(tr("&Verify Against Drive"), this, &ProgramController::verify);
    m_menu->addSeparator();
    QSettings settings;
    m_stripAction = m_menu->addAction(tr("Download &Without Comments"));
    m_stripAction->setCheckable(true);
    m_stripAction->setChecked(settings.value(kStripKey, false).toBool());
    m_stripAction->setToolTip(tr("Comment and blank lines are not sent; drive error line numbers are mapped "
                                 "back to the editor"));
    connect(m_stripAction, &QAction::toggled, this, [](bool on) { QSettings().setValue(kStripKey, on); });
    m_verifyAction = m_menu->addAction(tr("Verify &After Download"));
    m_verifyAction->setCheckable(true);
    m_verifyAction->setChecked(settings.value(kVerifyKey, true).toBool());
    connect(m_verifyAction, &QAction::toggled, this, [](bool on) { QSettings().setValue(kVerifyKey, on); });
    m_menu->addAction(tr("Drive &Password..."), this, &ProgramController::askPassword);

    connect(&window.connection(), &DriveConnection::rawReceived, this, &ProgramController::watchDriveOutput);
}

bool ProgramController::stripComments() const {
    return m_stripAction->isChecked();
}

void ProgramController::setStripComments(bool strip) {
    m_stripAction->setChecked(strip);
}

void ProgramController::newProgram() {
    m_window.editorArea()->documents()->newDocument();
}

void ProgramController::openFromDisk() {
    m_window.editorArea()->documents()->open();
}

void ProgramController::fromDrive() {
    if (!TransferReporter::canStart(m_window)) return;
    auto* upload = new serialport::Bds5Upload(*m_window.connection().session());
    new TransferDialog(tr("Program From Drive"), upload, &m_window);
    connect(
        upload, &serialport::Bds5Transfer::finished, this, [this](const serialport::Bds5TransferResult& r) {
            TransferReporter::report(m_window, r, tr("drive"));
            if (r.ok()) {
                const QString text =
                    r.lines.isEmpty() ? QString() : r.lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
                editor::ProgramEditor* editor =
                    TransferReporter::openNewDocument(m_window, QStringLiteral("drive-program.bds"), text);
                // The drive holds exactly this text: its LINE n is editor line n.
                m_driveProgram = serialport::Bds5ProgramText::prepare(text, false);
                m_driveProgramEditor = editor;
            }
            emit transferFinished(r);
        });
    upload->start();
}

void ProgramController::download() {
    if (!TransferReporter::canStart(m_window) || m_downloadQuestion) return;
    editor::ProgramEditor* editor = m_window.editor();
    // The editor's own diagnostics (the drive's parser, Bds5Checker): the drive would refuse these lines.
    std::vector<std::string> lines;
    for (QString line : editor->text().split(QLatin1Char('\n'))) {
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
        lines.push_back(line.toStdString());
    }
    const auto diagnostics = drive_core::bds5::checkProgram(lines);
    if (diagnostics.empty()) return startDownload(editor);
    const auto& first = diagnostics.front();
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Download to Drive"),
                                tr("The editor finds %n error(s) in this program; the first is on line %1: %2.\n\n"
                                   "The drive will refuse those lines.",
                                   nullptr, int(diagnostics.size()))
                                    .arg(first.line)
                                    .arg(QString::fromStdString(first.message)),
                                QMessageBox::Cancel, &m_window);
    QPushButton* anyway = box->addButton(tr("Download &Anyway"), QMessageBox::AcceptRole);
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    m_downloadQuestion = box;
    QPointer<editor::ProgramEditor> target(editor);
    connect(box, &QMessageBox::finished, this, [this, box, anyway, target, line = first.line](int) {
        if (box->clickedButton() == anyway && target) return startDownload(target);
        if (target) target->setCursorPosition(line - 1, 0);
        m_window.statusBar()->showMessage(tr("Download cancelled: the program has errors (line %1 first).").arg(line),
                                          8000);
    });
    box->open();
}

void ProgramController::startDownload(editor::ProgramEditor* editor) {
    if (!TransferReporter::canStart(m_window)) return;
    TransferMarkers::clear(*editor);
    auto* transfer = new serialport::Bds5Download(
        *m_window.connection().session(), editor->text(),
        {AppOptions::current().drivePassword, stripComments(), m_verifyAction->isChecked()});
    new TransferDialog(tr("Download to Drive"), transfer, &m_window);
    QPointer<editor::ProgramEditor> target(editor);
    connect(transfer, &serialport::Bds5Transfer::finished, this,
            [this, target, transfer](const serialport::Bds5TransferResult& r) {
                finishDownload(target, transfer->program(), r);
            });
    transfer->start();
}

void ProgramController::finishDownload(editor::ProgramEditor* editor,
                                       const serialport::Bds5ProgramText& program,
                                       const serialport::Bds5TransferResult& result) {
    showResult(result);
    if (result.linesDone > 0 || result.ok()) {
        // Whatever the drive accepted is what it holds now: map its later errors through this download.
        m_driveProgram = program;
        m_driveProgramEditor = editor;
    }
    if (result.checksum) m_checksum = result.checksum;
    if (editor) {
        for (const serialport::Bds5LineError& e : result.errors)
            TransferMarkers::mark(*editor, e.sourceLine, serialport::describeError(e.error));
        if (result.status == Status::Mismatch) finishVerify(editor, program, result);
    }
    if (result.status == Status::Refused && !result.errors.isEmpty() &&
        result.errors.first().error.code == 110)
        askPasswordThen([this] { download(); }); // chosen: ask at once, download again when given
    emit transferFinished(result);
}

void ProgramController::verify() {
    if (!TransferReporter::canStart(m_window)) return;
    editor::ProgramEditor* editor = m_window.editor();
    TransferMarkers::clear(*editor);
    const auto program = serialport::Bds5ProgramText::prepare(editor->text(), stripComments());
    auto* transfer = new serialport::Bds5Verify(*m_window.connection().session(), program);
    transfer->setRecordedChecksum(m_checksum);
    new TransferDialog(tr("Verify Against Drive"), transfer, &m_window);
    QPointer<editor::ProgramEditor> target(editor);
    connect(transfer, &serialport::Bds5Transfer::finished, this,
            [this, target, program](const serialport::Bds5TransferResult& r) {
                showResult(r);
                if (target && r.status == Status::Mismatch) finishVerify(target, program, r);
                emit transferFinished(r);
            });
    transfer->start();
}

void ProgramController::finishVerify(editor::ProgramEditor* editor,
                                     const serialport::Bds5ProgramText& program,
                                     const serialport::Bds5TransferResult& result) {
    // A line the drive lacks or holds extra has no editor line of its own: mark the last line sent then.
    int line = result.mismatchSourceLine;
    if (line == kNoEditorLine && program.lineCount() > 0) line = program.sourceLine(program.lineCount());
    const QString text = result.actual.isEmpty() && result.mismatchDriveLine > program.lineCount()
                             ? tr("Verify: the drive holds more lines than were sent")
                         : result.actual.isEmpty()
                             ? tr("Verify: the drive's program ends before this line")
                             : tr("Verify: the drive holds \"%1\" here").arg(result.actual);
    TransferMarkers::mark(*editor, line, text, TransferMarkers::Kind::Mismatch);
    TransferReporter::showLine(*editor, line);
}

void ProgramController::showResult(const serialport::Bds5TransferResult& result) {
    TransferReporter::report(m_window, result, m_window.editorArea()->documents()->displayName());
}

void ProgramController::askPassword() {
    askPasswordThen({});
}

void ProgramController::askPasswordThen(std::function<void()> then) {
    auto* dialog = new QInputDialog(&m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setObjectName(QStringLiteral("drivePasswordDialog"));
    dialog->setWindowTitle(tr("Drive Password"));
    dialog->setLabelText(tr("The editor password set on the drive with PASS (up to six characters).\n"
                            ">BDS sends it with every download. It is kept until ServoDesk closes,\n"
                            "unless \"remember\" is ticked under Options."));
    dialog->setTextEchoMode(QLineEdit::Password);
    dialog->setTextValue(AppOptions::current().drivePassword);
    connect(dialog, &QInputDialog::textValueSelected, this, [this, then](const QString& password) {
        AppOptions options = AppOptions::current();
        options.drivePassword = password;
        options.save(); // written to disk only when the user chose "remember" in Options
        m_window.statusBar()->showMessage(password.isEmpty() ? tr("No drive password: >BDS is sent alone.")
                                                             : tr("Drive password set."),
                                          TransferReporter::kStatusMs);
        if (then) then();
    });
    dialog->open();
}

void ProgramController::watchDriveOutput(const QByteArray& bytes) {
    // A running program's errors name the drive's line (ERR 83 LINE 3 ...): find it in the editor.
    m_driveOutputLine += QString::fromLatin1(bytes);
    qsizetype end;
    while ((end = m_driveOutputLine.indexOf(QLatin1Char('\n'))) >= 0) {
        QString line = m_driveOutputLine.left(end);
        m_driveOutputLine.remove(0, end + 1);
        while (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        if (!line.startsWith(QLatin1Char('\a'))) continue; // the drive rings before every error line
        if (const auto error = serialport::parseErrorLine(line); error && error->programLine > 0)
            markDriveError(*error);
    }
    if (m_driveOutputLine.size() > 4096) m_driveOutputLine.clear(); // no line end in sight: not an error line
}

void ProgramController::markDriveError(const serialport::Bds5ErrorLine& error) {
    if (!m_driveProgram || !m_driveProgramEditor) return;
    const int line = m_driveProgram->sourceLine(error.programLine);
    if (line == kNoEditorLine) return;
    TransferMarkers::mark(*m_driveProgramEditor, line, serialport::describeError(error));
    m_window.statusBar()->showMessage(
        tr("Editor line %1: %2").arg(line).arg(serialport::describeError(error)),
        TransferReporter::kStatusMs);
}

} // namespace app
