// Sc750ErrorText: SC750 faults, run-time and compile errors with the catalog's words and our hints.
#include "sc750_error_text.h"

#include "drive_core/catalog/sc750_catalog.h"

#include <QRegularExpression>

namespace app {

namespace cat = drive_core::catalog::sc750;
using Level = ErrorLogModel::Level;

namespace {
QString text(std::string_view view) {
    return QString::fromLatin1(view.data(), qsizetype(view.size()));
}

// Memory and processor faults are the hardware's, not the program's or the machine's.
Level levelOf(int code) {
    if (Sc750ErrorText::isNoFault(code)) return Level::Info;
    if (code == 14 || code == 242 || code == 243) return Level::Firmware;
    if (code == cat::kFaultRunTime || code == cat::kFaultIncompatible) return Level::Error;
    return Level::Fault;
}
} // namespace

bool Sc750ErrorText::isNoFault(int faultCode) {
    return faultCode == cat::kFaultNone || faultCode == cat::kFaultEnabled;
}

QString Sc750ErrorText::faultHint(int faultCode) {
    switch (faultCode) {
    case 0: return tr("Set ENABLE = 1 and assert the ENABLE input (J53-4) to enable the amplifier (L1496-L1520).");
    case 1:
        return tr("The motor ran faster than the resolver allows: lower the commanded speed or the gains that "
                  "overshoot, check the resolver wiring.");
    case 2: return tr("Let the motor cool; check its load, duty cycle and thermostat wiring.");
    case 3:
        return tr("Let the controller cool; check its ventilation and the ambient temperature, lower the duty cycle.");
    case 4: return tr("The I\u00b7t protection tripped: lower the RMS current (accelerations, load, duty cycle).");
    case 5: return tr("Check the motor cable for a short between phases or to ground.");
    case 6: return tr("Check the control supply voltage.");
    case 7: return tr("Check the bus supply and the motor cable; a load that regenerates may need a shunt regulator.");
    case 8: return tr("No fault: the amplifier is enabled.");
    case 9:
        return tr(
            "The load returns more energy than the shunt regulator can take: lower DECEL.RATE or fit a larger shunt.");
    case 10: return tr("Check the bus supply voltage and the control supply.");
    case 11: return tr("Check the encoder's +5 V wiring and what it draws.");
    case 12: return tr("Check what the terminal +5 V powers and its wiring.");
    case 13: return tr("Check the control supply; if the fault stays, the power stage needs service.");
    case 14: return tr("Cycle the power; if the fault stays, the controller needs service.");
    case 241:
        return tr("The motor could not follow the profile: lower ACCEL.RATE, DECEL.RATE or the speed, check the load "
                  "and the velocity loop gains.");
    case 242:
        return tr("Download the program again (Compile > Run Program); if the fault comes back, the program memory is "
                  "failing.");
    case 243:
        return tr("Set the parameters again (Controller > Edit Parameters, Controller Set Up) and check them after a "
                  "power cycle.");
    case 244: return tr("The program stopped at the line shown: correct it and run again (Reset Program clears F 4).");
    case 245:
        return tr(
            "Check the PacLAN cabling and that every axis the program addresses is on the network (L2285, L2360).");
    case 246:
        return tr("The .BIN came from another Motion Dialogue version: compile the program with this one and download "
                  "it again (L1554, L1585).");
    default: return tr("Not in the SC750's fault table.");
    }
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
    ErrorLogModel::Entry e;
    e.family = drive_core::DriveFamily::Sc750;
    e.code = faultCode;
    e.level = levelOf(faultCode);
    e.severity = isNoFault(faultCode) ? tr("Status") : tr("Fault");
    e.hint = faultHint(faultCode);
    if (const cat::FaultInfo* info = cat::findFault(faultCode)) {
        e.codeText = text(info->display);
        // The SC752/753 words; the SC754-756 ones differ for a few codes and go in the tool tip.
        e.message = text(info->sc752.empty() ? info->sc754 : info->sc752);
        e.explanation = tr("FAULTCODE %1, display \"%2\" (%3)").arg(faultCode).arg(e.codeText, text(info->manualLines));
        if (info->sc754 != info->sc752)
            e.explanation +=
                QLatin1Char('\n') + tr("SC752/753: %1\nSC754/755/756: %2").arg(text(info->sc752), text(info->sc754));
    } else {
        e.codeText = QString::number(faultCode);
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
