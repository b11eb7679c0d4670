// The BDS5's Tuning panel: the one TuningPanel over its TuningRunner (RECORD/PLAY), with what only the BDS5
// has — TUNE <bandwidth> <stability> with the manual's warning (L6283), the question asked when a test move
// would pass the software travel limits (PMAX/PMIN at power-up are +-100 counts), and the gains read once
// the drive connects. GUI thread only.
#pragma once

#include "test_move.h"

class QMessageBox;
class QWidget;

namespace app {

class DriveConnection;
class TuningPanel;

TuningPanel* makeBds5TuningPanel(DriveConnection& connection, QWidget* parent);
// The question shown (non-modal) while a run waits because its move would pass PMAX/PMIN: "Turn off the
// soft limits (PLIM=0) for the test" or Cancel. nullptr when none is open.
QMessageBox* softLimitsQuestion(const TuningPanel& panel);
// Shows the preset in the test-move fields and hands it to the runner, with its MI speed when it has one;
// the amplitude is the caller's.
void setTestMove(TuningPanel& panel, const TestMove& move);

} // namespace app
