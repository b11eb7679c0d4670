// A BDS5 error as the drive reports it: number, offending entry, optional program line.
#pragma once

#include <string>

namespace drive_core::bds5 {

struct Bds5Error {
    int code = 0;
    std::string entry; // the offending entry or line, printed in quotes; empty for asynchronous faults
    int line = 0;      // program line number when raised by the user program; 0 interactively
};

// The exact bytes of the error line without the leading BEL and trailing CR LF:
// "ERR 83 '2'" padded so the catalog message starts at column 40 (L6036-6100, L9805).
// Asynchronous faults with no entry print "ERR 17 FEEDBACK LOSS".
std::string formatError(const Bds5Error& error);
// The same bytes appended to out.
void appendError(std::string& out, const Bds5Error& error);

} // namespace drive_core::bds5
