// TransferDialog: the one non-modal progress window of every family's program and variable transfers
// (issue 17) — what it is doing, a bar in lines or bytes, Cancel. On success it closes itself; otherwise it
// stays with the result (what happened and what the drive holds) until closed. Only one transfer runs at a
// time: active() says which. A family's transfer reports through setStage(), showProgress() and finish();
// the BDS5's Bds5Transfer is wired by its own constructor. GUI thread only.
#pragma once

#include <QDialog>
#include <QPointer>

#include <functional>

class QDialogButtonBox;
class QLabel;
class QProgressBar;

namespace serialport {
class Bds5Transfer;
}

namespace app {

class TransferDialog final : public QDialog {
    Q_OBJECT
public:
    enum class Outcome { Done, Cancelled, Refused, Mismatch, Failed };

    // Shows itself (non-modal). unit names what the bar counts ("lines", "bytes"); cancel asks the transfer
    // to stop, once: the dialog then waits for finish(), which the transfer reports when the drive is safe.
    TransferDialog(const QString& title, const QString& unit, std::function<void()> cancel, QWidget* parent);
    // Follows a BDS5 transfer, which it takes over (deleted with the dialog).
    TransferDialog(const QString& title, serialport::Bds5Transfer* transfer, QWidget* parent);
    ~TransferDialog() override;

    // The dialog of the transfer in progress, if any.
    static TransferDialog* active();

    QString stageText() const;
    QString resultText() const;
    int progressValue() const; // lines or bytes done so far
    bool isFinished() const { return m_finished; }

    void setStage(const QString& text);
    void showProgress(qint64 done, qint64 total); // total 0: a length only the drive knows
    // Done closes the dialog; any other outcome stays with summary until the user closes it.
    void finish(Outcome outcome, const QString& summary);
    void reject() override;

private:
    std::function<void()> m_cancel;
    QString m_unit;
    QLabel* m_stage;
    QProgressBar* m_bar;
    QLabel* m_result;
    QDialogButtonBox* m_buttons;
    bool m_cancelling = false;
    bool m_finished = false;
};

} // namespace app
