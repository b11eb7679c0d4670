// MathChannelDialog: the form, and a preview evaluated on the shown capture at every change.
#include "math_channel_dialog.h"

#include "scope/scope_plot.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace app {

namespace {
using scope::MathOp;

bool twoOperands(MathOp op) {
    return op == MathOp::Sum || op == MathOp::Difference || op == MathOp::FollowingError;
}
} // namespace

MathChannelDialog::MathChannelDialog(const scope::Capture& shown, int room, QWidget* parent)
    : QDialog(parent), m_shown(shown), m_room(room), m_op(new QComboBox(this)), m_a(new QComboBox(this)),
      m_b(new QComboBox(this)), m_k(new QDoubleSpinBox(this)), m_unit(new QLineEdit(this)),
      m_window(new QSpinBox(this)), m_form(new QFormLayout), m_preview(new QLabel(this)),
      m_add(new QPushButton(tr("&Add"), this)) {
    setObjectName(QStringLiteral("mathChannelDialog"));
    setWindowTitle(tr("Math Channel"));
    const std::pair<MathOp, QString> ops[] = {
        {MathOp::Difference, tr("A \u2212 B")},
        {MathOp::Sum, tr("A + B")},
        {MathOp::Scale, tr("k \u00b7 A")},
        {MathOp::Derivative, tr("d/dt A (derivative)")},
        {MathOp::Integral, tr("\u222b A dt (integral)")},
        {MathOp::MovingAverage, tr("Moving average of A")},
        {MathOp::FollowingError, tr("Following error (command \u2212 feedback)")},
    };
    for (const auto& [op, label] : ops) m_op->addItem(label, int(op));
    for (const scope::CaptureChannel& c : shown.channels) {
        const QString name = QString::fromStdString(c.name);
        const QString label = c.unit.empty() ? name : QStringLiteral("%1 [%2]").arg(name, QString::fromStdString(c.unit));
        m_a->addItem(label, name);
        m_b->addItem(label, name);
    }
    if (m_b->count() > 1) m_b->setCurrentIndex(1); // A - B of two different channels to start with
    m_k->setRange(-1e9, 1e9);
    m_k->setDecimals(4);
    m_k->setValue(2);
    m_unit->setPlaceholderText(tr("A's unit"));
    m_unit->setToolTip(tr("The result's unit; leave empty to keep A's (k has no unit)."));
    m_window->setRange(1, 100000);
    m_window->setValue(8);
    m_window->setSuffix(tr(" samples"));
    m_window->setToolTip(tr("Trailing window: each output averages the last N samples, as a drive's filter would."));
    m_preview->setWordWrap(true);
    m_preview->setMinimumWidth(380);
    m_preview->setObjectName(QStringLiteral("mathPreview"));

    m_form->addRow(tr("&Operation:"), m_op);
    m_form->addRow(tr("A:"), m_a);
    m_form->addRow(tr("B:"), m_b);
    m_form->addRow(tr("&k:"), m_k);
    m_form->addRow(tr("&Unit:"), m_unit);
    m_form->addRow(tr("&Window:"), m_window);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    buttons->addButton(m_add, QDialogButtonBox::AcceptRole);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(m_form);
    layout->addWidget(m_preview);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_op, &QComboBox::currentIndexChanged, this, &MathChannelDialog::updateFields);
    for (QComboBox* c : {m_a, m_b}) connect(c, &QComboBox::currentIndexChanged, this, &MathChannelDialog::updatePreview);
    connect(m_k, &QDoubleSpinBox::valueChanged, this, &MathChannelDialog::updatePreview);
    connect(m_unit, &QLineEdit::textChanged, this, &MathChannelDialog::updatePreview);
    connect(m_window, &QSpinBox::valueChanged, this, &MathChannelDialog::updatePreview);
    updateFields();
}

scope::MathChannelSpec MathChannelDialog::spec() const {
    return m_spec;
}

bool MathChannelDialog::canAdd() const {
    return m_ok;
}

QString MathChannelDialog::preview() const {
    return m_preview->text();
}

void MathChannelDialog::choose(MathOp op, const QString& a, const QString& b) {
    m_op->setCurrentIndex(m_op->findData(int(op)));
    m_a->setCurrentIndex(m_a->findData(a));
    if (!b.isEmpty()) m_b->setCurrentIndex(m_b->findData(b));
}

void MathChannelDialog::setFactor(double k) {
    m_k->setValue(k);
}

void MathChannelDialog::setWindow(int samples) {
    m_window->setValue(samples);
}

// Only the fields the operation uses show; following error names its operands for what they are.
void MathChannelDialog::updateFields() {
    const auto op = MathOp(m_op->currentData().toInt());
    const bool fe = op == MathOp::FollowingError;
    auto label = [this](QWidget* field) { return qobject_cast<QLabel*>(m_form->labelForField(field)); };
    label(m_a)->setText(fe ? tr("&Command:") : tr("A:"));
    label(m_b)->setText(fe ? tr("&Feedback:") : tr("&B:"));
    m_form->setRowVisible(m_b, twoOperands(op));
    m_form->setRowVisible(m_k, op == MathOp::Scale);
    m_form->setRowVisible(m_unit, op == MathOp::Scale);
    m_form->setRowVisible(m_window, op == MathOp::MovingAverage);
    updatePreview();
    adjustSize();
}

void MathChannelDialog::updatePreview() {
    scope::MathChannelSpec s;
    s.op = MathOp(m_op->currentData().toInt());
    s.a = m_a->currentData().toString().toStdString();
    s.b = m_b->currentData().toString().toStdString();
    s.k = m_k->value();
    if (!m_unit->text().trimmed().isEmpty()) s.unit = m_unit->text().trimmed().toStdString();
    s.window = std::size_t(m_window->value());
    const scope::CaptureMath r = scope::evaluate(m_shown, s);
    QString why;
    if (m_shown.channels.empty()) {
        why = tr("There is no capture to compute from: record or open one first.");
    } else if (m_room <= 0) {
        why = tr("The plot shows at most %1 channels: remove a math channel first.").arg(scope::ScopePlot::kMaxChannels);
    } else if (!r.ok()) {
        why = QString::fromStdString(r.error) + QLatin1Char('.');
        if (r.status == scope::MathStatus::UnitMismatch && s.op == MathOp::FollowingError)
            why += tr(" A following error compares a command with its own feedback: choose two channels in the "
                      "same unit.");
        else if (r.status == scope::MathStatus::UnitMismatch)
            why += tr(" Only channels in the same unit can be added or subtracted.");
    } else if (m_shown.find(r.channel.name)) {
        why = tr("%1 is shown already.").arg(QString::fromStdString(r.channel.name));
    }
    m_ok = why.isEmpty();
    if (m_ok) {
        s.name = r.channel.name;
        m_spec = s;
        const QString unit = QString::fromStdString(r.channel.unit);
        m_preview->setText(tr("New channel: %1 [%2]")
                               .arg(QString::fromStdString(r.channel.name), unit.isEmpty() ? tr("no unit") : unit));
        m_preview->setStyleSheet(QString());
    } else {
        m_preview->setText(tr("Cannot add: %1").arg(why));
        m_preview->setStyleSheet(QStringLiteral("color: #b00020;"));
    }
    m_add->setEnabled(m_ok);
}

} // namespace app
