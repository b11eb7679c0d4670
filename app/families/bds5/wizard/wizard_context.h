// WizardContext: what every setup-wizard page shares — the drive connection, the variables read through
// it (VariableModel, kept up to date by VariableSync) and the changes not yet sent (WizardChanges).
#pragma once

namespace app {

class DriveConnection;
class VariableModel;
class VariableSync;
class WizardChanges;

struct WizardContext {
    DriveConnection& connection;
    VariableModel& model;
    VariableSync& sync;
    WizardChanges& changes;
};

} // namespace app
