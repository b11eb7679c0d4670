// SessionHost: a family's workspace, or the BDS5's connection.
#include "session_host.h"

#include "families/bds5/drive_connection.h"
#include "family_workspace.h"
#include "transfer_dialog.h"

#include <QCoreApplication>

namespace app {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("app::SessionHost", text);
}
} // namespace

SessionHost SessionHost::of(FamilyWorkspace& workspace) {
    return {workspace.family(), [&workspace] { return workspace.driveSession(); },
            [&workspace] { return workspace.busyReason(); }, tr("the controller is not connected")};
}

SessionHost SessionHost::of(DriveConnection& connection) {
    SessionHost host;
    host.family = drive_core::DriveFamily::Bds5;
    host.session = [&connection]() -> serialport::DriveSession* {
        return connection.isConnected() ? connection.driveSession() : nullptr;
    };
    host.busyReason = [&connection] {
        using Mode = serialport::Bds5Mode;
        if (TransferDialog::active()) return tr("a transfer is under way");
        const Mode mode = connection.session()->mode();
        if (mode == Mode::Running) return tr("the drive runs a program (no prompt)");
        if (mode != Mode::Interactive && mode != Mode::Monitor)
            return tr("the drive is at a %1 prompt").arg(serialport::modeName(mode));
        return QString();
    };
    host.notConnected = tr("the drive is not connected");
    return host;
}

} // namespace app
