// ReferenceTopics::introHtml: the introduction page of the help browser (Motion Link's INTRO HELP).
#include "reference_topics.h"

#include <QObject>

namespace app {

QString ReferenceTopics::introHtml() {
    return QObject::tr(
        "<h2>ServoDesk for the BDS5</h2>"
        "<p>ServoDesk does what Motion Link did for the Kollmorgen BDS5, on today's desktops. It talks to the "
        "drive over a serial port, or to the built-in simulated BDS5, which it opens by default.</p>"
        "<h3>The terminal</h3>"
        "<p>What you type goes to the drive, which echoes it: the terminal shows only what the drive sends. "
        "The prompt tells the mode: <code>--&gt;</code> interactive, <code>==&gt;</code> monitor, "
        "<code>s--&gt;</code> single-step, <code>e-&gt;</code> editor, <code>l-&gt;</code> program load; a "
        "running program has no prompt.</p>"
        "<table cellspacing=4>"
        "<tr><td><b>F3</b></td><td>the last command again (Up/Down walk through older ones)</td></tr>"
        "<tr><td><b>Ctrl+X</b></td><td>^X: stop motion and break the program, at once, in any mode</td></tr>"
        "<tr><td><b>Esc</b></td><td>a running program to monitor mode and back</td></tr>"
        "<tr><td><b>Ctrl+V</b></td><td>^V: start the program's VARIABLE$ task</td></tr>"
        "</table>"
        "<h3>Running and debugging</h3>"
        "<p>The <b>Drive</b> menu and toolbar run a label, break, stop motion, kill, enable and disable the "
        "drive. Turn on <b>Single-Step</b> (SS ON) and run: the line about to run is highlighted in the "
        "editor; <b>Step</b> runs it, <b>Continue</b> lets the program run on. <b>Trace</b> (TRC ON) "
        "highlights each line as the drive reports it.</p>"
        "<h3>Capture</h3>"
        "<p><b>Capture &gt; Start Capture</b> logs everything sent and received; view it, save it as "
        "<code>.CAP</code> (the drive's text, as Motion Link saved it) or open an old one.</p>"
        "<h3>Options</h3>"
        "<p>Port and baud rate (300\u201319200), the autobaud sequence, the multidrop axis, the drive "
        "password, colours and the editor's keys. <b>Cable Disconnect</b> closes the port safely; "
        "<b>Reconnect</b> opens it again.</p>"
        "<h3>This reference</h3>"
        "<p>Every command, variable and error of the BDS5, in the manual's words, with syntax, modes, units, "
        "limits and the manual lines. Type in the search box to filter; F1 in the editor opens the entry of "
        "the word under the cursor.</p>");
}

} // namespace app
