// Bds5Verify: Program > Verify, and the last step of a download. Reads the drive's program back with <BDS,
// compares it line by line with what was (or would be) sent and reports the first difference, then records
// P CHECKSUM (L9953-9984) for comparing later downloads.
#pragma once

#include "bds5_program_text.h"
#include "bds5_transfer.h"

namespace serialport {

class Bds5Verify final : public Bds5Transfer {
    Q_OBJECT
public:
    Bds5Verify(Bds5Session& session, Bds5ProgramText expected, QObject* parent = nullptr);

    // A P CHECKSUM recorded after an earlier download, to say whether the drive still holds that program.
    void setRecordedChecksum(std::optional<quint32> checksum) { m_recorded = checksum; }
    void cancel() override;

protected:
    void begin() override;
    void answered(const Bds5Response& response) override;
    void lost(const QString& reason) override;

private:
    void compare(const QStringList& actual);

    Bds5ProgramText m_expected;
    std::optional<quint32> m_recorded;
    Bds5TransferResult m_result;
    bool m_listing = true; // waiting for <BDS; then for P CHECKSUM
};

} // namespace serialport
