// WatchSource: how the polled rolling chart (Scope > Watch Variables) reads a handful of values from one
// drive family — the BDS5 prints them with P, the SC750 answers a G frame per variable, the PMC-960 answers
// its out-of-band status polls. VariableWatcher asks for one sample at a time and paces itself on the
// answers; the source knows the family's names, units and when its link can take a poll. GUI thread only.
//
//   source.poll({"POSITION", "VELOCITY"});   // later: answered({1024, 30.5}) or failed("...", stop)
#pragma once

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>

namespace app {

class WatchSource : public QObject {
    Q_OBJECT
public:
    struct Choice {
        QString name;  // what poll() takes: "VFB", "POS.ERROR", "f"
        QString label; // what the chooser and the legend show: "Following error (SF!)"
        QString unit;  // "" when the value has none
    };

    using QObject::QObject;

    virtual QString familyName() const = 0; // "BDS5", "SC750", "PMC-960"
    virtual QList<Choice> choices() const = 0;
    // For the chooser's tooltip: how a sample is read ("P polls them as fast as the link answers").
    virtual QString method() const = 0;
    // Why no poll may go out now ("not connected", "a download is under way"), or empty when one may.
    virtual QString notReady() const = 0;
    // Reads one value for each name, in order: exactly one of answered() or failed() follows, unless
    // cancel() comes first.
    virtual void poll(const QStringList& names) = 0;
    // Forget the poll in flight: its answer, if any, is dropped.
    virtual void cancel() = 0;
    // The shortest time from one poll to the next: room on the link for the family's other polls.
    virtual int minimumIntervalMs() const { return 0; }

    std::optional<Choice> choice(const QString& name) const;

    // A value as a drive prints it: a number, or ON/OFF as 1/0.
    static std::optional<double> number(const QString& word);

signals:
    // One value per name; an empty list when this answer held no usable sample (a garbled line): the
    // watcher polls again.
    void answered(const QList<double>& values);
    // stopWatching: the drive refused the names (watching them again would fail the same way).
    void failed(const QString& reason, bool stopWatching);
};

} // namespace app
