// InfoBar: layout.
#include "info_bar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace app {

InfoBar::InfoBar(const Look& look, const QString& first, const QString& second, QWidget* parent)
    : QFrame(parent), m_text(new QLabel(this)), m_first(new QPushButton(first, this)),
      m_second(new QPushButton(second, this)) {
    setObjectName(look.name);
    setStyleSheet(QStringLiteral("#%1 { background: %2; border-bottom: 1px solid %3; }")
                      .arg(look.name, look.background, look.border));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::RichText);
    auto* icon = new QLabel(this);
    icon->setPixmap(style()->standardIcon(look.icon).pixmap(24, 24));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 10, 6);
    layout->addWidget(icon);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_first);
    layout->addWidget(m_second);
    hide();
}

QString InfoBar::message() const {
    return m_text->text();
}

void InfoBar::showMessage(const QString& html) {
    m_text->setText(html);
    show();
}

} // namespace app
