// DiskChangeBar: the info bar over the editor tabs when a file open in a tab changed on disk and the tab
// holds unsaved edits (or the new file cannot be shown) — "MOTION.BDS changed on disk ... [Reload] [Keep My
// Edits]". Non-modal: the IDE stays usable while it waits for an answer. GUI thread only.
#pragma once

#include "info_bar.h"

#include <QPushButton>

namespace app {

class DiskChangeBar final : public InfoBar {
    Q_OBJECT
public:
    explicit DiskChangeBar(QWidget* parent = nullptr);

    // Shows the bar with html as its question; keepText labels the button that leaves the editor as it is.
    void ask(const QString& html, const QString& keepText);
    QPushButton* reloadButton() const { return first(); }
    QPushButton* keepButton() const { return second(); }

signals:
    void reloadRequested();
    void keepRequested();
};

} // namespace app
