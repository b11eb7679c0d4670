// Sc750ErrorText: SC750 faults, run-time and compile errors with the catalog's words and our hints.
#include "sc750_error_text.h"

#include "errors/catalog_error_entry.h"

#include "drive_core/catalog/sc750_catalog.h"

#include <QRegularExpression>

namespace app {

namespace cat = drive_core::catalog::sc750;
using Level = ErrorLogModel::Level;

namespace {
QString text(std::string_view view) {
    return QString::fromLatin1(view.data(), qsizetype(view.size()));
}
} // namespace

bool Sc750ErrorText::isNoFault(int faultCode) {
    return faultCode == cat::kFaultNone || faultCode == cat::kFaultEnabled;
}

QString Sc750ErrorText::faultHint(int faultCode) {
    return catalogErrorHint(drive_core::DriveFamily::Sc750, faultCode);
}

QString Sc750ErrorText::runTimeHint(const QString& message) {
    // The run-time errors the manual names (PacLAN, L2285 and L2360) and those a BASIC raises (digest §6.3).
    struct Hint {
        const char* prefix;
        const char* hint;
    };
    static const Hint kHints[] = {
        {"DIVISION BY ZERO", QT_TR_NOOP("Test the divisor before dividing (IF d <> 0 THEN ...).")},
        {"SUBSCRIPT OUT OF RANGE", QT_TR_NOOP("Keep the index within the bounds the array was DIMensioned with.")},
        {"OVERFLOW", QT_TR_NOOP("The value does not fit the variable: limit it, or use a FLOAT variable.")},
        {"VALUE OUT OF RANGE",
         QT_TR_NOOP("Keep the value within the variable's range (Help: the variable's page; the Variables window).")},
        {"STRING TOO LONG", QT_TR_NOOP("A string holds at most 255 characters: shorten it (LEFT$, MID$).")},
        {"RETURN WITHOUT GOSUB",
         QT_TR_NOOP(
             "A RETURN was reached that no GOSUB called: end the main program with END before its subroutines.")},
        {"OUT OF STACK SPACE",
         QT_TR_NOOP("GOSUBs nest too deep: a subroutine calls itself, or leaves with GOTO instead of RETURN.")},
        {"STACK OVERFLOW", QT_TR_NOOP("Expressions or calls nest too deep: split the expression or the recursion.")},
        {"AXIS", QT_TR_NOOP("Connect that axis to PacLAN or correct its address (L2285, L2360).")},
        {"LAN INDEX OUT OF RANGE", QT_TR_NOOP("LANINT and LANFLT indexes run from 1 to 32 (L2319).")},
        {"TIMER NUMBER OUT OF RANGE", QT_TR_NOOP("Timers are numbered 1 to 6.")},
        {"ILLEGAL FUNCTION CALL", QT_TR_NOOP("An argument is outside what the function accepts.")},
        {"END INTERRUPT", QT_TR_NOOP("END INTERRUPT ends an interrupt routine: reach it only from the INTERRUPT.")},
    };
    for (const Hint& h : kHints)
        if (message.startsWith(QLatin1String(h.prefix))) return tr(h.hint);
    return {};
}

ErrorLogModel::Entry Sc750ErrorText::fault(int faultCode) {
    ErrorLogModel::Entry e = catalogErrorEntry(drive_core::DriveFamily::Sc750, faultCode);
    e.hint = faultHint(faultCode);
    if (const cat::FaultInfo* info = cat::findFault(faultCode)) {
        // The SC752/753 words (the entry's message); the SC754-756 ones differ for a few codes: in the tool tip.
        e.explanation = tr("FAULTCODE %1, display \"%2\" (%3)").arg(faultCode).arg(e.codeText, text(info->manualLines));
        if (info->sc754 != info->sc752)
            e.explanation +=
                QLatin1Char('\n') + tr("SC752/753: %1\nSC754/755/756: %2").arg(text(info->sc752), text(info->sc754));
    } else {
        e.level = Level::Fault;
        e.severity = tr("Fault");
        e.message = tr("Unknown fault code %1").arg(faultCode);
    }
    return e;
}

ErrorLogModel::Entry Sc750ErrorText::runTimeError(int faultCode, int line, const QString& message) {
    ErrorLogModel::Entry e = fault(faultCode);
    static const QRegularExpression kLineSuffix(QStringLiteral("\\s*\\(line \\d+\\)\\s*$"));
    QString words = message;
    words.remove(kLineSuffix);
    if (!words.isEmpty()) e.message = words;
    e.severity = tr("Run-time error");
    e.level = Level::Error;
    e.programLine = line;
    const QString specific = runTimeHint(words);
    if (!specific.isEmpty()) e.hint = specific + QLatin1Char(' ') + e.hint;
    return e;
}

ErrorLogModel::Entry Sc750ErrorText::compileError(int line, int column, const QString& message) {
    ErrorLogModel::Entry e;
    e.family = drive_core::DriveFamily::Sc750;
    e.severity = tr("Compile");
    e.level = Level::Error;
    e.message = message;
    e.programLine = line;
    e.hint =
        tr("Correct line %1 at column %2 and compile again (Ctrl+F9): the compiler stops at the first error (L2644).")
            .arg(line)
            .arg(column);
    e.explanation = tr("Compile error, line %1 col %2").arg(line).arg(column);
    return e;
}

} // namespace app
