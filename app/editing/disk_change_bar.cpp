// DiskChangeBar: layout and wording.
#include "disk_change_bar.h"

namespace app {

DiskChangeBar::DiskChangeBar(QWidget* parent)
    : InfoBar({QStringLiteral("diskChangeBar"), QStyle::SP_MessageBoxQuestion, QStringLiteral("#e8f0fe"),
               QStringLiteral("#a8c0e8")},
              tr("&Reload"), tr("&Keep My Edits"), parent) {
    reloadButton()->setToolTip(tr("Show the file as it is on disk now; Edit > Undo brings the tab's unsaved edits back"));
    keepButton()->setToolTip(tr("Leave the tab as it is; saving it writes it over the file on disk"));
    connect(reloadButton(), &QPushButton::clicked, this, &DiskChangeBar::reloadRequested);
    connect(keepButton(), &QPushButton::clicked, this, &DiskChangeBar::keepRequested);
}

void DiskChangeBar::ask(const QString& html, const QString& keepText) {
    keepButton()->setText(keepText);
    showMessage(html);
}

} // namespace app
