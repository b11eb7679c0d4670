// Dep01Panel: display and keypad over the drive connection.
#include "dep01_panel.h"

#include "families/bds5/drive_connection.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace app {

namespace {
constexpr char kAttention = '\x16'; // ^V
}

Dep01Panel::Dep01Panel(DriveConnection& connection, QWidget* parent)
    : QDockWidget(tr("DEP-01 Panel"), parent), m_connection(connection) {
    setObjectName(QStringLiteral("dep01Panel"));
    auto* body = new QWidget(this);
    body->setStyleSheet(QStringLiteral("QWidget#dep01Body{background:#3c4043;border-radius:8px}"));
    body->setObjectName(QStringLiteral("dep01Body"));
    auto* layout = new QVBoxLayout(body);
    m_display = new QLabel(body);
    m_display->setTextFormat(Qt::PlainText);
    QFont font(QStringLiteral("monospace"));
    font.setStyleHint(QFont::Monospace);
    font.setPointSize(13);
    font.setBold(true);
    m_display->setFont(font);
    m_display->setStyleSheet(QStringLiteral(
        "QLabel{background:#a8c66c;color:#1d2a0f;border:6px solid #202124;border-radius:4px;padding:8px}"));
    layout->addWidget(m_display);
    layout->addWidget(makeKeypad());
    m_depSwitch = new QCheckBox(tr("Drive's DEP switch (errors cut to 40 characters)"), body);
    m_depSwitch->setStyleSheet(QStringLiteral("color:white"));
    layout->addWidget(m_depSwitch);
    layout->addStretch(1);
    setWidget(body);
    connect(&m_connection, &DriveConnection::rawReceived, this, &Dep01Panel::onBytes);
    connect(m_depSwitch, &QCheckBox::toggled, this,
            [this](bool on) { m_connection.sendCommand(on ? QStringLiteral("DEP 1") : QStringLiteral("DEP 0")); });
    render();
}

QWidget* Dep01Panel::makeKeypad() {
    auto* pad = new QWidget(this);
    auto* grid = new QGridLayout(pad);
    grid->setSpacing(6);
    struct Key {
        QString label;
        QByteArray bytes;
        int row, column, span;
    };
    const QList<Key> keys{
        {QStringLiteral("7"), "7", 0, 0, 1}, {QStringLiteral("8"), "8", 0, 1, 1},
        {QStringLiteral("9"), "9", 0, 2, 1}, {QStringLiteral("ATTN"), QByteArray(1, kAttention), 0, 3, 1},
        {QStringLiteral("4"), "4", 1, 0, 1}, {QStringLiteral("5"), "5", 1, 1, 1},
        {QStringLiteral("6"), "6", 1, 2, 1}, {QStringLiteral("CLR"), "\b", 1, 3, 1},
        {QStringLiteral("1"), "1", 2, 0, 1}, {QStringLiteral("2"), "2", 2, 1, 1},
        {QStringLiteral("3"), "3", 2, 2, 1}, {QStringLiteral("ENTER"), "\r", 2, 3, 2},
        {QStringLiteral("-"), "-", 3, 0, 1}, {QStringLiteral("0"), "0", 3, 1, 1},
        {QStringLiteral("."), ".", 3, 2, 1},
    };
    for (const Key& k : keys) {
        auto* button = new QPushButton(k.label, pad);
        button->setMinimumSize(56, 40);
        button->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding);
        const bool special = k.label.size() > 1;
        button->setStyleSheet(special ? QStringLiteral("QPushButton{background:#d93025;color:white;font-weight:bold;"
                                                       "border-radius:6px}")
                                      : QStringLiteral("QPushButton{background:#f1f3f4;font-weight:bold;font-size:14pt;"
                                                       "border-radius:6px}"));
        if (k.label == QLatin1String("ENTER"))
            button->setStyleSheet(
                QStringLiteral("QPushButton{background:#1a73e8;color:white;font-weight:bold;border-radius:6px}"));
        button->setToolTip(k.label == QLatin1String("ATTN") ? tr("Sends ^V: runs the drive's VARIABLE$ task")
                                                            : QString());
        grid->addWidget(button, k.row, k.column, k.span, 1);
        const QByteArray bytes = k.bytes;
        connect(button, &QPushButton::clicked, this, [this, bytes] { press(bytes); });
        m_keys << button;
    }
    return pad;
}

QPushButton* Dep01Panel::key(const QString& label) const {
    for (QPushButton* button : m_keys)
        if (button->text() == label) return button;
    return nullptr;
}

void Dep01Panel::press(const QByteArray& bytes) {
    m_connection.sendRaw(bytes); // the panel is a terminal on the drive's line, as the real DEP-01 is
}

void Dep01Panel::clearDisplay() {
    m_screen.clear();
    render();
}

void Dep01Panel::onBytes(const QByteArray& bytes) {
    m_screen.feed(bytes);
    render();
}

void Dep01Panel::render() {
    m_display->setText(m_screen.line(0) + QLatin1Char('\n') + m_screen.line(1));
}

} // namespace app
