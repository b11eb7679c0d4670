// Sc750SevenSegment: one red seven-segment digit with its decimal point, drawn like the SC750's front-panel
// status display (seed-sc750 §6.1). Given more than one character ("F4", "UC") it shows them in turn, the
// manual's "alternate (flash) between the two characters". A painted widget; GUI thread only.
#pragma once

#include <QTimer>
#include <QTransform>
#include <QWidget>

namespace app {

class Sc750SevenSegment final : public QWidget {
    Q_OBJECT
public:
    // Each character of a flashing code stays lit this long (the manual gives no rate: DECISIONS 45).
    static constexpr int kFlashMs = 600;

    explicit Sc750SevenSegment(QWidget* parent = nullptr);

    // The characters to show, in turn when more than one; spaces are ignored ("F 4" = "F4"). Empty = dark.
    void setCharacters(const QString& characters);
    QString characters() const { return m_characters; }
    void setDecimalPoint(bool lit);
    bool decimalPoint() const { return m_decimalPoint; }
    // The character lit now, or a null QChar when dark.
    QChar shown() const;
    // The segments lit now: bit 0 = a (top), 1 = b, 2 = c, 3 = d (bottom), 4 = e, 5 = f, 6 = g (middle).
    int litSegments() const { return segmentsOf(shown()); }
    // The segment pattern of a display character (0-9, A b c d E F, U C P S -); 0 for others.
    static int segmentsOf(QChar c);

    // Where the decimal point is painted, in widget coordinates.
    QRectF decimalPointRect() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QTransform digitTransform() const; // digit units to widget pixels

    QString m_characters;
    int m_index = 0;
    bool m_decimalPoint = false;
    QTimer m_flash;
};

} // namespace app
