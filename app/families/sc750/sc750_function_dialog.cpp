// Sc750FunctionDialog: P frames for the function's variables, then the F frame.
#include "sc750_function_dialog.h"

#include "sc750_workspace.h"
#include "theme.h"

#include "drive_core/catalog/sc750_catalog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

#include <memory>

namespace app {

Sc750FunctionDialog::Sc750FunctionDialog(Sc750Workspace& workspace, QWidget* parent)
    : QDialog(parent), m_workspace(workspace), m_function(new QComboBox), m_form(new QFormLayout),
      m_status(new QLabel) {
    setObjectName(QStringLiteral("sc750FunctionDialog"));
    setWindowTitle(tr("Real Time Function Call"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Issues a motion function directly, as the statement would in a program. "
                                "Only while no program executes."));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    auto* top = new QFormLayout;
    m_function->addItems(functions());
    top->addRow(tr("&Function:"), m_function);
    layout->addLayout(top);
    layout->addLayout(m_form);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    QPushButton* callButton = buttons->addButton(tr("&Call"), QDialogButtonBox::ApplyRole);
    callButton->setDefault(true);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(callButton, &QPushButton::clicked, this, &Sc750FunctionDialog::call);
    connect(m_function, &QComboBox::currentTextChanged, this, &Sc750FunctionDialog::rebuildFields);
    setMinimumWidth(420);
    rebuildFields();
}

QStringList Sc750FunctionDialog::functions() {
    return {QStringLiteral("GO.VEL"),  QStringLiteral("GO.INCR"),      QStringLiteral("GO.ABS"),
            QStringLiteral("GO.HOME"), QStringLiteral("ABORT.MOTION"), QStringLiteral("UPD.MOVE"),
            QStringLiteral("PAUSE")};
}

QStringList Sc750FunctionDialog::variablesOf(const QString& function) {
    const QStringList profile{QStringLiteral("RUN.SPEED"), QStringLiteral("ACCEL.RATE"), QStringLiteral("DECEL.RATE")};
    if (function == QLatin1String("GO.VEL")) return QStringList{QStringLiteral("DIR")} + profile;
    if (function == QLatin1String("GO.INCR")) return QStringList{QStringLiteral("INDEX.DIST")} + profile;
    if (function == QLatin1String("GO.ABS")) return QStringList{QStringLiteral("TARGET.POS")} + profile;
    if (function == QLatin1String("GO.HOME") || function == QLatin1String("UPD.MOVE")) return profile;
    if (function == QLatin1String("PAUSE")) return {QStringLiteral("PAUSE.TIME")};
    return {};
}

void Sc750FunctionDialog::selectFunction(const QString& function) {
    m_function->setCurrentText(function);
}

void Sc750FunctionDialog::rebuildFields() {
    while (m_form->rowCount() > 0) m_form->removeRow(0);
    m_fields.clear();
    m_read.clear();
    for (const QString& name : variablesOf(m_function->currentText())) {
        auto* field = new QLineEdit;
        const auto* info = drive_core::catalog::sc750::findVariable(name.toStdString());
        if (info) {
            field->setToolTip(QString::fromLatin1(info->description.data(), qsizetype(info->description.size())));
            field->setPlaceholderText(QString::fromLatin1(info->units.data(), qsizetype(info->units.size())));
        }
        m_form->addRow(name + QLatin1Char(':'), field);
        m_fields.insert(name, field);
        m_workspace.send(
            'G', name,
            [self = QPointer(this), name, field = QPointer(field)](const serialport::Sc750Reply& reply) {
                if (!self || !field) return; // closed, or another function chosen meanwhile
                const QString value = reply.payload.section(QLatin1Char('='), 1);
                self->m_read.insert(name, value);
                field->setText(value);
            },
            [self = QPointer(this), name](const QString& why) {
                if (self) self->setStatus(tr("%1: %2").arg(name, why), true);
            });
    }
    if (m_fields.isEmpty())
        setStatus(tr("%1 uses no variables.").arg(m_function->currentText()), false);
    else
        setStatus(QString(), false);
}

void Sc750FunctionDialog::call() {
    const QString function = m_function->currentText();
    auto failed = std::make_shared<bool>(false);
    for (auto it = m_fields.cbegin(); it != m_fields.cend(); ++it) {
        const QString value = it.value()->text().trimmed();
        if (value.isEmpty() || value == m_read.value(it.key())) continue;
        m_workspace.send('P', QStringLiteral("%1=%2").arg(it.key(), value), {},
                         [self = QPointer(this), failed, name = it.key()](const QString& why) {
                             *failed = true;
                             if (self) self->setStatus(tr("%1 not written: %2").arg(name, why), true);
                         });
    }
    m_workspace.send(
        'F', function,
        [self = QPointer(this), function, failed](const serialport::Sc750Reply&) {
            if (!self) return;
            if (!*failed) self->setStatus(tr("%1 issued.").arg(function), false);
            emit self->called(function);
        },
        [self = QPointer(this), function](const QString& why) {
            if (self) self->setStatus(tr("%1 refused: %2").arg(function, why), true);
        });
}

QString Sc750FunctionDialog::status() const {
    return m_status->text();
}

void Sc750FunctionDialog::setStatus(const QString& text, bool error) {
    Theme::showStatus(*m_status, text, error);
}

} // namespace app
