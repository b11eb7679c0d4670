// Bds5Download: Program > Download to Drive. `>BDS [password]`, each line at its l-> prompt, Esc, then
// (optionally) verify: read back with <BDS, compare line by line, record P CHECKSUM (L5356-5394,
// L9953-9984). Refuses on ERR 110 (editor password) and stops on ERR 86 (program full); cancel ends the
// load with Esc at the next prompt, and so does a ^X (Stop Motion) the user sends meanwhile: no program
// line goes out after a stop. The result says what the drive holds afterwards.
#pragma once

#include "bds5_program_text.h"
#include "bds5_transfer.h"

namespace serialport {

class Bds5Verify;

class Bds5Download final : public Bds5Transfer {
    Q_OBJECT
public:
    struct Options {
        QString password;           // the editor password set with PASS on the drive; empty for none
        bool stripComments = false; // send without comment lines and trailing comments (L1157)
        bool verify = true;         // read back and compare, then P CHECKSUM
        // A line damaged on the wire, a lost prompt or a failed read-back: leave load mode and download
        // again from the start, up to this many times in all. Success is only ever a verified read-back.
        int attempts = 3;
    };

    Bds5Download(Bds5Session& session, const QString& programText, Options options,
                 QObject* parent = nullptr);

    // What is sent, with the drive-line <-> editor-line map (for errors the drive reports later).
    const Bds5ProgramText& program() const { return m_program; }
    // Before the load ends: Esc at the next prompt. While verifying: stops the read-back.
    void cancel() override;

protected:
    void begin() override;
    void answered(const Bds5Response& response) override;
    void lost(const QString& reason) override;

private:
    enum class Step { Resyncing, Entering, Sending, Leaving, Verifying };

    void sendNextLine();
    void leave();
    void afterLeaving(const Bds5Response& response);
    void enter();
    void startVerify();
    // Starts over after reason, if attempts remain and the user has not cancelled.
    bool retry(const QString& reason);
    QString heldText() const;
    QString strippedText() const;

    Bds5ProgramText m_program;
    Options m_options;
    Step m_step = Step::Entering;
    int m_sent = 0; // lines the drive has acknowledged with l->
    Bds5TransferResult m_result;
    bool m_stopped = false; // cancelled by the user's ^X (Bds5Session::stopSent)
    bool m_full = false;    // ERR 86: the drive's memory is full
    QString m_leftLoadMode; // the prompt that replaced l-> (the drive left load mode on its own)
    Bds5Verify* m_verify = nullptr;
    int m_attempt = 1;
    int m_reads = 0; // read-backs in this attempt
};

} // namespace serialport
