// Pmc960ErrorText: #xx codes with the catalog's words, a severity and a hint.
#include "pmc960_error_text.h"

#include "drive_core/catalog/pmc960_catalog.h"

namespace app {

namespace cat = drive_core::catalog::pmc960;
using Level = ErrorLogModel::Level;

namespace {
QString text(std::string_view view) {
    return QString::fromUtf8(view.data(), qsizetype(view.size()));
}

// ESC and BREAK codes are the user's (or the machine's) own stop, not a mistake in the command.
bool isAbort(const cat::ErrorInfo& info) {
    const QString message = text(info.message);
    return message.contains(QLatin1String("ESC")) || message.contains(QLatin1String("Break")) ||
           message.contains(QLatin1String("BREAK"));
}
} // namespace

QString Pmc960ErrorText::codeText(int code) {
    return QStringLiteral("#%1").arg(code, 2, 16, QLatin1Char('0')).toUpper();
}

QString Pmc960ErrorText::hint(int code) {
    switch (code) {
    case 0x83:
        return tr("Reduce the change in velocity, increase the acceleration or lower the current speed (L2301).");
    case 0x86: return tr("Use a smaller change in velocity or make it over a longer distance (L2304).");
    case 0x8B: return tr("Give the Cam command a non-zero start speed.");
    case 0x90:
    case 0x91:
    case 0x92:
    case 0x93:
    case 0x97: return tr("Enter a value within the command's range (Help: the command's page lists it).");
    case 0x94:
        return tr("Enter a speed within the velocity range; after changing the range (TUV, TUS), enter the speed again "
                  "(L2320).");
    case 0x95: return tr("Enter 0 or 1.");
    case 0x96: return tr("Name an input bank the controller has (a hex digit for a muxed bank).");
    case 0x98: return tr("Enter a higher speed, or choose a lower velocity range (TUV).");
    case 0x99: return tr("Use a smaller position or distance, or coarser position units.");
    case 0x9A: return tr("Leave the bank out, or enable muxed inputs first (THM).");
    case 0x9B: return tr("Enter a home location below the resolver size set with THA.");
    case 0x9C: return tr("Use a smaller feedforward gain: it overflows in another velocity range.");
    case 0xA1:
        return tr("Check the command's letters: MPL commands are one or two upper-case letters (Help lists them).");
    case 0xA2: return tr("End the command with a carriage return or one of its display characters (? ! % &).");
    case 0xAA: return tr("Write the number with one ':' at most.");
    case 0xB1: return tr("Make SD larger than the deceleration distance plus the following error.");
    case 0xB2: return tr("Wait until the motion has stopped (or the FPS state ended), then send the command again.");
    case 0xB3: return tr("Unassert ESTOP' and try again (L2348).");
    case 0xB6: return tr("Enable the servodrive first: SM1 or SM2 (L2351).");
    case 0xB8: return tr("Move in reverse, off the forward limit (+LIMIT').");
    case 0xB9: return tr("Move forward, off the reverse limit (-LIMIT').");
    case 0xC1: return tr("Shorten the program: the program buffer is full.");
    case 0xC2: return tr("Define the label (@<label>) the command looks for, or correct its name.");
    case 0xC3: return tr("Enter the program again; if the fault comes back, the ZeroPower RAM is failing.");
    case 0xC5: return tr("Use a label character between \" and z.");
    case 0xC6: return tr("Stop the program first (ESC, MPL > Stop), then edit it.");
    case 0xC8: return tr("Use loop counter X, Y or Z.");
    case 0xD3: return tr("Write-enable the table and program buffer first (SW).");
    case 0xD4: return tr("Keep TUS times TUV below 384000.");
    case 0xD8: return tr("Send contour segments sooner, before the running segment ends.");
    case 0xE0: return tr("Motion stopped: release ESTOP', then enable again with SM1 or SM2 before moving.");
    case 0xE1: return tr("Clear the overflow with SM0, then SM1 or SM2 (L2382).");
    case 0xE2: return tr("Check that the servodrive is powered and ready (DRVRDY'), then SM1 or SM2 again.");
    case 0xE3: return tr("Clear the fault the FAULT input reports, then enable again with SM1 or SM2.");
    default: break;
    }
    const cat::ErrorInfo* info = cat::findError(code);
    if (!info) return tr("Not in the PMC-960's error list.");
    if (isAbort(*info)) return tr("Stopped on request: send the command again if it was not meant.");
    return text(info->meaning);
}

ErrorLogModel::Entry Pmc960ErrorText::entry(int code, const QString& detail) {
    ErrorLogModel::Entry e;
    e.family = drive_core::DriveFamily::Pmc960;
    e.code = code;
    e.codeText = codeText(code);
    e.detail = detail;
    e.hint = hint(code);
    const cat::ErrorInfo* info = cat::findError(code);
    if (!info) {
        e.message = tr("Unknown error code");
        e.severity = tr("Error");
        return e;
    }
    e.message = text(info->message);
    e.explanation = QStringLiteral("%1 (%2)").arg(text(info->meaning), text(info->manualLines));
    // Every error ends the command and the mode it was in (L2288); the word says why.
    if (info->group == cat::ErrorGroup::SystemStatus) {
        e.severity = tr("System");
        e.level = Level::Fault;
    } else if (code == 0xC3) {
        e.severity = tr("Hardware");
        e.level = Level::Firmware;
    } else if (isAbort(*info)) {
        e.severity = tr("Aborted");
        e.level = Level::Warning;
    } else {
        e.severity = tr("Refused");
        e.level = Level::Error;
    }
    return e;
}

} // namespace app
