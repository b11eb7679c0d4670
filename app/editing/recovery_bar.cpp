// RecoveryBar: layout and wording.
#include "recovery_bar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QStyle>

namespace app {

RecoveryBar::RecoveryBar(QWidget* parent)
    : QFrame(parent), m_text(new QLabel(this)), m_restore(new QPushButton(tr("&Restore"), this)),
      m_discard(new QPushButton(tr("&Discard"), this)) {
    setObjectName(QStringLiteral("recoveryBar"));
    setStyleSheet(QStringLiteral("#recoveryBar { background: #fff4ce; border-bottom: 1px solid #e0c56e; }"));
    m_text->setObjectName(QStringLiteral("recoveryMessage"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::RichText);
    m_restore->setObjectName(QStringLiteral("recoveryRestore"));
    m_discard->setObjectName(QStringLiteral("recoveryDiscard"));
    m_restore->setToolTip(tr("Open the unsaved text in tabs, marked as modified"));
    m_discard->setToolTip(tr("Delete the unsaved text for good"));

    auto* icon = new QLabel(this);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(24, 24));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 10, 6);
    layout->addWidget(icon);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_restore);
    layout->addWidget(m_discard);
    connect(m_restore, &QPushButton::clicked, this, &RecoveryBar::restoreRequested);
    connect(m_discard, &QPushButton::clicked, this, &RecoveryBar::discardRequested);
    hide();
}

void RecoveryBar::offer(const QList<RecoveredBuffer>& buffers) {
    if (buffers.isEmpty()) {
        hide();
        return;
    }
    QStringList names;
    for (const RecoveredBuffer& buffer : buffers) {
        const QString when = QLocale().toString(buffer.savedAt.toLocalTime(), QLocale::ShortFormat);
        names << tr("<b>%1</b> (%2)").arg(buffer.displayName.toHtmlEscaped(), when);
    }
    m_text->setText(tr("ServoDesk did not close normally. The unsaved text of %1 can be restored.")
                        .arg(names.join(QStringLiteral(", "))));
    show();
}

QString RecoveryBar::message() const {
    return m_text->text();
}

} // namespace app
