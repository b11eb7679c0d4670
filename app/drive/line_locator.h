// LineLocator: finds the editor line a program line shown by the drive came from. The drive shows its
// copy of the line (single-step, trace), which may have lost its comment or indentation on the way.
// Pure functions over the editor's lines (0-based).
#pragma once

#include <QString>
#include <QStringList>

namespace app {

class LineLocator {
public:
    // The line to compare: comment (" ;...") removed outside strings, runs of blanks made one, upper case.
    // keepIndent keeps the leading blanks as they are (the drive shows the line as it stored it).
    static QString normalized(const QString& line, bool keepIndent = false);

    // The first line after `after` whose text matches driveText, wrapping round to the top (chosen: the
    // drive runs on from the last line shown, so the next occurrence is the likeliest). A match with the
    // same indentation wins over one without (the manual's 55$: "ENDIF" is the outer ENDIF, not
    // "  ENDIF"), so a drive that kept the indentation is followed exactly. -1 if none.
    static int find(const QStringList& lines, const QString& driveText, int after);

    // The line of label n ("55$"), or -1.
    static int labelLine(const QStringList& lines, int label);
};

} // namespace app
