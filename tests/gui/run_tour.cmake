# Runs `servodesk --screenshot-tour OUT_DIR` in a clean OUT_DIR, under xvfb-run (PLATFORM=xvfb) or with
# QT_QPA_PLATFORM=offscreen. Fails when the tour fails or takes too long.
# cmake -DSERVODESK=... -DOUT_DIR=... -DPLATFORM=xvfb|offscreen [-DXVFB_RUN=...] -P run_tour.cmake
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
set(ENV{XDG_RUNTIME_DIR} "${OUT_DIR}/.runtime")
file(MAKE_DIRECTORY "$ENV{XDG_RUNTIME_DIR}")
# Crash recovery of a real session must not show up in (or be taken by) the tour.
set(ENV{SERVODESK_RECOVERY_DIR} "${OUT_DIR}/.recovery")
file(CHMOD "$ENV{XDG_RUNTIME_DIR}" DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
if(PLATFORM STREQUAL "xvfb")
    set(ENV{QT_QPA_PLATFORM} "xcb")
    # xvfb-run's default screen is 640x480 at 8 bits: give the 1280x800 window room and true colour.
    set(command "${XVFB_RUN}" -a -s "-screen 0 1920x1200x24" "${SERVODESK}")
else()
    set(ENV{QT_QPA_PLATFORM} "offscreen")
    set(command "${SERVODESK}")
endif()
# A hang guard: the tour takes ~130 s beside a loaded machine's other tests (two tours run at once under
# ctest -j), and 210 s was reached by both when a build ran beside them as well.
execute_process(COMMAND ${command} --screenshot-tour "${OUT_DIR}"
                RESULT_VARIABLE result TIMEOUT 480)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "screenshot tour (${PLATFORM}) failed: ${result}")
endif()
