// RecoveryBar: the info bar over the editor tabs after a crash — "ServoDesk did not close normally ...
// [Restore] [Discard]". Non-modal: the IDE is usable while it is shown. GUI thread only.
#pragma once

#include "recovery_store.h"

#include <QFrame>

class QLabel;
class QPushButton;

namespace app {

class RecoveryBar final : public QFrame {
    Q_OBJECT
public:
    explicit RecoveryBar(QWidget* parent = nullptr);

    // Shows the bar listing buffers (hidden when there are none).
    void offer(const QList<RecoveredBuffer>& buffers);
    QString message() const;
    QPushButton* restoreButton() const { return m_restore; }
    QPushButton* discardButton() const { return m_discard; }

signals:
    void restoreRequested();
    void discardRequested();

private:
    QLabel* m_text;
    QPushButton* m_restore;
    QPushButton* m_discard;
};

} // namespace app
