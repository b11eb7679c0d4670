// FamilyWorkspace: the state cell every family shows alike unless it knows more.
#include "family_workspace.h"

namespace app {

FamilyWorkspace::LinkState FamilyWorkspace::linkState() const {
    return isConnected() ? LinkState{tr("Connected"), QStringLiteral("#1e8e3e")}
                         : LinkState{tr("Disconnected"), QStringLiteral("#b3261e")};
}

} // namespace app
