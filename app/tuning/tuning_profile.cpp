// The SC750's and the PMC-960's tuning on the wire. Choices are the manuals' procedures: the SC750 manual gives
// no procedure (§4.5 L2238-L2252 names the gains; DACMAP L2145-L2175 the test point), the PMC-960's §4.8
// (L571-L636) does — velocity loop in SM1, position loop in SM2, the tachometer signal on an oscilloscope.
#include "tuning_profile.h"

#include "drive_core/catalog/drive_catalog.h"
#include "drive_core/catalog/sc750_catalog.h"

#include <QRegularExpression>

namespace app {

namespace {
namespace cat = drive_core::catalog;

TuningGain catalogGain(drive_core::DriveFamily family, const QString& name, const char* parameter) {
    TuningGain g;
    g.name = name;
    g.parameter = QString::fromLatin1(parameter);
    if (const cat::Parameter* p = cat::findParameter(family, parameter)) {
        g.minimum = p->minimum;
        g.maximum = p->maximum;
        g.decimals = p->type == cat::ValueType::Decimal ? 3 : 0;
        g.unit = QString::fromUtf8(p->unit.data(), qsizetype(p->unit.size()));
        g.description = QString::fromUtf8(p->description.data(), qsizetype(p->description.size()));
    }
    return g;
}

TuningProfile sc750() {
    using drive_core::DriveFamily;
    TuningProfile p;
    p.family = DriveFamily::Sc750;
    for (const char* name : {"KVP", "KVI", "KPP", "KVFF", "ARF0", "ARF1", "ILC"})
        p.gains << catalogGain(DriveFamily::Sc750, QString::fromLatin1(name), name);
    // KVP is a fraction of an A per rad/s (0.087086 for the boiler-plate motor): it needs its digits.
    for (TuningGain& g : p.gains)
        if (g.name == QLatin1String("KVP")) g.decimals = 6;
    p.moves << TuningMove{QStringLiteral("Velocity step (GO.VEL)"),
                          {QStringLiteral("ACCEL.RATE=1000000"), QStringLiteral("DECEL.RATE=1000000"),
                           QStringLiteral("RUN.SPEED=%1"), QStringLiteral("GO.VEL")},
                          {QStringLiteral("ABORT.MOTION")},
                          QStringLiteral("RPM"),
                          200,
                          QStringLiteral("GO.VEL at RUN.SPEED with ACCEL.RATE and DECEL.RATE at their top "
                                         "(1,000,000 RPM/s), ABORT.MOTION after the hold. With KVFF at 100 the "
                                         "velocity loop (KVP, KVI, ARF0/ARF1) sees the step; at 0 the position "
                                         "loop (KPP) shapes it")};
    p.prepare = {QStringLiteral("DACMAP=1"), QStringLiteral("ENABLE=1")};
    p.prepareNote = QStringLiteral("The runs put the resolver velocity on the analog monitor (DACMAP=1, 1 V/kRPM) "
                                   "and enable the drive (ENABLE=1).");
    p.monitor = QStringLiteral("DACMON");
    p.command = QStringLiteral("VEL.CMD");
    p.watch = QStringLiteral("RVEL");
    p.watchUnit = QStringLiteral("RPM");
    p.gainsFilter = QStringLiteral("Parameter files (*.prm *.PRM);;All files (*)"); // its PARAMS block
    p.gainsFileName = QStringLiteral("gains.prm");
    for (const TuningGain& g : p.gains) p.readGains << g.parameter;
    // DECISIONS 56: a servo fault latches (FAULTCODE shows it) until ENABLE is written 0; prepare enables again.
    p.faultCheck = {QStringLiteral("FAULTCODE")};
    p.clearFault = {QStringLiteral("ENABLE=0")};
    return p;
}

TuningProfile pmc960() {
    using drive_core::DriveFamily;
    TuningProfile p;
    p.family = DriveFamily::Pmc960;
    const std::pair<const char*, const char*> gains[] = {{"VLGAIN", "TGV"}, {"VLCOMP", "TGB"}, {"PLGAIN", "TGP"},
                                                         {"PLCOMP", "TGE"}, {"FFGAIN", "TGF"}, {"TGAIN", "TGT"},
                                                         {"ALGAIN", "TGL"}};
    for (const auto& [name, parameter] : gains) p.gains << catalogGain(DriveFamily::Pmc960, QString::fromLatin1(name), parameter);
    // The manual's test motion is an index (4.8.1); a jog holds the speed for as long as the hold, so the
    // tach's plateau and the loop's settling are both in the picture. J41 = 4.1 kHz, one revolution a second
    // of a 4,096-count encoder in the 192 kHz range: the speed the manual suggests.
    p.moves << TuningMove{QStringLiteral("Velocity loop: jog in SM1 (4.8.1)"),
                          {QStringLiteral("SM1"), QStringLiteral("J%1+")},
                          {QStringLiteral("J*")},
                          QStringLiteral("\u00d7 100 Hz"),
                          41,
                          QStringLiteral("Velocity mode (SM1): the jog reaches the velocity loop through FFGAIN "
                                         "only (the manual sets TGF100 for this); raise VLGAIN until the tach "
                                         "overshoots, rise 3-15 ms")};
    p.moves << TuningMove{QStringLiteral("Position loop: jog in SM2 (4.8.3)"),
                          {QStringLiteral("SM2"), QStringLiteral("J%1+")},
                          {QStringLiteral("J*")},
                          QStringLiteral("\u00d7 100 Hz"),
                          41,
                          QStringLiteral("Position mode (SM2): raise PLGAIN until the tach overshoots (the manual "
                                         "turns FFGAIN off first, TGF0); rise under 30 ms")};
    p.prepareNote = QStringLiteral("The oscilloscope is on the tachometer signal after TGAIN (§4.8). Each gain is "
                                   "written with SW1 before and SW0 after it. The jog uses the present A.");
    p.monitor = QStringLiteral("tach");
    p.command = QStringLiteral("velocity command");
    p.watch = QStringLiteral("V");
    p.watchUnit = QStringLiteral("V units");
    p.gainsFilter = QStringLiteral("MPL parameter files (*.mpl *.MPL);;All files (*)"); // T-table lines, SW1 ... SW0
    p.gainsFileName = QStringLiteral("gains.mpl");
    p.readGains = {QStringLiteral("TG?")};
    // The following-error trip returns the drive to IDLE (L223) with #E1, cleared by SM0 then SM1 or SM2
    // (L2382): every move starts with its SM, so SM0 is all a next run needs first.
    p.faultCheck = {QStringLiteral("SM!"), QStringLiteral("SE?")};
    p.clearFault = {QStringLiteral("SM0")};
    return p;
}
} // namespace

const TuningGain* TuningProfile::gain(const QString& name) const {
    for (const TuningGain& g : gains)
        if (g.name == name) return &g;
    return nullptr;
}

QStringList TuningProfile::writeGain(const QString& name, double value) const {
    const TuningGain* g = gain(name);
    if (!g) return {};
    const QString number = QString::number(value, 'f', g->decimals);
    if (family == drive_core::DriveFamily::Pmc960) {
        // TGE and TGB are shown and typed in hex (L1741-1773).
        const bool hex = g->parameter == QLatin1String("TGE") || g->parameter == QLatin1String("TGB");
        const QString digits = hex ? QString::number(qRound(value), 16).toUpper() : QString::number(qRound(value));
        return {QStringLiteral("SW1"), g->parameter + digits, QStringLiteral("SW0")};
    }
    return {g->parameter + QLatin1Char('=') + number};
}

QMap<QString, double> TuningProfile::parseGains(const QList<serialport::LineAnswer>& answers) const {
    QMap<QString, double> out;
    if (family == drive_core::DriveFamily::Pmc960) {
        // "P-16 V-16 T-160 F-16 E-00 B-00 X-0 L-0": TG?'s letters, TGE and TGB in hex.
        static const QRegularExpression item(QStringLiteral("\\b([PVTFEBXL])-([0-9A-Fa-f]+)"));
        for (const serialport::LineAnswer& a : answers)
            for (const QString& line : a.lines)
                for (auto m = item.globalMatch(line); m.hasNext();) {
                    const auto match = m.next();
                    const QString parameter = QStringLiteral("TG") + match.captured(1);
                    const bool hex = parameter == QLatin1String("TGE") || parameter == QLatin1String("TGB");
                    bool ok = false;
                    const int value = match.captured(2).toInt(&ok, hex ? 16 : 10);
                    if (!ok) continue;
                    for (const TuningGain& g : gains)
                        if (g.parameter == parameter) out.insert(g.name, value);
                }
        return out;
    }
    for (int i = 0; i < answers.size() && i < gains.size(); ++i) {
        bool ok = false;
        const double value = answers[i].lines.value(0).trimmed().toDouble(&ok);
        if (ok && answers[i].ok()) out.insert(gains[i].name, value);
    }
    return out;
}

QString TuningProfile::faultIn(const QList<serialport::LineAnswer>& answers) const {
    const auto text = [this](int code) {
        const cat::ErrorEntry* e = cat::findError(family, code);
        if (!e) return QString::number(code);
        return QString::fromStdString(e->codeText) + QLatin1Char(' ') +
               QString::fromUtf8(e->message.data(), qsizetype(e->message.size()));
    };
    const auto lastWord = [&answers](int i) {
        return answers.value(i).lines.join(QLatin1Char(' ')).trimmed().section(QLatin1Char(' '), -1);
    };
    if (family == drive_core::DriveFamily::Pmc960) {
        // Every move puts the drive in SM1 or SM2; IDLE after it means the drive stopped itself.
        bool ok = false;
        const int mode = lastWord(0).toInt(&ok);
        if (!ok || mode != 0) return {};
        const int code = lastWord(1).toInt(&ok, 16);
        return ok && code != 0 ? text(code) : QStringLiteral("the drive went to IDLE (SM0)");
    }
    bool ok = false;
    const int code = lastWord(0).toInt(&ok);
    if (!ok || code == cat::sc750::kFaultNone || code == cat::sc750::kFaultEnabled) return {};
    return text(code);
}

QStringList TuningProfile::lines(const QStringList& pattern, int amplitude) const {
    QStringList out;
    for (const QString& line : pattern) out << (line.contains(QLatin1String("%1")) ? line.arg(amplitude) : line);
    return out;
}

std::optional<TuningProfile> tuningProfile(drive_core::DriveFamily family) {
    switch (family) {
    case drive_core::DriveFamily::Sc750: return sc750();
    case drive_core::DriveFamily::Pmc960: return pmc960();
    case drive_core::DriveFamily::Bds5: break;
    }
    return std::nullopt;
}

} // namespace app
