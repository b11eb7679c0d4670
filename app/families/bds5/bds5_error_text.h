// Bds5ErrorText: a BDS5 error line ("ERR 92 LINE 3 'X1=5/X2' ZERO DIVIDE") as an error log row, with its
// severity (App. D, Table D.1), the catalog's meaning and the manual's remedy (catalog_error_entry.h). Pure.
#pragma once

#include "errors/error_log_model.h"

#include "serialport/bds5_protocol.h"

#include <QCoreApplication>

namespace app {

class Bds5ErrorText {
    Q_DECLARE_TR_FUNCTIONS(Bds5ErrorText)

public:
    static ErrorLogModel::Entry entry(const serialport::Bds5ErrorLine& error);
    // The manual's remedy for ERR code, else its meaning.
    static QString fixHint(int code);
};

} // namespace app
