// Bds5PlayListing: puts the BDS5's PLAY listing together from several copies read over a wire that may drop
// and corrupt bytes, so that the scope gets the drive's exact samples or an error, never shifted or altered
// data. Pure logic, no I/O; Bds5RecordPlay feeds it one copy per PLAY.
//
// The listing (drive_core/bds5/bds5_recorder.h) is a header "RECORD <n> <t> <v1> [v2 v3 v4]" and one line per
// sample, each value an integer right-justified in 12 columns. A copy is anchored at its header (first line,
// or second after a damaged echo; a few characters of it may be damaged, but the exact header must come
// through twice before the listing is accepted, so a recording set up differently is never taken for the
// one asked for); sample lines are numbered by counting line ends, and a damaged
// stretch (a line of the wrong length, e.g. two lines run together when a CR LF was lost) counts for as many
// lines as its length spans, so the lines after it keep their places. A copy whose count then differs from
// <n> keeps only the lines before its first damaged stretch. Only a line of exactly the right length is
// read, field by field, and a field counts only when it is exactly what the drive prints for some value.
// A value is accepted when two undamaged copies agree on it and no copy reads it otherwise, or when at
// least three copies agree and outnumber every other reading two to one (a bit flip can turn one digit into
// another, so two damaged copies may agree by chance; three practically never do).
// On a link that has shown no damage (setTrustCleanCopy), a first copy without any damage is accepted alone:
// what a clean copy could still hide is a byte changed into another digit with nothing else touched, which a
// wire that damages nothing else practically never does; the first damaged or lost copy ends the trust.
#pragma once

#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <vector>

namespace serialport {

class Bds5PlayListing {
public:
    // header: the RECORD line the drive is expected to print (upper case, single spaces); samples: <n>;
    // variables: 1-4.
    Bds5PlayListing(QString header, int samples, int variables);

    // text: what the drive sent after the PLAY echo up to its prompt (Bds5Response::text);
    // echoDamaged: Bds5Response::garbled.
    void addCopy(const QString& text, bool echoDamaged);
    void addLostCopy() { ++m_lost; } // the PLAY or its answer was lost on the wire
    void setTrustCleanCopy(bool trust) { m_trustClean = trust; } // before the first addCopy

    bool complete() const;
    QStringList lines() const; // header + samples, as the drive printed them; only when complete()
    // A RECORD line three copies agree on, the one asked for never seen: the drive records something else
    // (the RECORD command was damaged on its way).
    std::optional<QString> otherHeader() const;

    int copies() const { return m_copies; }
    int damagedCopies() const { return m_damaged; }
    int lostCopies() const { return m_lost; }
    int samplesAgreed() const; // samples whose every value is agreed
    int samples() const { return m_samples; }

private:
    struct Reading {
        int all = 0;   // copies that read the field so
        int clean = 0; // of them, copies without any damage
    };
    using Votes = std::map<QString, Reading>;
    bool validField(const QString& field) const;
    bool decided(const Votes& votes) const;
    bool headerConfirmed() const;
    int cleanCopiesNeeded() const { return m_trustClean && m_damaged == 0 && m_lost == 0 ? 1 : 2; }

    QString m_header;
    int m_samples;
    int m_variables;
    int m_width;                // characters of a sample line
    std::vector<Votes> m_votes; // per sample x variable
    std::vector<bool> m_done;
    std::map<QString, int> m_headers; // RECORD lines read where the header belongs
    int m_agreed = 0;
    int m_copies = 0;
    int m_damaged = 0;
    int m_lost = 0;
    bool m_trustClean = false;
};

} // namespace serialport
