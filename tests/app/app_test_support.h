#pragma once
// What the app tests share: how long a drive may take to answer, and when the simulated BDS5 takes a line.
#include "families/bds5/drive_connection.h"
#include "app/main_window.h"
#include "serialport/bds5_session.h"

namespace app_test {

// Generous: a loaded machine has been seen to stall every process for 8 s at once (issue 23).
constexpr int kDriveTimeoutMs = 30000;

// The BDS5 session is idle at the interactive prompt.
inline bool driveReady(const app::MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready &&
           session->mode() == serialport::Bds5Mode::Interactive;
}

} // namespace app_test
