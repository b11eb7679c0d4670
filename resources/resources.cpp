// Registers the resources of servodesk.qrc. Q_INIT_RESOURCE must be expanded outside any namespace.
#include "resources.h"

#include <QtGlobal>

static void initializeServoDeskResources() {
    Q_INIT_RESOURCE(servodesk);
}

namespace resources {

void initialize() {
    static const bool done = [] {
        initializeServoDeskResources();
        return true;
    }();
    Q_UNUSED(done);
}

} // namespace resources
