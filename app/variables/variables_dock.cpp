// VariablesDock: a dock around the browser.
#include "variables_dock.h"

#include "session_host.h"
#include "variable_browser.h"

namespace app {

VariablesDock::VariablesDock(DriveConnection& connection, QWidget* parent)
    : QDockWidget(tr("Variables"), parent), m_browser(new VariableBrowser(SessionHost::of(connection), this)) {
    setObjectName(QStringLiteral("variablesDock"));
    setWidget(m_browser);
}

} // namespace app
