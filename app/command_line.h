// The servodesk command line: [FILE...] --screenshot-tour DIR, --port PATH, --baud N, --drive F, --help,
// --version.
#pragma once

#include "connection_choice.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace app {

struct LaunchOptions {
    QString screenshotTourDir; // empty: no tour
    ConnectionChoice connection = ConnectionChoice::simulator();
    QStringList files; // to open, each in its own tab (a file manager's double-click: Exec=servodesk %F)
};

// Parses arguments (argv as QStrings). --help and --version print and exit the process, as
// QCommandLineParser does; a bad value prints the reason to stderr and gives nullopt.
std::optional<LaunchOptions> parseCommandLine(const QStringList& arguments);

} // namespace app
