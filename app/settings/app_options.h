// AppOptions: the Options dialog's settings (Motion Link's OPTIONS menu) as a value type, persisted in
// QSettings under "options/". The drive password is written to the settings file only when the user ticks
// "remember"; otherwise it lives in this process's memory until ServoDesk quits.
#pragma once

#include <QChar>
#include <QString>

namespace app {

struct AppOptions {
    enum class Theme { Light, Dark };
    enum class Keymap { Modern, Classic }; // stored as the editor's own "editor/keymap"; the editor applies it

    static constexpr int kAutobaudReturns = 5; // "several carriage returns" (L5294): chosen 5

    bool autobaud = false;     // send kAutobaudReturns CRs right after connecting
    QChar axis;                // multidrop axis ID ('A'-'Z', '0'-'9'); null for a single drive
    QString drivePassword;     // for >BDS (the editor's PASS); empty when none
    bool rememberPassword = false;
    Theme theme = Theme::Light;
    Keymap keymap = Keymap::Modern;

    // The options in effect: the settings, plus a password given earlier in this session.
    static AppOptions current();
    // Makes these the options in effect and stores them (the password only when rememberPassword).
    void save() const;

    static bool isValidAxis(QChar id) { return (id >= u'A' && id <= u'Z') || (id >= u'0' && id <= u'9'); }

    bool operator==(const AppOptions&) const = default;
};

} // namespace app
