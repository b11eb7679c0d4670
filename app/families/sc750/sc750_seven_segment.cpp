// Sc750SevenSegment: segment patterns, the flash timer and the painting.
#include "sc750_seven_segment.h"

#include <QPainter>

#include <algorithm>
#include <array>

namespace app {

namespace {
// Digit geometry in its own units: the segments' outer edges span kWidth x kHeight, kStroke thick, kGap
// apart at the joints; the decimal point sits right of the bottom-right corner. Slanted like the LED part.
constexpr double kWidth = 10, kHeight = 18, kStroke = 2.4, kGap = 0.45, kSlant = 0.12;
const QPointF kPoint(kWidth + 1.6 * kStroke, kHeight); // the decimal point's centre
constexpr double kPointRadius = kStroke * 0.62;
const QColor kBezel(0x1b, 0x12, 0x12);
const QColor kLit(0xff, 0x30, 0x1e);
const QColor kDark(0x45, 0x1a, 0x16); // an unlit segment glows faintly, as on the real display

QPolygonF horizontal(double cx, double cy, double length) {
    const double h = kStroke / 2, x0 = cx - length / 2, x1 = cx + length / 2;
    return QPolygonF({{x0, cy}, {x0 + h, cy - h}, {x1 - h, cy - h}, {x1, cy}, {x1 - h, cy + h}, {x0 + h, cy + h}});
}

QPolygonF vertical(double cx, double cy, double length) {
    const double h = kStroke / 2, y0 = cy - length / 2, y1 = cy + length / 2;
    return QPolygonF({{cx, y0}, {cx + h, y0 + h}, {cx + h, y1 - h}, {cx, y1}, {cx - h, y1 - h}, {cx - h, y0 + h}});
}

// a b c d e f g, centre lines on the digit's outline.
std::array<QPolygonF, 7> segmentShapes() {
    const double across = kWidth - 2 * kGap, down = kHeight / 2 - 2 * kGap;
    return {horizontal(kWidth / 2, 0, across),          vertical(kWidth, kHeight / 4, down),
            vertical(kWidth, 3 * kHeight / 4, down),    horizontal(kWidth / 2, kHeight, across),
            vertical(0, 3 * kHeight / 4, down),         vertical(0, kHeight / 4, down),
            horizontal(kWidth / 2, kHeight / 2, across)};
}
} // namespace

Sc750SevenSegment::Sc750SevenSegment(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred);
    m_flash.setInterval(kFlashMs);
    connect(&m_flash, &QTimer::timeout, this, [this] {
        m_index = (m_index + 1) % int(m_characters.size());
        update();
    });
}

void Sc750SevenSegment::setCharacters(const QString& characters) {
    QString wanted = characters;
    wanted.remove(QLatin1Char(' '));
    if (wanted == m_characters) return;
    m_characters = wanted;
    m_index = 0;
    if (m_characters.size() > 1)
        m_flash.start(); // restarts: the first character gets its full time
    else
        m_flash.stop();
    update();
}

void Sc750SevenSegment::setDecimalPoint(bool lit) {
    if (lit == m_decimalPoint) return;
    m_decimalPoint = lit;
    update();
}

QChar Sc750SevenSegment::shown() const {
    return m_characters.isEmpty() ? QChar() : m_characters.at(m_index % m_characters.size());
}

int Sc750SevenSegment::segmentsOf(QChar c) {
    switch (c.unicode()) {
    case '0': return 0x3F;
    case '1': return 0x06;
    case '2': return 0x5B;
    case '3': return 0x4F;
    case '4': return 0x66;
    case '5':
    case 'S': return 0x6D;
    case '6': return 0x7D;
    case '7': return 0x07;
    case '8': return 0x7F;
    case '9': return 0x6F;
    case 'A': return 0x77;
    case 'b': return 0x7C;
    case 'c': return 0x58;
    case 'C': return 0x39;
    case 'd': return 0x5E;
    case 'E': return 0x79;
    case 'F': return 0x71;
    case 'P': return 0x73;
    case 'U': return 0x3E;
    case '-': return 0x40;
    default: return 0;
    }
}

QSize Sc750SevenSegment::sizeHint() const {
    return {24, 32};
}

QSize Sc750SevenSegment::minimumSizeHint() const {
    return {15, 20};
}

void Sc750SevenSegment::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(kBezel);
    const QRectF box = QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5);
    p.drawRoundedRect(box, 3, 3);
    p.setTransform(digitTransform());
    const int lit = litSegments();
    const auto shapes = segmentShapes();
    for (int s = 0; s < 7; ++s) {
        p.setBrush((lit >> s) & 1 ? kLit : kDark);
        p.drawPolygon(shapes[std::size_t(s)]);
    }
    p.setBrush(m_decimalPoint ? kLit : kDark);
    p.drawEllipse(kPoint, kPointRadius, kPointRadius);
}

QTransform Sc750SevenSegment::digitTransform() const {
    // Fit the digit and its decimal point into the bezel with a margin, keeping their proportions. The span
    // runs from the bottom-left segment's edge to the decimal point's right edge (the slant cancels out).
    const QRectF box = QRectF(rect()).adjusted(3, 3, -3, -3);
    const double spanX = kPoint.x() + kPointRadius + kStroke / 2, spanY = kHeight + kStroke;
    const double scale = std::min(box.width() / spanX, box.height() / spanY);
    QTransform t;
    t.translate(box.center().x() - scale * spanX / 2 + scale * (kStroke / 2 + kSlant * kHeight),
                box.center().y() - scale * spanY / 2 + scale * kStroke / 2);
    t.scale(scale, scale);
    return QTransform(1, 0, -kSlant, 1, 0, 0) * t; // lean right, about the top edge
}

QRectF Sc750SevenSegment::decimalPointRect() const {
    return digitTransform().mapRect(
        QRectF(kPoint.x() - kPointRadius, kPoint.y() - kPointRadius, 2 * kPointRadius, 2 * kPointRadius));
}

} // namespace app
