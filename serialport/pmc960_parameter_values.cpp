// The parameter table's display commands, reply parsing and checked writes.
#include "pmc960_parameter_values.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

namespace serialport {

namespace {
using drive_core::catalog::pmc960::NumberBase;

QString tr(const char* text) {
    return QCoreApplication::translate("serialport::Pmc960ParameterValues", text);
}

constexpr std::int64_t kFixedScale = 10000; // FixedPoint values are stored x 10000 ("5:7777" = 57777)

QString fixedText(std::int64_t value) {
    const std::int64_t fraction = value % kFixedScale;
    if (fraction == 0) return QString::number(value / kFixedScale);
    QString digits = QStringLiteral("%1").arg(fraction, 4, 10, QLatin1Char('0'));
    while (digits.endsWith(QLatin1Char('0'))) digits.chop(1);
    return QStringLiteral("%1:%2").arg(value / kFixedScale).arg(digits);
}

QString limitText(const Pmc960Parameter& p, std::int64_t v) {
    switch (p.base) {
    case NumberBase::Hex: return QStringLiteral("%1").arg(v, 2, 16, QLatin1Char('0')).toUpper();
    case NumberBase::Label: return v == 0 ? tr("none") : QString(QChar(char(v)));
    case NumberBase::FixedPoint: return fixedText(v);
    case NumberBase::Decimal: break;
    }
    return QString::number(v);
}
} // namespace

QString parameterName(const Pmc960Parameter& p) {
    return QString::fromLatin1(p.name.data(), qsizetype(p.name.size()));
}

QByteArray displayCommand(const Pmc960Parameter& p, char kind) {
    const QByteArray name(p.name.data(), qsizetype(p.name.size()));
    if (name == "SLF" || name == "SLR") return QByteArray("SL") + kind;
    const auto* command = drive_core::catalog::pmc960::findCommand(p.name);
    const unsigned wanted = kind == '?' ? drive_core::catalog::pmc960::kStored : drive_core::catalog::pmc960::kCurrent;
    if (!command || (command->displays & wanted) == 0) return {};
    return name + kind;
}

QString valueFromDisplay(const Pmc960Parameter& p, const QString& reply) {
    const QString text = reply.trimmed();
    const QString name = parameterName(p);
    if (name == QLatin1String("SLF") || name == QLatin1String("SLR")) { // "F0 R0"
        const QRegularExpression re(QStringLiteral("%1\\s*(-?\\d+)").arg(name.at(2)));
        const auto m = re.match(text);
        return m.hasMatch() ? m.captured(1) : text;
    }
    // T displays in decimal output label the item: "P-16", "I-=", "B-" (no label set).
    if (name.size() == 3 && name.startsWith(QLatin1Char('T')) && text.size() >= 2 && text.at(0) == name.at(2) &&
        text.at(1) == QLatin1Char('-'))
        return text.mid(2);
    return text;
}

bool isReadOnlyFromHost(const Pmc960Parameter& p) {
    static const QStringList kReadOnly{QStringLiteral("THB"), QStringLiteral("THC"), QStringLiteral("THI"),
                                       QStringLiteral("G"),   QStringLiteral("J"),   QStringLiteral("D"),
                                       QStringLiteral("SW")};
    return kReadOnly.contains(parameterName(p)) || displayCommand(p, '?').isEmpty();
}

QString rangeText(const Pmc960Parameter& p) {
    return QStringLiteral("%1 \u2013 %2").arg(limitText(p, p.minimum), limitText(p, p.maximum));
}

ParameterWrite parameterWrite(const Pmc960Parameter& p, const QString& input) {
    const QString text = input.trimmed();
    ParameterWrite w{{}, p.nonVolatile, {}};
    std::int64_t value = 0;
    bool ok = false;
    QByteArray digits;
    switch (p.base) {
    case NumberBase::Decimal:
        value = text.toLongLong(&ok);
        if (!ok) w.error = tr("%1 takes a whole number.").arg(parameterName(p));
        digits = QByteArray::number(qAbs(value));
        break;
    case NumberBase::Hex:
        value = text.toLongLong(&ok, 16);
        if (!ok) w.error = tr("%1 takes a hex number (00 \u2013 FF).").arg(parameterName(p));
        digits = QByteArray::number(value, 16).toUpper();
        break;
    case NumberBase::Label:
        ok = text.size() == 1 && text.at(0).unicode() < 0x80;
        if (!ok) w.error = tr("%1 takes one character.").arg(parameterName(p));
        else value = text.at(0).toUpper().unicode();
        digits = QByteArray(1, char(value));
        break;
    case NumberBase::FixedPoint: {
        const QRegularExpression re(QStringLiteral("^(\\d+)(?::(\\d{1,4}))?$"));
        const auto m = re.match(text);
        ok = m.hasMatch();
        if (!ok) {
            w.error = tr("%1 takes a number with up to four decimals after a colon (5:7777).").arg(parameterName(p));
            break;
        }
        QString fraction = m.captured(2);
        while (fraction.size() < 4) fraction += QLatin1Char('0');
        value = m.captured(1).toLongLong() * kFixedScale + fraction.toLongLong();
        digits = text.toLatin1();
        break;
    }
    }
    if (!ok) return w;
    if (value < p.minimum || value > p.maximum) {
        w.error = tr("%1 must lie within %2.").arg(parameterName(p), rangeText(p));
        return w;
    }
    QByteArray command(p.name.data(), qsizetype(p.name.size()));
    command += digits;
    if (value < 0) command += '-'; // the sign follows the number (SL<F|R><position>[<sign>])
    w.command = command + '\r';
    return w;
}

} // namespace serialport
