// VariablesDock: the BDS5's Variables dock — the family-neutral VariableBrowser over the main window's
// connection. GUI thread.
#pragma once

#include <QDockWidget>

namespace app {

class DriveConnection;
class VariableBrowser;

class VariablesDock final : public QDockWidget {
    Q_OBJECT
public:
    explicit VariablesDock(DriveConnection& connection, QWidget* parent = nullptr);

    VariableBrowser* browser() const { return m_browser; }

private:
    VariableBrowser* m_browser;
};

} // namespace app
