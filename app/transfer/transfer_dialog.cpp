// TransferDialog: progress, cancel, result.
#include "transfer_dialog.h"

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

TransferDialog::TransferDialog(const QString& title, serialport::Bds5Transfer* transfer, QWidget* parent)
    : QDialog(parent), m_transfer(transfer), m_stage(new QLabel(this)), m_bar(new QProgressBar(this)),
      m_result(new QLabel(this)), m_buttons(new QDialogButtonBox(QDialogButtonBox::Cancel, this)) {
    setObjectName(QStringLiteral("transferDialog"));
    setWindowTitle(title);
    setAttribute(Qt::WA_DeleteOnClose);
    setWindowModality(Qt::NonModal);
    setMinimumWidth(kMinimumWidth);
    m_transfer->setParent(this);
    m_stage->setText(tr("Waiting for the drive's prompt..."));
    m_bar->setRange(0, 0);
    m_bar->setFormat(tr("%v of %m lines"));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_result->hide();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_stage);
    layout->addWidget(m_bar);
    layout->addWidget(m_result);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &TransferDialog::reject);
    connect(m_transfer, &serialport::Bds5Transfer::stageChanged, m_stage, &QLabel::setText);
    connect(m_transfer, &serialport::Bds5Transfer::progress, this, &TransferDialog::onProgress);
    connect(m_transfer, &serialport::Bds5Transfer::finished, this, &TransferDialog::onFinished);
    s_active = this;
    show();
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

void TransferDialog::reject() {
    // Cancel, Esc and the window's close button all cancel first; the dialog goes once the drive is safe.
    if (m_finished) return QDialog::reject();
    if (m_transfer->isCancelling()) return;
    m_transfer->cancel();
    m_stage->setText(tr("Cancelling: waiting for the drive's prompt..."));
    if (QPushButton* cancel = m_buttons->button(QDialogButtonBox::Cancel)) cancel->setEnabled(false);
}

void TransferDialog::onProgress(int done, int total) {
    // total 0: a listing whose length only the drive knows; the bar runs and the label counts.
    if (total <= 0) {
        m_bar->setRange(0, 0);
        m_bar->setFormat(tr("%1 lines").arg(done));
    } else {
        m_bar->setRange(0, total);
        m_bar->setFormat(tr("%v of %m lines"));
    }
    m_bar->setValue(done);
}

void TransferDialog::onFinished(const serialport::Bds5TransferResult& result) {
    m_finished = true;
    if (result.ok()) {
        close();
        return;
    }
    using Status = serialport::Bds5TransferResult::Status;
    m_stage->setText(result.status == Status::Cancelled  ? tr("Cancelled")
                     : result.status == Status::Refused  ? tr("Refused by the drive")
                     : result.status == Status::Mismatch ? tr("Verify failed")
                                                         : tr("Failed"));
    if (m_bar->maximum() == 0) m_bar->setRange(0, 1);
    m_result->setText(result.summary);
    m_result->show();
    m_buttons->setStandardButtons(QDialogButtonBox::Close);
    adjustSize();
}

} // namespace app
