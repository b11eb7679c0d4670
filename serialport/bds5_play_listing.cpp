// Bds5PlayListing: PLAY copies in, agreed samples out.
#include "bds5_play_listing.h"

#include <algorithm>
#include <limits>

namespace serialport {

namespace {
constexpr int kFieldWidth = 12;  // as P prints a value (bds5_printer formatValue)
constexpr int kHeaderDamage = 3; // dropped or changed characters a header line may show and still anchor

// How many characters of expected were dropped or changed to give received (the wire drops and flips
// bytes but adds none within a line); a large number when received cannot come from expected so.
int damage(const QString& expected, const QString& received) {
    const qsizetype n = expected.size(), m = received.size();
    if (m > n) return std::numeric_limits<int>::max();
    // cost[j]: received[0, j) from expected[0, i), over i.
    std::vector<int> cost(std::size_t(m + 1), std::numeric_limits<int>::max() / 2);
    cost[0] = 0;
    for (qsizetype i = 1; i <= n; ++i)
        for (qsizetype j = std::min(i, m); j >= 0; --j) {
            const int drop = cost[std::size_t(j)] + 1;
            const int keep = j > 0 ? cost[std::size_t(j - 1)] + (expected[i - 1] != received[j - 1]) : drop;
            cost[std::size_t(j)] = std::min(drop, keep);
        }
    return cost[std::size_t(m)];
}
} // namespace

Bds5PlayListing::Bds5PlayListing(QString header, int samples, int variables)
    : m_header(std::move(header)), m_samples(std::max(0, samples)), m_variables(std::clamp(variables, 1, 4)),
      m_width(kFieldWidth * m_variables), m_votes(std::size_t(m_samples * m_variables)), m_done(m_votes.size(), false) {
}

// Exactly what the drive prints for some 32-bit value: right-justified in 12 columns, no '+', no leading 0.
bool Bds5PlayListing::validField(const QString& field) const {
    if (field.size() != kFieldWidth) return false;
    bool ok = false;
    const qlonglong value = field.trimmed().toLongLong(&ok);
    if (!ok || value < std::numeric_limits<qint32>::min() || value > std::numeric_limits<qint32>::max()) return false;
    return QString::number(value).rightJustified(kFieldWidth) == field;
}

bool Bds5PlayListing::decided(const Votes& votes) const {
    const Reading* best = nullptr;
    for (const auto& [text, reading] : votes)
        if (!best || reading.all > best->all) best = &reading;
    if (!best) return false;
    int second = 0;
    for (const auto& [text, reading] : votes)
        if (&reading != best) second = std::max(second, reading.all);
    return (best->clean >= cleanCopiesNeeded() && second == 0) || (best->all >= 3 && best->all >= 2 * second + 1);
}

void Bds5PlayListing::addCopy(const QString& text, bool echoDamaged) {
    ++m_copies;
    QStringList chunks = text.split(QStringLiteral("\r\n"));
    if (!chunks.isEmpty() && chunks.last().isEmpty()) chunks.removeLast(); // the text ends with CR LF
    // The header is the first line, or the second after a damaged echo ("PLY", "-->PLAY"): a line that
    // differs from the expected one by at most kHeaderDamage dropped or changed characters.
    qsizetype at = -1;
    for (qsizetype i = 0; i < std::min<qsizetype>(2, chunks.size()) && at < 0; ++i) {
        if (i == 1 && chunks[0].size() >= kFieldWidth - kHeaderDamage) break; // chunk 0 held data
        if (damage(m_header, chunks[i]) <= kHeaderDamage) at = i;
        if (at >= 0 || chunks[i].startsWith(QLatin1String("RECORD "))) ++m_headers[chunks[i]];
    }
    if (at < 0) {
        ++m_damaged; // no anchor: nothing in this copy can be placed
        return;
    }

    struct Field {
        int index;
        QString text;
    };
    std::vector<Field> fields;
    bool damaged = echoDamaged || at > 0 || chunks[at] != m_header;
    std::optional<std::size_t> beforeDamage; // fields read before the first stretch of the wrong length
    int line = 0;
    for (qsizetype c = at + 1; c < chunks.size() && line < m_samples; ++c) {
        const QString& chunk = chunks[c];
        const bool whole = chunk.size() == m_width;
        // A line of the right length has every field in its place. In a damaged stretch the fields before
        // the first damage still are, and no field after it can pass for one: once a byte is lost each
        // window holds the end of one value and the leading blank of the next (or the line end).
        for (int v = 0; v < m_variables; ++v) {
            const QString field = chunk.mid(v * kFieldWidth, kFieldWidth);
            if (validField(field)) {
                fields.push_back({line * m_variables + v, field});
                continue;
            }
            damaged = true;
            if (!whole) break;
        }
        if (whole) {
            ++line;
            continue;
        }
        damaged = true;
        if (!beforeDamage) beforeDamage = fields.size();
        // Lines run together keep their CR or LF (one character) or lost both: the length tells how many.
        line += std::max(1, qRound(double(chunk.size() + 2) / double(m_width + 2)));
    }
    if (line > m_samples || chunks.size() > at + 1 + m_samples) damaged = true;
    if (beforeDamage && line != m_samples) fields.resize(*beforeDamage); // the count does not add up
    if (damaged) ++m_damaged;

    for (const Field& f : fields) {
        Reading& r = m_votes[std::size_t(f.index)][f.text];
        ++r.all;
        r.clean += !damaged;
    }
    m_agreed = 0;
    for (std::size_t i = 0; i < m_votes.size(); ++i) {
        m_done[i] = decided(m_votes[i]);
        m_agreed += m_done[i];
    }
}

QStringList Bds5PlayListing::lines() const {
    if (!complete()) return {};
    QStringList out{m_header};
    for (int s = 0; s < m_samples; ++s) {
        QString line;
        for (int v = 0; v < m_variables; ++v) {
            const Votes& votes = m_votes[std::size_t(s * m_variables + v)];
            const auto best = std::max_element(
                votes.begin(), votes.end(), [](const auto& a, const auto& b) { return a.second.all < b.second.all; });
            line += best->first;
        }
        out << line;
    }
    return out;
}

bool Bds5PlayListing::complete() const {
    return m_agreed == m_samples * m_variables && headerConfirmed();
}

// The drive printed exactly the RECORD line asked for, twice (once on a trusted clean link), and more often than any other reading of it
// (a RECORD damaged on its way may have set up a recording that differs in one digit, e.g. 3 ms for 1 ms).
bool Bds5PlayListing::headerConfirmed() const {
    const auto exact = m_headers.find(m_header);
    if (exact == m_headers.end() || exact->second < cleanCopiesNeeded()) return false;
    for (const auto& [header, count] : m_headers)
        if (header != m_header && count >= exact->second) return false;
    return true;
}

std::optional<QString> Bds5PlayListing::otherHeader() const {
    if (m_headers.count(m_header)) return std::nullopt;
    for (const auto& [header, count] : m_headers)
        if (count >= 3) return header;
    return std::nullopt;
}

int Bds5PlayListing::samplesAgreed() const {
    int agreed = 0;
    for (int s = 0; s < m_samples; ++s) {
        bool all = true;
        for (int v = 0; v < m_variables; ++v) all = all && m_done[std::size_t(s * m_variables + v)];
        agreed += all;
    }
    return agreed;
}

} // namespace serialport
