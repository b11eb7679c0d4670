// Sc750SetupDialog: the set-up screen, the Auto rule, and writing the result.
#include "sc750_setup_dialog.h"

#include "sc750_setup_data_table.h"
#include "sc750_workspace.h"
#include "theme.h"

#include "main_window.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "drive_core/catalog/sc750_motors.h"
#include "editor/program_editor.h"
#include "serialport/sc750_parameter_file.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

namespace catalog = drive_core::catalog::sc750;

Sc750SetupDialog::Sc750SetupDialog(Sc750Workspace& workspace, QWidget* parent)
    : QDialog(parent), m_workspace(workspace), m_part(new QLineEdit), m_model(new QLabel(tr("(reading...)"))),
      m_auto(new QRadioButton(tr("&Auto"))), m_manual(new QRadioButton(tr("&Manual"))), m_response(new QComboBox),
      m_dataBox(new QGroupBox(tr("Controller Set Up &Data"))), m_data(new Sc750SetupDataTable),
      m_table(new QTableWidget(0, 2)), m_status(new QLabel) {
    setObjectName(QStringLiteral("sc750SetupDialog"));
    setWindowTitle(tr("Controller Set Up"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_part->setPlaceholderText(tr("Enter the first four digits of your part number"));
    m_part->setMaxLength(4);
    form->addRow(tr("Motor &part number:"), m_part);
    form->addRow(tr("Controller model:"), m_model);
    auto* modes = new QHBoxLayout;
    modes->addWidget(m_auto);
    modes->addWidget(m_manual);
    modes->addStretch();
    form->addRow(tr("Set-up mode:"), modes);
    m_response->addItems({tr("Stiff/High Bandwidth"), tr("Gentle/Low Bandwidth")});
    form->addRow(tr("System &Response:"), m_response);
    layout->addLayout(form);
    // Manual's first screen: the motor's data; the computed values below follow every edit.
    auto* dataLayout = new QVBoxLayout(m_dataBox);
    dataLayout->addWidget(m_data);
    layout->addWidget(m_dataBox);
    auto* valuesBox = new QGroupBox(tr("Computed &values (PARAMS)"));
    auto* valuesLayout = new QVBoxLayout(valuesBox);
    m_table->setHorizontalHeaderLabels({tr("Parameter"), tr("Value")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    valuesLayout->addWidget(m_table);
    layout->addWidget(valuesBox, 1);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &Sc750SetupDialog::apply);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_auto, &QRadioButton::toggled, this, [this](bool on) { setManual(!on); });
    connect(m_response, &QComboBox::currentIndexChanged, this, &Sc750SetupDialog::compute);
    connect(m_part, &QLineEdit::textChanged, this, [this] {
        m_data->setSetupData(catalog::setupData(m_part->text().trimmed().toStdString(), false));
        compute();
    });
    connect(m_data, &Sc750SetupDataTable::dataEdited, this, &Sc750SetupDialog::compute);
    resize(480, 760);
    m_data->setSetupData(catalog::SetupData{});
    m_auto->setChecked(true);
    compute();
    // The Options path reads the model from the controller (L2574).
    m_workspace.send(
        'V', {},
        [self = QPointer(this)](const serialport::Sc750Reply& reply) {
            if (!self) return;
            const QString model = reply.payload.section(QLatin1Char(','), 0, 0).trimmed();
            self->m_model->setText(QStringLiteral("SC%1").arg(model));
            self->m_modelNumber = model.toInt();
            if (!self->m_fromProgram) self->compute();
        },
        [self = QPointer(this)](const QString& why) {
            if (self) self->m_model->setText(tr("unknown (%1)").arg(why));
        });
}

void Sc750SetupDialog::setMotorPart(const QString& part) {
    m_part->setText(part);
}

void Sc750SetupDialog::compute() {
    m_fromProgram = false;
    const bool gentle = m_response->currentIndex() == 1;
    catalog::SetupData setup = catalog::setupData(m_part->text().trimmed().toStdString(), gentle);
    if (m_manual->isChecked()) {
        const std::optional<catalog::SetupData> edited = m_data->setupData();
        m_ok->setEnabled(edited.has_value());
        if (!edited) {
            setStatus(m_data->problem(), true);
            return;
        }
        setup = *edited;
        setup.gentle = gentle;
    }
    const auto values = catalog::setupParameters(setup, m_modelNumber);
    m_table->setRowCount(int(values.size()));
    for (int row = 0; row < int(values.size()); ++row) {
        auto* name = new QTableWidgetItem(QString::fromStdString(values[std::size_t(row)].first));
        name->setFlags(name->flags() & ~Qt::ItemIsEditable);
        m_table->setItem(row, 0, name);
        m_table->setItem(row, 1,
                         new QTableWidgetItem(serialport::Sc750ParameterFile::formatValue(
                             values[std::size_t(row)].first, values[std::size_t(row)].second)));
    }
    showMode();
}

void Sc750SetupDialog::loadParams(const QString& text) {
    setManual(true);
    const serialport::Sc750ParameterFile file = serialport::Sc750ParameterFile::parse(text);
    for (const serialport::Sc750ParameterAssignment& a : file.assignments())
        for (int row = 0; row < m_table->rowCount(); ++row)
            if (m_table->item(row, 0)->text().compare(a.name, Qt::CaseInsensitive) == 0)
                m_table->item(row, 1)->setText(a.value);
    m_fromProgram = true;
    setStatus(tr("The program's PARAMS values: edit them (editing the motor's data recomputes them), then OK."), false);
}

void Sc750SetupDialog::setManual(bool manual) {
    if (m_manual->isChecked() == manual && m_auto->isChecked() != manual) return showMode();
    m_manual->setChecked(manual);
    m_auto->setChecked(!manual);
    compute(); // Auto: the motor table's data; Manual: the data screen, which Auto's edits never touch
}

void Sc750SetupDialog::showMode() {
    const bool manual = m_manual->isChecked();
    m_dataBox->setVisible(manual);
    if (!manual) m_ok->setEnabled(true);
    for (int row = 0; row < m_table->rowCount(); ++row) {
        QTableWidgetItem* item = m_table->item(row, 1);
        item->setFlags(manual ? item->flags() | Qt::ItemIsEditable : item->flags() & ~Qt::ItemIsEditable);
    }
    if (manual) {
        setStatus(tr("Manual: edit the motor's data (the values follow), then the values if need be; OK writes them."),
                  false);
        return;
    }
    const QString part = m_part->text().trimmed();
    const catalog::MotorInfo* motor = catalog::findMotor(part.toStdString());
    const QString forMotor =
        motor ? tr("motor %1 (%2)")
                    .arg(QString::fromLatin1(motor->part.data(), qsizetype(motor->part.size())),
                         QString::fromLatin1(motor->description.data(), qsizetype(motor->description.size())))
        : part.isEmpty() ? tr("no motor given: the boiler-plate values")
                         : tr("motor %1 is not in the table: the boiler-plate values").arg(part);
    setStatus(tr("Auto: computed for a stable, medium-performance servo, %1; OK writes them.").arg(forMotor), false);
}

void Sc750SetupDialog::setGentle(bool gentle) {
    m_response->setCurrentIndex(gentle ? 1 : 0);
}

QString Sc750SetupDialog::paramsBlock() const {
    QList<QPair<QString, QString>> values;
    for (int row = 0; row < m_table->rowCount(); ++row)
        values.append({m_table->item(row, 0)->text(), m_table->item(row, 1)->text()});
    return serialport::Sc750ParameterFile::block(values);
}

void Sc750SetupDialog::apply() {
    editor::ProgramEditor* editor = m_workspace.window().editor();
    const QString part = m_part->text().trimmed();
    QString block = paramsBlock();
    if (!part.isEmpty()) block = QStringLiteral("' Motor %1, %2\n").arg(part, m_response->currentText()) + block;
    editor->beginUndoAction();
    editor->selectAll();
    editor->replaceSelectedText(serialport::Sc750ParameterFile::withBlock(editor->text(), block));
    editor->endUndoAction();
    editor->setCursorPosition(0, 0);
    accept();
    if (!m_workspace.isConnected()) {
        emit m_workspace.message(tr("The PARAMS block is in the program; connect to set up the controller"));
        return;
    }
    // Then the controller: each value, and configured (it shows UC until then, L1555).
    for (int row = 0; row < m_table->rowCount(); ++row)
        m_workspace.send(
            'P', QStringLiteral("%1=%2").arg(m_table->item(row, 0)->text(), m_table->item(row, 1)->text().trimmed()),
            {}, [ws = &m_workspace](const QString& why) { emit ws->message(tr("Set up: %1").arg(why)); });
    m_workspace.send('K', QStringLiteral("1"), [ws = &m_workspace](const serialport::Sc750Reply&) {
        emit ws->message(tr("The controller is set up and configured"));
    });
}

QString Sc750SetupDialog::status() const {
    return m_status->text();
}

void Sc750SetupDialog::setStatus(const QString& text, bool error) {
    Theme::showStatus(*m_status, text, error);
}

} // namespace app
