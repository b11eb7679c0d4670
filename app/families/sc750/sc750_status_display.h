// Sc750StatusDisplay: the SC750's front-panel status display in the status bar (seed-sc750 §6.1) — the red
// seven-segment digit showing FAULTCODE's display character from the catalog ("F 4" and "U C" alternating),
// its decimal point lit while a program runs, and the code's meaning beside it. Fed only by the controller's
// status answers (`?`, PROTOCOL.md §4): polled every kPollMs while the line is free, at least every
// kQuietMs when other traffic keeps it busy, and at once when a program event arrives. GUI thread only.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>

class QLabel;

namespace app {

class Sc750SevenSegment;
class Sc750Workspace;

class Sc750StatusDisplay final : public QWidget {
    Q_OBJECT
public:
    static constexpr int kPollMs = 250;   // a status request at most this often
    static constexpr int kQuietMs = 1000; // ... and at least this often, even between other commands
    static constexpr int kLostMs = 5000;  // an unanswered request older than this is given up

    explicit Sc750StatusDisplay(Sc750Workspace& workspace, QWidget* parent = nullptr);

    Sc750SevenSegment* digit() const { return m_digit; }
    QString meaning() const; // the text beside the digit: "No fault, enabled", "Run time error"
    // The controller model from V ("752"): the meaning of codes 5, 7, 9, 10, 13 differs by model.
    void setModel(const QString& model);

private:
    void tick();
    void request();
    void show(const QString& payload);
    void showDisconnected();

    Sc750Workspace& m_workspace;
    Sc750SevenSegment* m_digit;
    QLabel* m_meaning;
    QTimer m_poll;
    QElapsedTimer m_sinceAnswer;
    QElapsedTimer m_sinceRequest;
    QString m_model;
    QString m_lastPayload;
    bool m_asking = false; // a `?` is on its way
};

} // namespace app
