// Pmc960ErrorText: a PMC-960 #xx error code (7.22, L2286-L2384: 65 codes, #80-#E3) as an error log row,
// decoded from the catalog, with a severity word and what to do. 7.22 explains each code but rarely says
// what to do: the hints are the manual's where it gives one (E1: SM0 then SM1 or SM2; B3: unassert ESTOP')
// and otherwise what the explanation implies. Pure; no I/O.
#pragma once

#include "errors/error_log_model.h"

#include <QCoreApplication>

namespace app {

class Pmc960ErrorText {
    Q_DECLARE_TR_FUNCTIONS(Pmc960ErrorText)

public:
    // code: 0x80..0xE3; detail: the command it answered ("TGF200"), empty when unknown.
    static ErrorLogModel::Entry entry(int code, const QString& detail = {});
    // "#9C" as the controller prints it.
    static QString codeText(int code);
    static QString hint(int code);
};

} // namespace app
