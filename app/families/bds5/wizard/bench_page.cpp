// BenchPage: commands, live readout, answers.
#include "bench_page.h"

#include "families/bds5/drive_connection.h"
#include "variables/variable_model.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace app {

namespace cat = drive_core::catalog::bds5;

namespace {
constexpr int kReadoutColumns = 8;

bool isSwitch(const QString& name, bool* writable = nullptr) {
    const QByteArray upper = name.toLatin1();
    const auto ref = cat::findVariable(std::string_view(upper.constData(), std::size_t(upper.size())));
    if (writable) *writable = ref && ref->info->write != cat::WriteCondition::Never;
    return ref && ref->info->isSwitch;
}

QString lampStyle(bool on) {
    return on ? QStringLiteral("background:#34a853;color:white;border-radius:4px;padding:4px;font-weight:bold")
              : QStringLiteral("background:#e0e0e0;color:#5f6368;border-radius:4px;padding:4px");
}
} // namespace

BenchPage::BenchPage(WizardContext context, const QString& title, const QString& text, QList<Action> actions,
                     const QStringList& readout, QWidget* parent)
    : QWizardPage(parent), m_context(context), m_readout(readout) {
    setTitle(title);
    setSubTitle(text); // in the wizard's header, as every page's (SetupWizard numbers them)
    auto* layout = new QVBoxLayout(this);
    if (!actions.isEmpty()) {
        auto* row = new QHBoxLayout;
        for (const Action& action : actions) {
            QList<QLineEdit*> fields;
            for (const Field& f : action.fields) {
                row->addWidget(new QLabel(f.label, this));
                auto* edit = new QLineEdit(f.initial, this);
                edit->setMaximumWidth(70);
                row->addWidget(edit);
                fields << edit;
            }
            auto* button = new QPushButton(action.label, this);
            row->addWidget(button);
            m_actions.insert(action.label, button);
            connect(button, &QPushButton::clicked, this, [this, command = action.command, fields] {
                QString line = command;
                for (QLineEdit* f : fields) line = line.arg(f->text().trimmed());
                run(line);
            });
        }
        row->addStretch(1);
        layout->addLayout(row);
    }
    if (!m_readout.isEmpty()) layout->addWidget(makeReadout());
    m_log = new QPlainTextEdit(this);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(200);
    m_log->setPlaceholderText(tr("The drive's answers appear here."));
    m_log->setStyleSheet(QStringLiteral("font-family:monospace"));
    layout->addWidget(m_log, 1);
    m_log->setVisible(!actions.isEmpty() || !m_toggles.isEmpty()); // a readout alone has no answers to show
    if (!m_log->isVisible()) layout->addStretch(1);
    connect(&m_context.model, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex& first) {
        const QString name = first.data(VariableModel::NameRole).toString();
        if (m_readout.contains(name)) showValue(name);
    });
}

QWidget* BenchPage::makeReadout() {
    auto* box = new QGroupBox(tr("Live from the drive"), this);
    auto* grid = new QGridLayout(box);
    int at = 0;
    for (const QString& name : m_readout) {
        bool writable = false;
        const bool lamp = isSwitch(name, &writable);
        if (lamp && writable) {
            auto* button = new QPushButton(name, box);
            button->setCheckable(true);
            button->setStyleSheet(
                QStringLiteral("QPushButton:checked{background:#34a853;color:white;font-weight:bold}"));
            connect(button, &QPushButton::clicked, this,
                    [this, name](bool on) { run(name + (on ? QStringLiteral(" 1") : QStringLiteral(" 0"))); });
            m_toggles.insert(name, button);
            grid->addWidget(button, at / kReadoutColumns, at % kReadoutColumns);
        } else if (lamp) {
            auto* label = new QLabel(name, box);
            label->setAlignment(Qt::AlignCenter);
            label->setStyleSheet(lampStyle(false));
            m_values.insert(name, label);
            grid->addWidget(label, at / kReadoutColumns, at % kReadoutColumns);
        } else {
            auto* label = new QLabel(QStringLiteral("<b>%1</b>  \u2014").arg(name), box);
            label->setStyleSheet(QStringLiteral("font-family:monospace;font-size:13pt;padding:4px"));
            m_values.insert(name, label);
            grid->addWidget(label, at / 3, at % 3); // numbers get room: three a row
        }
        ++at;
    }
    return box;
}

void BenchPage::showValue(const QString& name) {
    const QString value = m_context.model.value(name);
    if (QPushButton* toggle = m_toggles.value(name)) {
        toggle->setChecked(value != QLatin1String("0") && !value.isEmpty());
    } else if (QLabel* label = m_values.value(name)) {
        if (isSwitch(name))
            label->setStyleSheet(lampStyle(value != QLatin1String("0") && !value.isEmpty()));
        else
            label->setText(QStringLiteral("<b>%1</b>  %2").arg(name, value));
    }
}

void BenchPage::run(const QString& line) {
    serialport::Bds5Session* session = m_context.connection.session();
    if (!session || !m_context.connection.isConnected()) {
        m_log->appendPlainText(tr("Not connected: %1 was not sent.").arg(line));
        return;
    }
    if (session != m_session) {
        m_session = session;
        connect(session, &serialport::Bds5Session::finished, this, &BenchPage::onFinished);
    }
    m_log->appendPlainText(QStringLiteral("--> ") + line);
    m_pending << session->send(line);
}

void BenchPage::onFinished(quint64 id, const serialport::Bds5Response& response) {
    if (!m_pending.removeOne(id)) return;
    for (const QString& line : response.lines) m_log->appendPlainText(line);
    for (const serialport::Bds5ErrorLine& e : response.errors)
        m_log->appendPlainText(QStringLiteral("ERR %1 %2").arg(e.code).arg(e.message));
}

QPushButton* BenchPage::actionButton(const QString& label) const {
    return m_actions.value(label);
}

QPushButton* BenchPage::toggleFor(const QString& name) const {
    return m_toggles.value(name);
}

QString BenchPage::log() const {
    return m_log->toPlainText();
}

QString BenchPage::readoutText(const QString& name) const {
    const QLabel* label = m_values.value(name);
    if (!label || isSwitch(name)) return {};
    static const QRegularExpression kMarkup(QStringLiteral("<[^>]*>"));
    return QString(label->text()).remove(kMarkup);
}

} // namespace app
