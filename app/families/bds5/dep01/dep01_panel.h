// Dep01Panel: Motion Link's "Run DEP01 simulator" — a DEP-01 Data Entry Panel on the drive's serial line:
// a 2 x 40 display of what the drive sends (Dep01Screen) and a keypad whose keys send their characters,
// ENTER a CR and ATTN a ^V (fires the drive's VARIABLE$ task, L4818). GUI thread.
#pragma once

#include "dep01_screen.h"

#include <QDockWidget>

class QCheckBox;
class QLabel;
class QPushButton;

namespace app {

class DriveConnection;

class Dep01Panel final : public QDockWidget {
    Q_OBJECT
public:
    explicit Dep01Panel(DriveConnection& connection, QWidget* parent = nullptr);

    const Dep01Screen& screen() const { return m_screen; }
    // The keypad key with this label ("7", "ENTER", "ATTN"), as a user clicks it.
    QPushButton* key(const QString& label) const;
    QCheckBox* depSwitch() const { return m_depSwitch; }
    void clearDisplay();

private:
    QWidget* makeKeypad();
    void onBytes(const QByteArray& bytes);
    void press(const QByteArray& bytes);
    void render();

    DriveConnection& m_connection;
    Dep01Screen m_screen;
    QLabel* m_display;
    QCheckBox* m_depSwitch;
    QList<QPushButton*> m_keys;
};

} // namespace app
