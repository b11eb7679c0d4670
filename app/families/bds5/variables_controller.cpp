// VariablesController: the Variables menu and its transfers.
#include "variables_controller.h"

#include "editing/document_controller.h"
#include "drive_connection.h"
#include "editing/editor_area.h"
#include "editing/editor_tabs.h"
#include "main_window.h"
#include "transfer/transfer_dialog.h"
#include "transfer/transfer_markers.h"
#include "transfer/transfer_reporter.h"

#include "editor/program_editor.h"
#include "resources/resources.h"
#include "serialport/bds5_variables_from_drive.h"
#include "serialport/bds5_variables_to_drive.h"

#include <QDateTime>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>
#include <QStatusBar>

namespace app {

namespace {
const QString kStandardName = QStringLiteral("STANDARD.VAR");

QString standardText() {
    QFile file(resources::kStandardVariables);
    return file.open(QIODevice::ReadOnly) ? QString::fromLatin1(file.readAll()) : QString();
}
} // namespace

VariablesController::VariablesController(MainWindow& window)
    : QObject(&window), m_window(window), m_menu(new QMenu(tr("V&ariables"), &window)) {
    m_menu->setObjectName(QStringLiteral("variablesMenu"));
    m_menu->addAction(tr("&New Variables"), this, &VariablesController::newVariables);
    m_menu->addAction(tr("From &Disk..."), this, &VariablesController::openFromDisk);
    m_menu->addAction(tr("From D&rive"), this, &VariablesController::fromDrive);
    m_menu->addSeparator();
    m_menu->addAction(tr("&Send to Drive"), QKeySequence(tr("Shift+F5")), this,
                      &VariablesController::sendToDrive);
    m_menu->addSeparator();
    m_menu->addAction(tr("&View STANDARD.VAR"), this, &VariablesController::viewStandard);
    m_menu->addAction(tr("Reset to S&TANDARD.VAR..."), this, &VariablesController::resetToStandard);
}

void VariablesController::newVariables() {
    EditorTabs& tabs = *m_window.editorArea()->tabs();
    tabs.addEditor(tabs.freeUntitledName(FileType::Variables));
}

void VariablesController::openFromDisk() {
    m_window.editorArea()->documents()->open();
}

void VariablesController::viewStandard() {
    m_window.editorArea()->documents()->openTemplate(resources::kStandardVariables, kStandardName);
}

void VariablesController::fromDrive() {
    if (!TransferReporter::canStart(m_window)) return;
    auto* transfer = new serialport::Bds5VariablesFromDrive(*m_window.connection().session());
    new TransferDialog(tr("Variables From Drive"), transfer, &m_window);
    connect(transfer, &serialport::Bds5Transfer::finished, this,
            [this, transfer](const serialport::Bds5TransferResult& r) {
                TransferReporter::report(m_window, r, tr("DUMP"));
                if (r.ok()) {
                    const QString text = transfer->variables().toText(
                        {tr("BDS5 variables read with DUMP from %1, %2")
                             .arg(m_window.connection().linkDescription(),
                                  QDateTime::currentDateTime().toString(Qt::ISODate)),
                         tr("One NAME value per line; Variables > Send to Drive sends them back.")});
                    TransferReporter::openNewDocument(m_window, QStringLiteral("drive-variables.var"), text);
                }
                emit transferFinished(r);
            });
    transfer->start();
}

void VariablesController::sendToDrive() {
    editor::ProgramEditor* editor = m_window.editor();
    send(editor->text(), editor, m_window.editorArea()->documents()->displayName(),
         tr("Send Variables to Drive"));
}

void VariablesController::resetToStandard() {
    auto* box = new QMessageBox(QMessageBox::Question, tr("Reset to STANDARD.VAR"),
                                tr("Send the factory variable set STANDARD.VAR to the drive?\n\nEvery gain, "
                                   "limit, unit and user variable it lists goes back to its factory value. "
                                   "Communication settings and outputs are left alone."),
                                QMessageBox::Yes | QMessageBox::Cancel, &m_window);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setDefaultButton(QMessageBox::Cancel);
    connect(box, &QMessageBox::finished, this, [this, box](int) {
        if (box->standardButton(box->clickedButton()) == QMessageBox::Yes) sendStandard();
    });
    box->open();
}

void VariablesController::sendStandard() {
    send(standardText(), nullptr, kStandardName, tr("Reset to STANDARD.VAR"));
}

void VariablesController::send(const QString& text, editor::ProgramEditor* markIn, const QString& fileName,
                               const QString& title) {
    if (!TransferReporter::canStart(m_window)) return;
    if (markIn) TransferMarkers::clear(*markIn);
    auto* transfer = new serialport::Bds5VariablesToDrive(*m_window.connection().session(), text);
    new TransferDialog(title, transfer, &m_window);
    QPointer<editor::ProgramEditor> target(markIn);
    connect(transfer, &serialport::Bds5Transfer::finished, this,
            [this, target, fileName](const serialport::Bds5TransferResult& r) {
                TransferReporter::report(m_window, r, fileName);
                int first = 0;
                for (const serialport::Bds5LineError& e : r.errors) {
                    if (!target) break;
                    TransferMarkers::mark(*target, e.sourceLine,
                                          e.error.code ? serialport::describeError(e.error)
                                                       : e.error.message);
                    if (!first) first = e.sourceLine;
                }
                if (target && first) TransferReporter::showLine(*target, first);
                emit transferFinished(r);
            });
    transfer->start();
}

} // namespace app
