// Sc750ErrorText: SC750 fault codes (FAULTCODE and the front panel display, L1522-L1588), run-time errors
// (F 4 with the drive's message and line) and compile errors as error log rows, with what to do. The
// manual lists the codes but says little about remedies: the hints are written from the sections it does
// have (enable conditions L1496-L1520, PacLAN L2285/L2360, versions L1554) and otherwise from what a user
// of the drive would check first. Pure; no I/O.
#pragma once

#include "errors/error_log_model.h"

#include <QCoreApplication>

namespace app {

class Sc750ErrorText {
    Q_DECLARE_TR_FUNCTIONS(Sc750ErrorText)

public:
    // A fault the controller shows (FAULTCODE 1-14, 241-246); codes 0 and 8 are "no fault" rows.
    static ErrorLogModel::Entry fault(int faultCode);
    // A run-time error event: FAULTCODE (244), the line it stopped at, the drive's message
    // ("DIVISION BY ZERO (line 3)": the line suffix is dropped, it has a column of its own).
    static ErrorLogModel::Entry runTimeError(int faultCode, int line, const QString& text);
    // The compiler's first error (Compile Program, L2632-L2646).
    static ErrorLogModel::Entry compileError(int line, int column, const QString& message);
    // What to do about a fault code; for a run-time error, about its message too.
    static QString faultHint(int faultCode);
    static QString runTimeHint(const QString& message);
    // True for 0 and 8: the display's "no fault" states (L235).
    static bool isNoFault(int faultCode);
};

} // namespace app
