// RecoveryBar: layout and wording.
#include "recovery_bar.h"

#include <QLocale>

namespace app {

RecoveryBar::RecoveryBar(QWidget* parent)
    : InfoBar({QStringLiteral("recoveryBar"), QStyle::SP_MessageBoxWarning, QStringLiteral("#fff4ce"),
               QStringLiteral("#e0c56e")},
              tr("&Restore"), tr("&Discard"), parent) {
    restoreButton()->setToolTip(tr("Open the unsaved text in tabs, marked as modified"));
    discardButton()->setToolTip(tr("Delete the unsaved text for good"));
    connect(restoreButton(), &QPushButton::clicked, this, &RecoveryBar::restoreRequested);
    connect(discardButton(), &QPushButton::clicked, this, &RecoveryBar::discardRequested);
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
    showMessage(tr("ServoDesk did not close normally. The unsaved text of %1 can be restored.")
                    .arg(names.join(QStringLiteral(", "))));
}

} // namespace app
