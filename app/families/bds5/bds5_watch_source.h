// The BDS5's values for the polled chart: the generic SessionWatchSource over the connection's
// Bds5DriveSession — one quiet "P VAR1 VAR2" a sample (no echo in the terminal), only at an interactive
// prompt: never while a program runs, a transfer (RECORD/PLAY, download) is under way, or the link is down.
// Any variable P prints can be watched, including those RECORD cannot take. GUI thread only.
#pragma once

#include "scope/session_watch_source.h"

namespace app {

class DriveConnection;

SessionWatchSource* makeBds5WatchSource(DriveConnection& connection, QObject* parent = nullptr);

} // namespace app
