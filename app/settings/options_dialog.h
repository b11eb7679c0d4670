// OptionsDialog: Motion Link's OPTIONS as one dialog — communications (port, baud 300-19200, autobaud
// sequence), axis selection (multidrop wake-up), drive password (remembered only on request), colours and
// keymap. Starts from the stored options; on OK stores them. Use open() and listen to accepted().
#pragma once

#include "app_options.h"
#include "connection_choice.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QTabWidget;

namespace app {

class OptionsDialog final : public QDialog {
    Q_OBJECT
public:
    explicit OptionsDialog(QWidget* parent = nullptr);

    void setOptions(const AppOptions& options, const ConnectionChoice& choice);
    AppOptions options() const;
    ConnectionChoice choice() const;
    // "communications", "drive" or "appearance": the page to show.
    void showPage(const QString& name);

    void accept() override;

private:
    QWidget* makeCommunicationsPage();
    QWidget* makeDrivePage();
    QWidget* makeAppearancePage();

    QTabWidget* m_tabs;
    QComboBox* m_port;
    QComboBox* m_baud;
    QCheckBox* m_autobaud;
    QComboBox* m_axis;
    QLineEdit* m_password;
    QCheckBox* m_remember;
    QComboBox* m_theme;
    QComboBox* m_keymap;
};

} // namespace app
