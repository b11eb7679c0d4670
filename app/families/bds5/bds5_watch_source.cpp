// The BDS5's watch: when its P polls may go.
#include "bds5_watch_source.h"

#include "drive_connection.h"
#include "transfer_dialog.h"

namespace app {

SessionWatchSource* makeBds5WatchSource(DriveConnection& connection, QObject* parent) {
    SessionWatchSource::Host host;
    host.family = drive_core::DriveFamily::Bds5;
    host.session = [&connection]() -> serialport::DriveSession* {
        return connection.isConnected() ? connection.driveSession() : nullptr;
    };
    host.busyReason = [&connection] {
        if (TransferDialog::active()) return SessionWatchSource::tr("a transfer is under way");
        if (connection.session()->mode() != serialport::Bds5Mode::Interactive)
            return SessionWatchSource::tr("the drive is not at an interactive prompt");
        return QString();
    };
    host.notConnected = SessionWatchSource::tr("the drive is not connected");
    return new SessionWatchSource(std::move(host), parent);
}

} // namespace app
