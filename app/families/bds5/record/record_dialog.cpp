// RecordDialog: the RECORD set-up form.
#include "record_dialog.h"

#include "scope_catalog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace app {

namespace {
constexpr int kMaxIntervalMs = 60'000; // one minute (L6372)
const QString kNone = QStringLiteral("\u2014");
} // namespace

RecordDialog::RecordDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("recordDialog"));
    setWindowTitle(tr("Scope From Drive \u2014 RECORD"));
    auto* form = new QFormLayout(this);
    const QStringList names = recordableVariables();
    for (int i = 0; i < 4; ++i) {
        m_variables[i] = new QComboBox(this);
        if (i > 0) m_variables[i]->addItem(kNone);
        m_variables[i]->addItems(names);
        m_variables[i]->setToolTip(tr("PE, REMOTE, TMR1-4, VAVG, VXAVG and user switches cannot be recorded."));
        connect(m_variables[i], &QComboBox::currentIndexChanged, this, &RecordDialog::updateLimits);
        form->addRow(tr("Variable %1").arg(i + 1), m_variables[i]);
    }
    m_samples = new QSpinBox(this);
    m_samples->setRange(1, recordSampleLimit(1));
    m_interval = new QSpinBox(this);
    m_interval->setRange(1, kMaxIntervalMs);
    m_interval->setSuffix(tr(" ms"));
    form->addRow(tr("Samples (RECORD <n>)"), m_samples);
    form->addRow(tr("Interval (RECORD <t>)"), m_interval);
    m_trigger = new QLineEdit(this);
    m_trigger->setPlaceholderText(tr("e.g. J 1000 \u2014 sent right after RECORD"));
    form->addRow(tr("Trigger command"), m_trigger);
    auto* thenRow = new QHBoxLayout;
    m_then = new QLineEdit(this);
    m_then->setPlaceholderText(tr("e.g. J 0"));
    m_thenAt = new QSpinBox(this);
    m_thenAt->setRange(0, 3'600'000);
    m_thenAt->setPrefix(tr("after "));
    m_thenAt->setSuffix(tr(" ms"));
    thenRow->addWidget(m_then, 1);
    thenRow->addWidget(m_thenAt);
    form->addRow(tr("Then"), thenRow);
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    form->addRow(m_summary);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Record"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
    connect(m_samples, &QSpinBox::valueChanged, this, &RecordDialog::updateLimits);
    connect(m_interval, &QSpinBox::valueChanged, this, &RecordDialog::updateLimits);

    serialport::Bds5RecordPlan defaults;
    defaults.samples = 250;
    defaults.intervalMs = 1;
    defaults.variables = {QStringLiteral("VCMD"), QStringLiteral("VFB")};
    defaults.commands = {{0, QStringLiteral("J 1000")}, {150, QStringLiteral("J 0")}};
    setPlan(defaults);
}

serialport::Bds5RecordPlan RecordDialog::plan() const {
    serialport::Bds5RecordPlan p;
    for (QComboBox* box : m_variables)
        if (box->currentText() != kNone && !p.variables.contains(box->currentText())) p.variables << box->currentText();
    p.samples = m_samples->value();
    p.intervalMs = m_interval->value();
    if (!m_trigger->text().trimmed().isEmpty()) p.commands.append({0, m_trigger->text().trimmed()});
    if (!m_then->text().trimmed().isEmpty()) {
        p.commands.append({m_thenAt->value(), m_then->text().trimmed()});
        p.onCancel = m_then->text().trimmed();
    }
    return p;
}

void RecordDialog::setPlan(const serialport::Bds5RecordPlan& plan) {
    for (int i = 0; i < 4; ++i) {
        const QString name = plan.variables.value(i, i == 0 ? QStringLiteral("VFB") : kNone);
        m_variables[i]->setCurrentIndex(std::max(0, m_variables[i]->findText(name)));
    }
    m_interval->setValue(plan.intervalMs);
    m_trigger->setText(plan.commands.value(0).line);
    m_then->setText(plan.commands.value(1).line);
    m_thenAt->setValue(plan.commands.value(1).atMs);
    updateLimits();
    m_samples->setValue(plan.samples);
}

// The sample limit follows the number of variables, and the summary says how long the recording lasts.
void RecordDialog::updateLimits() {
    const int count = int(plan().variables.size());
    m_samples->setMaximum(recordSampleLimit(count));
    const double seconds = double(m_samples->value()) * m_interval->value() / 1000.0;
    m_summary->setText(tr("%1 \u2014 %2 variable(s): at most %3 samples; the recording lasts %4 s.")
                           .arg(plan().recordLine())
                           .arg(count)
                           .arg(recordSampleLimit(count))
                           .arg(seconds, 0, 'g', 4));
}

} // namespace app
