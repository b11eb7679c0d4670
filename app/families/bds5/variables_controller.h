// VariablesController: Motion Link's Variables menu — New, From Disk, From Drive (DUMP), Send to Drive (one
// NAME value per prompt, each refusal marked at its line), View and Reset to STANDARD.VAR (the factory set
// generated from the catalog). GUI thread only.
#pragma once

#include "serialport/bds5_transfer.h"

#include <QObject>

class QMenu;

namespace editor {
class ProgramEditor;
}

namespace app {

class MainWindow;

class VariablesController final : public QObject {
    Q_OBJECT
public:
    explicit VariablesController(MainWindow& window);

    QMenu* menu() const { return m_menu; }

    void newVariables();
    void openFromDisk();
    void fromDrive();
    void sendToDrive();
    void viewStandard();
    // Asks first (non-modal), then sends STANDARD.VAR.
    void resetToStandard();
    // Sends STANDARD.VAR without asking.
    void sendStandard();

signals:
    void transferFinished(const serialport::Bds5TransferResult& result); // after the result is shown

private:
    void send(const QString& text, editor::ProgramEditor* markIn, const QString& fileName,
              const QString& title);

    MainWindow& m_window;
    QMenu* m_menu;
};

} // namespace app
