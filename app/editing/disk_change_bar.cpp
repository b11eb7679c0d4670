// DiskChangeBar: layout and wording.
#include "disk_change_bar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>

namespace app {

DiskChangeBar::DiskChangeBar(QWidget* parent)
    : QFrame(parent), m_text(new QLabel(this)), m_reload(new QPushButton(tr("&Reload"), this)),
      m_keep(new QPushButton(tr("&Keep My Edits"), this)) {
    setObjectName(QStringLiteral("diskChangeBar"));
    setStyleSheet(QStringLiteral("#diskChangeBar { background: #e8f0fe; border-bottom: 1px solid #a8c0e8; }"));
    m_text->setObjectName(QStringLiteral("diskChangeMessage"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::RichText);
    m_reload->setObjectName(QStringLiteral("diskChangeReload"));
    m_keep->setObjectName(QStringLiteral("diskChangeKeep"));
    m_reload->setToolTip(tr("Show the file as it is on disk now; the tab's unsaved edits are discarded"));
    m_keep->setToolTip(tr("Leave the tab as it is; saving it writes it over the file on disk"));

    auto* icon = new QLabel(this);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxQuestion).pixmap(24, 24));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 10, 6);
    layout->addWidget(icon);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_reload);
    layout->addWidget(m_keep);
    connect(m_reload, &QPushButton::clicked, this, &DiskChangeBar::reloadRequested);
    connect(m_keep, &QPushButton::clicked, this, &DiskChangeBar::keepRequested);
    hide();
}

void DiskChangeBar::ask(const QString& html, const QString& keepText) {
    m_text->setText(html);
    m_keep->setText(keepText);
    show();
}

QString DiskChangeBar::message() const {
    return m_text->text();
}

} // namespace app
