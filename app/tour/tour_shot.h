// TourShot: what a screenshot-tour step saves — the picture, and the widgets painted into it with where each
// one's top-left corner lies in the picture, so that what the picture shows can be read from the widget tree
// (ShotFacts) at the moment of the grab. GUI thread only.
#pragma once

#include <QPixmap>
#include <QPoint>
#include <QPointer>
#include <QRect>
#include <QWidget>

#include <vector>

namespace app {

struct TourShot {
    struct Layer {
        QPointer<QWidget> widget;
        QPoint at; // the widget's (0,0) in the picture, logical pixels (the picture's device-independent size)
    };

    QPixmap picture;
    std::vector<Layer> layers; // bottom first: a later layer was painted over the earlier ones

    // The widget as grab() paints it, one layer at (0,0); an empty shot (no picture) for a null widget.
    static TourShot of(QWidget* widget);
    // A window with its visible tool-tip and popup windows (help, completion list) painted where they are.
    static TourShot withPopups(QWidget* window);
    bool isNull() const { return picture.isNull(); }
    // Paints widget->grab() over the picture at `at` (logical pixels) and adds its layer.
    void paintOver(QWidget* widget, QPoint at);
    // The part of the picture inside `area` (logical pixels); the layers move with it.
    TourShot cropped(const QRect& area) const;
};

} // namespace app
