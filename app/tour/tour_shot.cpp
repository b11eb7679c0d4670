// TourShot: grabbing widgets into one picture while remembering where each one went.
#include "tour_shot.h"

#include <QApplication>
#include <QPainter>

namespace app {

TourShot TourShot::of(QWidget* widget) {
    if (!widget) return {};
    return {.picture = widget->grab(), .layers = {{widget, QPoint(0, 0)}}};
}

TourShot TourShot::withPopups(QWidget* window) {
    TourShot shot = of(window);
    if (!window) return shot;
    for (QWidget* top : QApplication::topLevelWidgets()) {
        if (top == window || !top->isVisible()) continue;
        const Qt::WindowType type = top->windowType();
        if (type != Qt::ToolTip && type != Qt::Popup) continue;
        shot.paintOver(top, window->mapFromGlobal(top->mapToGlobal(QPoint(0, 0))));
    }
    return shot;
}

void TourShot::paintOver(QWidget* widget, QPoint at) {
    if (!widget) return;
    QPainter painter(&picture);
    painter.drawPixmap(at, widget->grab());
    layers.push_back({widget, at});
}

TourShot TourShot::cropped(const QRect& area) const {
    const qreal ratio = picture.devicePixelRatio();
    const QRect pixels(area.topLeft() * ratio, area.size() * ratio);
    TourShot part{.picture = picture.copy(pixels), .layers = layers};
    for (Layer& layer : part.layers) layer.at -= area.topLeft();
    return part;
}

} // namespace app
