// TransferDialog: the non-modal progress window of a program or variable transfer — what it is doing,
// a bar in lines, Cancel. On success it closes itself; otherwise it stays with the result (what happened
// and what the drive holds) until closed. Only one transfer runs at a time: active() says which.
// GUI thread only.
#pragma once

#include "serialport/bds5_transfer.h"

#include <QDialog>
#include <QPointer>

class QDialogButtonBox;
class QLabel;
class QProgressBar;

namespace app {

class TransferDialog final : public QDialog {
    Q_OBJECT
public:
    // Shows itself (non-modal) and follows transfer, which it takes over (deleted with the dialog).
    TransferDialog(const QString& title, serialport::Bds5Transfer* transfer, QWidget* parent);
    ~TransferDialog() override;

    // The dialog of the transfer in progress, if any.
    static TransferDialog* active();

    QString stageText() const;
    QString resultText() const;
    bool isFinished() const { return m_finished; }
    void reject() override;

private:
    void onProgress(int done, int total);
    void onFinished(const serialport::Bds5TransferResult& result);

    serialport::Bds5Transfer* m_transfer;
    QLabel* m_stage;
    QProgressBar* m_bar;
    QLabel* m_result;
    QDialogButtonBox* m_buttons;
    bool m_finished = false;
};

} // namespace app
