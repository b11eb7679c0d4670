// Sc750ControllerMenu: new programs, axis, .BIN download, configure and unconfigure.
#include "sc750_controller_menu.h"

#include "sc750_debugger.h"
#include "sc750_setup_dialog.h"
#include "sc750_source_transfer.h"
#include "sc750_workspace.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "file_types.h"
#include "main_window.h"
#include "transfer_dialog.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "editor/program_editor.h"
#include "serialport/sc750_parameter_file.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace app {

namespace catalog = drive_core::catalog::sc750;

Sc750ControllerMenu::Sc750ControllerMenu(Sc750Workspace& workspace, QWidget* parent)
    : QMenu(tr("Co&ntroller"), parent), m_workspace(workspace) {
    setObjectName(QStringLiteral("sc750ControllerMenu"));
    addAction(tr("Create &Program"), this, &Sc750ControllerMenu::createProgram);
    addAction(tr("&Edit Parameters..."), this, &Sc750ControllerMenu::editParameters);
    addSeparator();
    addAction(tr("&Axis Selection..."), this, &Sc750ControllerMenu::selectAxis);
    addAction(tr("Download &BIN File..."), this, &Sc750ControllerMenu::downloadBinFile);
    addAction(tr("&Download Source File"), this, &Sc750ControllerMenu::downloadSource);
    addAction(tr("Upl&oad Source File"), this, &Sc750ControllerMenu::uploadSource);
    addSeparator();
    addAction(tr("Controller &Set Up..."), this, &Sc750ControllerMenu::controllerSetUp);
    addAction(tr("&Unconfigure..."), this, &Sc750ControllerMenu::unconfigure);
}

QString Sc750ControllerMenu::boilerplate() {
    QList<QPair<QString, QString>> values;
    for (const catalog::VariableInfo& v : catalog::variables()) {
        if (v.access != catalog::Access::Parameter) continue;
        const std::string name(v.name);
        values.append({QString::fromStdString(name), serialport::Sc750ParameterFile::formatValue(name, v.defaultValue)});
    }
    QStringList lines{QStringLiteral("'-----Parameter Values Header-----"), serialport::Sc750ParameterFile::block(values)};
    lines << QString() << QStringLiteral("'----- Variable Definitions -----")
          << QStringLiteral("' for help put cursor on -> DIM <- and press the F1 key") << QString()
          << QStringLiteral("'----- Main Program -----") << QString() << QStringLiteral("END") << QString()
          << QStringLiteral("'----- Subroutines and Interrupt Routines -----") << QString();
    return lines.join(QLatin1Char('\n'));
}

void Sc750ControllerMenu::createProgram() {
    EditorTabs* tabs = m_workspace.window().editorArea()->tabs();
    editor::ProgramEditor* editor = tabs->addEditor(tabs->freeUntitledName(FileType::Sc750Program));
    editor->setText(boilerplate());
    editor->setModified(false);
    tabs->refreshTab(editor);
    editor->setFocus();
}

void Sc750ControllerMenu::selectAxis() {
    auto* dialog = new QInputDialog(&m_workspace.window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Axis Selection"));
    dialog->setLabelText(tr("Multidrop address of the controller (S1 switches), 0-254; 255 = RS-232:"));
    dialog->setInputMode(QInputDialog::IntInput);
    dialog->setIntRange(0, 255);
    dialog->setIntValue(m_workspace.axis());
    connect(dialog, &QInputDialog::intValueSelected, &m_workspace, &Sc750Workspace::setAxis);
    dialog->open();
}

void Sc750ControllerMenu::downloadBinFile() {
    auto* dialog = new QFileDialog(&m_workspace.window(), tr("Download BIN File"), QString(),
                                   tr("Compiled programs (*.BIN *.bin)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            emit m_workspace.message(tr("Cannot open %1: %2").arg(path, file.errorString()));
            return;
        }
        const QByteArray bytes = file.readAll();
        m_workspace.debugger().downloadBin(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    });
    dialog->open();
}

Sc750SourceTransfer* Sc750ControllerMenu::startTransfer(const QString& title, const QString& stage) {
    auto* transfer = new Sc750SourceTransfer(m_workspace);
    auto* progress = new TransferDialog(title, tr("bytes"), [transfer] { transfer->cancel(); }, &m_workspace.window());
    progress->setStage(stage);
    connect(transfer, &Sc750SourceTransfer::progress, progress, &TransferDialog::showProgress);
    connect(transfer, &Sc750SourceTransfer::finished, progress,
            [progress, transfer](bool ok, const QByteArray&, const QString& message) {
                using Outcome = TransferDialog::Outcome;
                progress->finish(ok ? Outcome::Done : transfer->isCancelled() ? Outcome::Cancelled : Outcome::Failed,
                                 message);
            });
    return transfer;
}

void Sc750ControllerMenu::downloadSource() {
    const QByteArray text = m_workspace.window().editor()->text().toUtf8();
    Sc750SourceTransfer* transfer = startTransfer(tr("Download Source File"), tr("Writing the source file to the SC750..."));
    connect(transfer, &Sc750SourceTransfer::finished, this, [this](bool ok, const QByteArray&, const QString& message) {
        emit m_workspace.message(ok ? message : tr("Download Source File: %1").arg(message));
    });
    transfer->download(text);
}

void Sc750ControllerMenu::uploadSource() {
    Sc750SourceTransfer* transfer = startTransfer(tr("Upload Source File"), tr("Reading the source file stored in the SC750..."));
    connect(transfer, &Sc750SourceTransfer::finished, this,
            [this](bool ok, const QByteArray& bytes, const QString& message) {
                if (!ok) {
                    emit m_workspace.message(tr("Upload Source File: %1").arg(message));
                    return;
                }
                // Into a new tab: the program in the editor is not overwritten.
                EditorTabs* tabs = m_workspace.window().editorArea()->tabs();
                editor::ProgramEditor* editor = tabs->addEditor(tabs->freeUntitledName(FileType::Sc750Program));
                editor->setText(QString::fromUtf8(bytes));
                tabs->refreshTab(editor);
                emit m_workspace.message(tr("%1: %2 bytes").arg(message).arg(bytes.size()));
            });
    transfer->upload();
}

QWidget* Sc750ControllerMenu::controllerSetUp() {
    auto* dialog = new Sc750SetupDialog(m_workspace, &m_workspace.window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

QWidget* Sc750ControllerMenu::editParameters() {
    auto* dialog = new Sc750SetupDialog(m_workspace, &m_workspace.window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Edit Parameters"));
    dialog->loadParams(m_workspace.window().editor()->text());
    dialog->open();
    return dialog;
}

QWidget* Sc750ControllerMenu::unconfigure() {
    auto* first = new QMessageBox(QMessageBox::Warning, tr("Unconfigure"),
                                  tr("Are you sure you want to unconfigure your controller?"),
                                  QMessageBox::Ok | QMessageBox::Cancel, &m_workspace.window());
    first->setAttribute(Qt::WA_DeleteOnClose);
    connect(first, &QMessageBox::buttonClicked, this, [this, first](QAbstractButton* button) {
        if (first->standardButton(button) != QMessageBox::Ok) return;
        // The second screen: the user types "Yes" (L2589-L2590).
        auto* dialog = new QDialog(&m_workspace.window());
        dialog->setObjectName(QStringLiteral("sc750UnconfigureDialog"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setWindowTitle(tr("Unconfigure"));
        auto* layout = new QVBoxLayout(dialog);
        layout->addWidget(new QLabel(tr("This erases the controller's configuration; it will show UC.\n"
                                        "Type Yes to unconfigure:")));
        auto* answer = new QLineEdit;
        layout->addWidget(answer);
        auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
        QPushButton* ok = buttons->button(QDialogButtonBox::Ok);
        ok->setEnabled(false);
        layout->addWidget(buttons);
        connect(answer, &QLineEdit::textChanged, ok, [ok](const QString& text) { ok->setEnabled(text == QLatin1String("Yes")); });
        connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
        connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
        connect(dialog, &QDialog::accepted, this, [this] {
            m_workspace.send('K', QStringLiteral("0"), [this](const serialport::Sc750Reply&) {
                emit m_workspace.message(tr("The controller is unconfigured (UC)"));
            });
        });
        dialog->open();
    });
    first->open();
    return first;
}

} // namespace app
