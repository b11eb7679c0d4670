// InfoBar: a strip over the editor tabs with an icon, a message and two answers — the non-modal question the
// editor asks (crash recovery, a file changed on disk). The IDE stays usable while it is shown. GUI thread only.
#pragma once

#include <QFrame>
#include <QStyle>

class QLabel;
class QPushButton;

namespace app {

class InfoBar : public QFrame {
    Q_OBJECT
public:
    struct Look {
        QString name; // object name, and the style sheet's selector
        QStyle::StandardPixmap icon;
        QString background;  // colours of the strip and its lower border
        QString border;
    };
    InfoBar(const Look& look, const QString& first, const QString& second, QWidget* parent);

    QString message() const;

protected:
    void showMessage(const QString& html);
    QPushButton* first() const { return m_first; }
    QPushButton* second() const { return m_second; }

private:
    QLabel* m_text;
    QPushButton* m_first;
    QPushButton* m_second;
};

} // namespace app
