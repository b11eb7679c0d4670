// TransferDialog: progress, cancel, result.
#include "transfer_dialog.h"

#include "serialport/bds5_transfer.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace app {

namespace {
QPointer<TransferDialog> s_active;
constexpr int kMinimumWidth = 460;
} // namespace

TransferDialog::TransferDialog(const QString& title, const QString& unit, std::function<void()> cancel,
                               QWidget* parent)
    : QDialog(parent), m_cancel(std::move(cancel)), m_unit(unit), m_stage(new QLabel(this)),
      m_bar(new QProgressBar(this)), m_result(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Cancel, this)) {
    setObjectName(QStringLiteral("transferDialog"));
    setWindowTitle(title);
    setAttribute(Qt::WA_DeleteOnClose);
    setWindowModality(Qt::NonModal);
    setMinimumWidth(kMinimumWidth);
    m_stage->setText(tr("Waiting for the drive..."));
    m_stage->setWordWrap(true);
    m_bar->setRange(0, 0);
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_result->hide();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_stage);
    layout->addWidget(m_bar);
    layout->addWidget(m_result);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &TransferDialog::reject);
    s_active = this;
    show();
}

TransferDialog::TransferDialog(const QString& title, serialport::Bds5Transfer* transfer, QWidget* parent)
    : TransferDialog(title, tr("lines"), [transfer] { transfer->cancel(); }, parent) {
    transfer->setParent(this);
    setStage(tr("Waiting for the drive's prompt..."));
    connect(transfer, &serialport::Bds5Transfer::stageChanged, this, &TransferDialog::setStage);
    connect(transfer, &serialport::Bds5Transfer::progress, this,
            [this](int done, int total) { showProgress(done, total); });
    connect(transfer, &serialport::Bds5Transfer::finished, this, [this](const serialport::Bds5TransferResult& r) {
        using Status = serialport::Bds5TransferResult::Status;
        finish(r.ok()                           ? Outcome::Done
               : r.status == Status::Cancelled ? Outcome::Cancelled
               : r.status == Status::Refused   ? Outcome::Refused
               : r.status == Status::Mismatch  ? Outcome::Mismatch
                                               : Outcome::Failed,
               r.summary);
    });
}

TransferDialog::~TransferDialog() = default;

TransferDialog* TransferDialog::active() {
    return s_active && !s_active->isFinished() ? s_active.data() : nullptr;
}

QString TransferDialog::stageText() const {
    return m_stage->text();
}

QString TransferDialog::resultText() const {
    return m_result->text();
}

int TransferDialog::progressValue() const {
    return m_bar->value();
}

void TransferDialog::setStage(const QString& text) {
    if (!m_finished) m_stage->setText(text);
}

void TransferDialog::reject() {
    // Cancel, Esc and the window's close button all cancel first; the dialog goes once the drive is safe.
    if (m_finished) return QDialog::reject();
    if (m_cancelling) return;
    m_cancelling = true;
    m_stage->setText(tr("Cancelling: waiting for the drive..."));
    if (QPushButton* cancel = m_buttons->button(QDialogButtonBox::Cancel)) cancel->setEnabled(false);
    if (m_cancel) m_cancel();
}

void TransferDialog::showProgress(qint64 done, qint64 total) {
    // total 0: a listing whose length only the drive knows; the bar runs and the label counts.
    if (total <= 0) {
        m_bar->setRange(0, 0);
        m_bar->setFormat(tr("%1 %2").arg(done).arg(m_unit));
    } else {
        m_bar->setRange(0, int(total));
        m_bar->setFormat(tr("%v of %m %1").arg(m_unit));
    }
    m_bar->setValue(int(done));
}

void TransferDialog::finish(Outcome outcome, const QString& summary) {
    if (m_finished) return;
    m_finished = true;
    if (outcome == Outcome::Done) {
        close();
        return;
    }
    m_stage->setText(outcome == Outcome::Cancelled  ? tr("Cancelled")
                     : outcome == Outcome::Refused  ? tr("Refused by the drive")
                     : outcome == Outcome::Mismatch ? tr("Verify failed")
                                                    : tr("Failed"));
    if (m_bar->maximum() == 0) m_bar->setRange(0, 1);
    m_result->setText(summary);
    m_result->show();
    m_buttons->setStandardButtons(QDialogButtonBox::Close);
    adjustSize();
}

} // namespace app
