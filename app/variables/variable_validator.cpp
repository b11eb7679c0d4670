// VariableValidator: the drive's own write checks (App. E, Table E.2), done before sending.
#include "variable_validator.h"

namespace app {

namespace cat = drive_core::catalog::bds5;

namespace {
constexpr int kBadOrOutOfRange = 83;
constexpr int kMustBeDisabled = 51;
constexpr int kMonitorVariable = 81;
constexpr int kProtected = 111;
} // namespace

QString VariableValidator::driveError(int code) {
    const cat::ErrorInfo* info = cat::findError(code);
    return info ? QStringLiteral("ERR %1 %2")
                      .arg(code)
                      .arg(QString::fromLatin1(info->message.data(), qsizetype(info->message.size())))
                : QStringLiteral("ERR %1").arg(code);
}

std::pair<QString, QString> VariableValidator::unitPair(cat::UnitClass unitClass) {
    switch (unitClass) {
    case cat::UnitClass::Position: return {QStringLiteral("PNUM"), QStringLiteral("PDEN")};
    case cat::UnitClass::Velocity: return {QStringLiteral("VNUM"), QStringLiteral("VDEN")};
    case cat::UnitClass::Acceleration: return {QStringLiteral("ANUM"), QStringLiteral("ADEN")};
    case cat::UnitClass::Current: return {QStringLiteral("INUM"), QStringLiteral("IDEN")};
    case cat::UnitClass::ExtPosition: return {QStringLiteral("PXNUM"), QStringLiteral("PXDEN")};
    case cat::UnitClass::ExtVelocity: return {QStringLiteral("VXNUM"), QStringLiteral("VXDEN")};
    default: return {};
    }
}

std::optional<std::pair<double, double>> VariableValidator::userLimits(const cat::VariableInfo& info,
                                                                       const Context& context) {
    if (info.limits == cat::LimitClass::None) return std::nullopt;
    double low = double(cat::minimumOf(info));
    double high = double(cat::maximumOf(info));
    const auto [num, den] = unitPair(info.unitClass);
    if (!num.isEmpty()) {
        const auto n = context.valueOf ? context.valueOf(num) : std::nullopt;
        const auto d = context.valueOf ? context.valueOf(den) : std::nullopt;
        if (!n || !d || *n <= 0 || *d <= 0) return std::nullopt; // units unknown: the drive decides
        low = low * *d / *n;
        high = high * *d / *n;
    }
    return std::pair{low, high};
}

VariableValidator::Verdict VariableValidator::check(const QString& name, const QString& text, const Context& context) {
    Verdict verdict;
    const QByteArray upper = name.toUpper().toLatin1();
    const auto ref = cat::findVariable(std::string_view(upper.constData(), std::size_t(upper.size())));
    if (!ref) {
        verdict.message = tr("%1 is not a BDS5 variable").arg(name);
        return verdict;
    }
    const cat::VariableInfo& info = *ref->info;
    switch (info.write) {
    case cat::WriteCondition::Never:
        verdict.message =
            tr("%1: %2 is a monitor variable and cannot be written").arg(driveError(kMonitorVariable), name);
        return verdict;
    case cat::WriteCondition::Factory:
        verdict.message = tr("%1: %2 is set at the factory").arg(driveError(kProtected), name);
        return verdict;
    case cat::WriteCondition::Disabled:
        if (context.valueOf && context.valueOf(QStringLiteral("ACTIVE")).value_or(0) != 0) {
            verdict.message = tr("%1: disable the drive before changing %2").arg(driveError(kMustBeDisabled), name);
            return verdict;
        }
        break;
    default: break;
    }
    QString value = text.trimmed().toUpper();
    if (info.isSwitch || info.limits == cat::LimitClass::Switch) {
        if (value == QLatin1String("ON"))
            value = QStringLiteral("1");
        else if (value == QLatin1String("OFF"))
            value = QStringLiteral("0");
    }
    bool isNumber = false;
    const double number = value.toDouble(&isNumber);
    if (!isNumber) {
        verdict.message = tr("%1: '%2' is not a number").arg(driveError(kBadOrOutOfRange), text.trimmed());
        return verdict;
    }
    if (const auto limits = userLimits(info, context); limits && (number < limits->first || number > limits->second)) {
        verdict.message = tr("%1: %2 must lie between %3 and %4")
                              .arg(driveError(kBadOrOutOfRange), name, QString::number(limits->first, 'g', 12),
                                   QString::number(limits->second, 'g', 12));
        return verdict;
    }
    verdict.ok = true;
    verdict.instruction = name.toUpper() + QLatin1Char(' ') + value;
    return verdict;
}

} // namespace app
