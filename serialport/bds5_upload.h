// Bds5Upload: Program > From Drive. Sends <BDS and collects the drive's program, line for line (empty
// lines kept), until the --> prompt; progress counts the lines as they arrive.
#pragma once

#include "bds5_transfer.h"

namespace serialport {

// The program lines of a <BDS answer: its text split at CR LF, error lines (BEL ERR ...) left out.
QStringList listingLines(const Bds5Response& response);

class Bds5Upload final : public Bds5Transfer {
    Q_OBJECT
public:
    explicit Bds5Upload(Bds5Session& session, QObject* parent = nullptr);

    // Esc stops the listing at once (L5350); the drive's program is untouched either way.
    void cancel() override;

protected:
    void begin() override;
    void answered(const Bds5Response& response) override;
    void lost(const QString& reason) override;
};

} // namespace serialport
