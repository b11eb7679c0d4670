// HelpPopup: a rich-text label in a bordered tool-tip window, placed on the screen.
#include "help_popup.h"

#include <QGuiApplication>
#include <QLabel>
#include <QScreen>
#include <QVBoxLayout>

namespace editor {

HelpPopup::HelpPopup(QWidget* parent)
    : QFrame(parent, Qt::ToolTip | Qt::FramelessWindowHint), m_label(new QLabel(this)) {
    setObjectName(QStringLiteral("bds5HelpPopup"));
    setAttribute(Qt::WA_ShowWithoutActivating);
    setFrameShape(QFrame::Box);
    setAutoFillBackground(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(10, 8, 10, 8);
    m_label->setTextFormat(Qt::RichText);
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::NoTextInteraction);
    layout->addWidget(m_label);
    setDarkTheme(false);
}

void HelpPopup::setDarkTheme(bool dark) {
    // Colours by palette, for the frame, its border and the label alike.
    QPalette palette = this->palette();
    const QColor paper = dark ? QColor(0x25, 0x25, 0x26) : QColor(0xfb, 0xfc, 0xfd);
    const QColor ink = dark ? QColor(0xd4, 0xd4, 0xd4) : QColor(0x1f, 0x23, 0x28);
    for (const QPalette::ColorRole role : {QPalette::Window, QPalette::ToolTipBase, QPalette::Base})
        palette.setColor(role, paper);
    for (const QPalette::ColorRole role : {QPalette::WindowText, QPalette::ToolTipText, QPalette::Text})
        palette.setColor(role, ink);
    palette.setColor(QPalette::Light, dark ? QColor(0x45, 0x45, 0x45) : QColor(0xc8, 0xd1, 0xda));
    palette.setColor(QPalette::Dark, dark ? QColor(0x45, 0x45, 0x45) : QColor(0xc8, 0xd1, 0xda));
    palette.setColor(QPalette::Mid, dark ? QColor(0x45, 0x45, 0x45) : QColor(0xc8, 0xd1, 0xda));
    setPalette(palette);
    m_label->setPalette(palette);
}

void HelpPopup::showHtml(const QString& html, const QPoint& global, int avoidTop) {
    m_label->setText(html);
    m_label->setFixedWidth(kMaxWidth - 20);
    adjustSize();
    QPoint at = global;
    if (const QScreen* screen = QGuiApplication::screenAt(global)) {
        const QRect area = screen->availableGeometry();
        if (at.y() + height() > area.bottom()) at.setY(avoidTop - height());
        at.setX(qBound(area.left(), at.x(), area.right() - width()));
        at.setY(qMax(area.top(), at.y()));
    }
    move(at);
    show();
}

QString HelpPopup::html() const {
    return m_label->text();
}

} // namespace editor
