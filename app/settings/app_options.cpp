// AppOptions: QSettings persistence; the unremembered password stays in memory.
#include "app_options.h"

#include "editor/keymap.h"

#include <QSettings>

namespace app {

namespace {
QString& unrememberedPassword() {
    static QString password; // this process only, never written anywhere
    return password;
}
} // namespace

AppOptions AppOptions::current() {
    QSettings settings;
    settings.beginGroup(QStringLiteral("options"));
    AppOptions o;
    o.autobaud = settings.value(QStringLiteral("autobaud"), false).toBool();
    const QString axis = settings.value(QStringLiteral("axis")).toString();
    if (axis.size() == 1 && isValidAxis(axis[0])) o.axis = axis[0];
    o.rememberPassword = settings.value(QStringLiteral("rememberPassword"), false).toBool();
    o.drivePassword = o.rememberPassword ? settings.value(QStringLiteral("password")).toString()
                                         : unrememberedPassword();
    o.theme = settings.value(QStringLiteral("theme")).toString() == QLatin1String("dark") ? Theme::Dark
                                                                                        : Theme::Light;
    settings.endGroup();
    // The keymap shares the editor's own setting, which the editor's quick switch also writes.
    o.keymap = settings.value(editor::Keymap::kSettingsKey).toString() == editor::Keymap::kClassic ? Keymap::Classic
                                                                                                 : Keymap::Modern;
    return o;
}

void AppOptions::save() const {
    QSettings settings;
    settings.beginGroup(QStringLiteral("options"));
    settings.setValue(QStringLiteral("autobaud"), autobaud);
    settings.setValue(QStringLiteral("axis"), axis.isNull() ? QString() : QString(axis));
    settings.setValue(QStringLiteral("rememberPassword"), rememberPassword);
    if (rememberPassword) {
        settings.setValue(QStringLiteral("password"), drivePassword);
        unrememberedPassword().clear();
    } else {
        settings.remove(QStringLiteral("password")); // unticking "remember" forgets the stored one
        unrememberedPassword() = drivePassword;
    }
    settings.setValue(QStringLiteral("theme"), theme == Theme::Dark ? QStringLiteral("dark") : QStringLiteral("light"));
    settings.endGroup();
    settings.setValue(editor::Keymap::kSettingsKey,
                      keymap == Keymap::Classic ? editor::Keymap::kClassic : editor::Keymap::kModern);
}

} // namespace app
