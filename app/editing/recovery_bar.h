// RecoveryBar: the info bar over the editor tabs after a crash — "ServoDesk did not close normally ...
// [Restore] [Discard]". Non-modal: the IDE is usable while it is shown. GUI thread only.
#pragma once

#include "recovery_store.h"

#include "info_bar.h"

#include <QPushButton>

namespace app {

class RecoveryBar final : public InfoBar {
    Q_OBJECT
public:
    explicit RecoveryBar(QWidget* parent = nullptr);

    // Shows the bar listing buffers (hidden when there are none).
    void offer(const QList<RecoveredBuffer>& buffers);
    QPushButton* restoreButton() const { return first(); }
    QPushButton* discardButton() const { return second(); }

signals:
    void restoreRequested();
    void discardRequested();
};

} // namespace app
