// Sc750ControllerMenu: Motion Dialogue's Options and File items that belong to the SC750 (seed-sc750 §2.4,
// §2.7): Create Program with the parameter header, Axis Selection, Download BIN File, Download and Upload
// Source File, Controller Set Up and Unconfigure (two confirmations, typing "Yes", L2580-L2591). Port Configuration is Drive > Connect.
// Dialogs open without blocking. GUI thread only.
#pragma once

#include <QMenu>

namespace app {

class Sc750SourceTransfer;
class Sc750Workspace;

class Sc750ControllerMenu final : public QMenu {
    Q_OBJECT
public:
    Sc750ControllerMenu(Sc750Workspace& workspace, QWidget* parent);

    // The boiler-plate a new program starts with (L944-L982): the PARAMS block from the catalog's
    // parameters and defaults, the section comments, END.
    static QString boilerplate();
    // File > Create Program: a new .bas tab holding the boiler-plate.
    void createProgram();
    // File > Edit Parameters (listed, never described, L331; our design): the set-up dialog in Manual
    // mode holding the current program's PARAMS values.
    QWidget* editParameters();
    // Options > Unconfigure: asks twice (the second time the user types "Yes"), then K0.
    QWidget* unconfigure();
    // Options > Controller Set Up: the set-up dialog (Auto or Manual), then PARAMS, values and K1.
    QWidget* controllerSetUp();

    // Options > Download / Upload Source File: the editor's text into the controller's NV memory, and
    // the stored text back into a new tab.
    void downloadSource();
    void uploadSource();

private:
    void selectAxis();
    void downloadBinFile();
    // The transfer, followed by a TransferDialog titled title that says stage.
    Sc750SourceTransfer* startTransfer(const QString& title, const QString& stage);

    Sc750Workspace& m_workspace;
};

} // namespace app
