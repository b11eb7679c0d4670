// XyPlot: one channel of a capture against another (following error against velocity, current against
// position) — two channel choosers over a QCustomPlot curve drawn in sample order, its axes titled with the
// channels' names and units. The Scope dock shows it as its XY tab. GUI thread only.
#pragma once

#include "capture.h"

#include <QWidget>

class QCPCurve;
class QComboBox;
class QCustomPlot;

namespace scope {

class XyPlot final : public QWidget {
    Q_OBJECT
public:
    explicit XyPlot(QWidget* parent = nullptr);

    // Shows the capture; the chosen channels stay chosen when the new one has them (by name).
    void showCapture(const Capture& capture);
    // Channel indices into the capture; out-of-range choices are ignored.
    void setChannels(int xChannel, int yChannel);
    int xChannel() const;
    int yChannel() const;

    QCustomPlot* customPlot() const { return m_plot; }
    QCPCurve* curve() const { return m_curve; }
    QComboBox* xChooser() const { return m_x; }
    QComboBox* yChooser() const { return m_y; }

private:
    void replot();

    QComboBox* m_x;
    QComboBox* m_y;
    QCustomPlot* m_plot;
    QCPCurve* m_curve;
    Capture m_capture;
};

} // namespace scope
