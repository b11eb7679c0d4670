// OptionsDialog: the pages and the mapping to AppOptions and ConnectionChoice.
#include "options_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSerialPortInfo>
#include <QSettings>
#include <QTabWidget>
#include <QVBoxLayout>

namespace app {

namespace {
QLabel* note(const QString& text) {
    auto* label = new QLabel(text);
    label->setWordWrap(true);
    label->setForegroundRole(QPalette::PlaceholderText);
    return label;
}
} // namespace

OptionsDialog::OptionsDialog(QWidget* parent) : QDialog(parent), m_tabs(new QTabWidget) {
    setObjectName(QStringLiteral("optionsDialog"));
    setWindowTitle(tr("Options"));
    m_tabs->addTab(makeCommunicationsPage(), tr("Communications"));
    m_tabs->addTab(makeDrivePage(), tr("Axis && Password"));
    m_tabs->addTab(makeAppearancePage(), tr("Appearance"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_tabs);
    layout->addWidget(buttons);
    QSettings settings;
    setOptions(AppOptions::current(), ConnectionChoice::load(settings));
    resize(560, sizeHint().height());
}

QWidget* OptionsDialog::makeCommunicationsPage() {
    auto* page = new QWidget;
    auto* form = new QFormLayout(page);
    m_port = new QComboBox;
    m_port->setObjectName(QStringLiteral("optionsPort"));
    m_port->setEditable(true);
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->addItem(tr("Simulated BDS5 (built in)"));
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) m_port->addItem(info.systemLocation());
    m_baud = new QComboBox;
    m_baud->setObjectName(QStringLiteral("optionsBaud"));
    for (const int rate : ConnectionChoice::baudRates()) m_baud->addItem(QString::number(rate), rate);
    m_autobaud = new QCheckBox(tr("Send the autobaud sequence (%1 carriage returns) after connecting")
                                   .arg(AppOptions::kAutobaudReturns));
    m_autobaud->setObjectName(QStringLiteral("optionsAutobaud"));
    form->addRow(tr("&Port:"), m_port);
    form->addRow(tr("&Baud rate:"), m_baud);
    form->addRow(m_autobaud);
    form->addRow(note(tr("A drive autobauds at power-up when its MOTION input is off or ABAUD is on: it "
                         "measures the carriage returns and answers at that rate. A changed port or rate "
                         "reconnects when you press OK.")));
    return page;
}

QWidget* OptionsDialog::makeDrivePage() {
    auto* page = new QWidget;
    auto* form = new QFormLayout(page);
    m_axis = new QComboBox;
    m_axis->setObjectName(QStringLiteral("optionsAxis"));
    m_axis->addItem(tr("Single drive (no multidrop)"), QString());
    for (char16_t c = u'A'; c <= u'Z'; ++c) m_axis->addItem(tr("Axis %1").arg(QChar(c)), QString(QChar(c)));
    for (char16_t c = u'0'; c <= u'9'; ++c) m_axis->addItem(tr("Axis %1").arg(QChar(c)), QString(QChar(c)));
    m_password = new QLineEdit;
    m_password->setObjectName(QStringLiteral("optionsPassword"));
    m_password->setEchoMode(QLineEdit::Password);
    m_password->setPlaceholderText(tr("none"));
    m_remember = new QCheckBox(tr("&Remember the password"));
    m_remember->setObjectName(QStringLiteral("optionsRemember"));
    form->addRow(tr("&Axis:"), m_axis);
    form->addRow(note(tr("On an RS-485 multidrop line, each drive's ADDR gives it an ID. ServoDesk wakes the "
                         "chosen axis with \\ and its ID after connecting and when you pick Options > Wake "
                         "Up Axis; only that axis then answers.")));
    form->addRow(tr("Drive &password:"), m_password);
    form->addRow(m_remember);
    form->addRow(note(tr("The password set with the resident editor's PASS command; downloads send it with "
                         ">BDS. Unless \"Remember\" is ticked it is kept only until ServoDesk quits. If ticked, "
                         "it is stored unencrypted in the settings file:\n%1")
                          .arg(QSettings().fileName())));
    return page;
}

QWidget* OptionsDialog::makeAppearancePage() {
    auto* page = new QWidget;
    auto* form = new QFormLayout(page);
    m_theme = new QComboBox;
    m_theme->setObjectName(QStringLiteral("optionsTheme"));
    m_theme->addItem(tr("Light"), int(AppOptions::Theme::Light));
    m_theme->addItem(tr("Dark"), int(AppOptions::Theme::Dark));
    m_keymap = new QComboBox;
    m_keymap->setObjectName(QStringLiteral("optionsKeymap"));
    m_keymap->addItem(tr("Modern (Ctrl+F find, Ctrl+S save, ...)"), int(AppOptions::Keymap::Modern));
    m_keymap->addItem(tr("Classic Motion Link (F10 menus, ^K^B, ^Q^F, ^Y, ...)"), int(AppOptions::Keymap::Classic));
    form->addRow(tr("&Colours (editor and terminal):"), m_theme);
    form->addRow(tr("&Editor keys:"), m_keymap);
    return page;
}

void OptionsDialog::setOptions(const AppOptions& options, const ConnectionChoice& choice) {
    if (choice.kind == ConnectionChoice::Kind::Simulator) m_port->setCurrentIndex(0);
    else m_port->setCurrentText(choice.portName);
    const int baud = m_baud->findData(choice.baudRate);
    m_baud->setCurrentIndex(baud >= 0 ? baud : m_baud->findData(9600));
    m_autobaud->setChecked(options.autobaud);
    m_axis->setCurrentIndex(std::max(0, m_axis->findData(options.axis.isNull() ? QString() : QString(options.axis))));
    m_password->setText(options.drivePassword);
    m_remember->setChecked(options.rememberPassword);
    m_theme->setCurrentIndex(m_theme->findData(int(options.theme)));
    m_keymap->setCurrentIndex(m_keymap->findData(int(options.keymap)));
}

AppOptions OptionsDialog::options() const {
    AppOptions o;
    o.autobaud = m_autobaud->isChecked();
    const QString axis = m_axis->currentData().toString();
    if (axis.size() == 1) o.axis = axis[0];
    o.drivePassword = m_password->text();
    o.rememberPassword = m_remember->isChecked();
    o.theme = AppOptions::Theme(m_theme->currentData().toInt());
    o.keymap = AppOptions::Keymap(m_keymap->currentData().toInt());
    return o;
}

ConnectionChoice OptionsDialog::choice() const {
    const QString port = m_port->currentText().trimmed();
    if (m_port->currentIndex() == 0 && port == m_port->itemText(0)) {
        ConnectionChoice simulated = ConnectionChoice::simulator();
        simulated.baudRate = m_baud->currentData().toInt();
        return simulated;
    }
    return ConnectionChoice::serialPort(port, m_baud->currentData().toInt());
}

void OptionsDialog::showPage(const QString& name) {
    static const QStringList kPages{QStringLiteral("communications"), QStringLiteral("drive"),
                                    QStringLiteral("appearance")};
    m_tabs->setCurrentIndex(std::max(0, int(kPages.indexOf(name))));
}

void OptionsDialog::accept() {
    options().save();
    QSettings settings;
    choice().save(settings);
    QDialog::accept();
}

} // namespace app
