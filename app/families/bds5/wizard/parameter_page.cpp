// ParameterPage: catalog rows rendered as a form.
#include "parameter_page.h"

#include "variables/variable_model.h"
#include "variables/variable_sync.h"
#include "variables/variable_validator.h"
#include "wizard_changes.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QVBoxLayout>

namespace app {

namespace cat = drive_core::catalog::bds5;

namespace {
const cat::VariableInfo* infoOf(const QString& name) {
    const QByteArray upper = name.toLatin1();
    const auto ref = cat::findVariable(std::string_view(upper.constData(), std::size_t(upper.size())));
    return ref ? ref->info : nullptr;
}

QString latin(std::string_view view) {
    return QString::fromLatin1(view.data(), qsizetype(view.size()));
}
} // namespace

ParameterPage::ParameterPage(WizardContext context, const QString& title, const QString& subTitle,
                             const QStringList& names, QWidget* parent)
    : QWizardPage(parent), m_context(context), m_names(names) {
    setTitle(title);
    setSubTitle(subTitle);
    auto* outer = m_outer = new QVBoxLayout(this);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* form = new QWidget(scroll);
    auto* grid = new QGridLayout(form);
    grid->setColumnStretch(4, 1);
    grid->setHorizontalSpacing(12);
    scroll->setWidget(form);
    outer->addWidget(scroll, 1);
    for (const QString& name : m_names) addRow(name);
    m_preview = new QLabel(this);
    m_preview->setWordWrap(true);
    m_preview->setStyleSheet(QStringLiteral("background:#e8f0fe;padding:6px;border-radius:4px"));
    m_preview->hide();
    outer->addWidget(m_preview);
    connect(&m_context.model, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex& first) {
        const QString name = first.data(VariableModel::NameRole).toString();
        if (m_editors.contains(name)) showRead(name);
    });
}

void ParameterPage::addRow(const QString& name) {
    const cat::VariableInfo* info = infoOf(name);
    if (!info) return;
    auto* grid = static_cast<QGridLayout*>(findChild<QScrollArea*>()->widget()->layout());
    const int row = grid->rowCount();
    auto* label = new QLabel(QStringLiteral("<b><tt>%1</tt></b>").arg(name), this);
    label->setToolTip(latin(info->description));
    QWidget* editor = nullptr;
    const bool writable = info->write != cat::WriteCondition::Never && info->write != cat::WriteCondition::Factory;
    if (info->isSwitch) {
        auto* box = new QCheckBox(tr("on"), this);
        connect(box, &QCheckBox::clicked, this,
                [this, name](bool on) { edited(name, on ? QStringLiteral("1") : QStringLiteral("0")); });
        editor = box;
    } else {
        auto* field = new QLineEdit(this);
        // Wide enough for the longest value a BDS5 variable holds (AMAX showed "00000" of 3000000).
        field->setMinimumWidth(field->fontMetrics().horizontalAdvance(QStringLiteral("-2147483648")) + 16);
        field->setMaximumWidth(field->minimumWidth() + 40);
        field->setAlignment(Qt::AlignRight);
        connect(field, &QLineEdit::textEdited, this, [this, name](const QString& t) { edited(name, t); });
        editor = field;
    }
    editor->setEnabled(writable);
    editor->setToolTip(latin(info->description));
    m_editors.insert(name, editor);
    auto* unit = new QLabel(latin(info->units), this);
    unit->setStyleSheet(QStringLiteral("color:#5f6368"));
    const QModelIndex index = m_context.model.indexOf(name, VariableModel::Limits);
    auto* limits = new QLabel(index.data().toString(), this);
    limits->setStyleSheet(QStringLiteral("color:#5f6368"));
    auto* description = new QLabel(latin(info->description).section(QLatin1String(". "), 0, 0), this);
    description->setToolTip(latin(info->description));
    auto* problem = new QLabel(this);
    problem->setStyleSheet(QStringLiteral("color:#b3261e"));
    problem->hide();
    m_problems.insert(name, problem);
    grid->addWidget(label, row, 0);
    grid->addWidget(editor, row, 1);
    grid->addWidget(unit, row, 2);
    grid->addWidget(limits, row, 3);
    grid->addWidget(description, row, 4);
    grid->addWidget(problem, row + 1, 1, 1, 4);
}

void ParameterPage::setPreview(Preview preview) {
    m_previewFunction = std::move(preview);
    m_preview->setVisible(bool(m_previewFunction));
    updatePreview();
}

void ParameterPage::addWidget(QWidget* widget) {
    m_outer->insertWidget(m_outer->indexOf(m_preview), widget);
}

void ParameterPage::readAgain() {
    m_context.sync.readNow(m_names);
}

void ParameterPage::initializePage() {
    m_context.sync.readNow(m_names);
    for (const QString& name : m_names) showRead(name);
}

void ParameterPage::showRead(const QString& name) {
    const QString value = m_context.model.value(name);
    if (value.isEmpty()) return;
    m_context.changes.setOriginal(name, value);
    const QString shown = m_context.changes.valueOf(name);
    QWidget* editor = m_editors.value(name);
    if (auto* box = qobject_cast<QCheckBox*>(editor))
        box->setChecked(shown != QLatin1String("0"));
    else if (auto* field = qobject_cast<QLineEdit*>(editor); field && !field->hasFocus())
        field->setText(shown);
    updatePreview();
}

void ParameterPage::edited(const QString& name, const QString& typed) {
    const VariableValidator::Verdict verdict =
        VariableValidator::check(name, typed, m_context.model.validationContext());
    QLabel* problem = m_problems.value(name);
    problem->setVisible(!verdict.ok);
    problem->setText(verdict.message);
    if (verdict.ok) m_context.changes.setEdited(name, verdict.instruction.section(QLatin1Char(' '), 1));
    updatePreview();
}

QString ParameterPage::text(const QString& name) const {
    QWidget* editor = m_editors.value(name);
    if (auto* box = qobject_cast<QCheckBox*>(editor))
        return box->isChecked() ? QStringLiteral("ON") : QStringLiteral("OFF");
    if (auto* field = qobject_cast<QLineEdit*>(editor)) return field->text();
    return {};
}

void ParameterPage::setText(const QString& name, const QString& typed) {
    QWidget* editor = m_editors.value(name);
    if (auto* box = qobject_cast<QCheckBox*>(editor)) {
        const bool on = typed == QLatin1String("1") || typed.toUpper() == QLatin1String("ON");
        box->setChecked(on);
        edited(name, on ? QStringLiteral("1") : QStringLiteral("0"));
    } else if (auto* field = qobject_cast<QLineEdit*>(editor)) {
        field->setText(typed);
        edited(name, typed);
    }
}

QString ParameterPage::previewText() const {
    return m_preview->text();
}

void ParameterPage::updatePreview() {
    if (!m_previewFunction) return;
    m_preview->setText(m_previewFunction([this](const QString& name) {
        bool ok = false;
        const double v = m_context.changes.valueOf(name).toDouble(&ok);
        return ok ? v : 0.0;
    }));
}

} // namespace app
