// Registers the resources of servodesk.qrc. Q_INIT_RESOURCE must be expanded outside any namespace.
#include "resources.h"

#include <QtGlobal>

static void initializeServoDeskResources() {
    Q_INIT_RESOURCE(servodesk);
    Q_INIT_RESOURCE(standard_var); // generated at build time (resources/CMakeLists.txt)
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
