# Proves screenshot_check can fail: it must refuse the main window's PNG and facts saved under the name of the
# scope's step response (wrong texts, no plot), and a plot area with no trace — only a grey grid and a black
# axis, then with a red marker line 2 pixels wide too — while it passes the same plot with a trace across it.
# cmake -DCHECK=<screenshot_check> -DSHOTS=<the tour's folder> -DOUT_DIR=<scratch folder> -DSPEC=<the
#       scope-step-response.png SPEC from CMakeLists.txt> -P refuse_check.cmake
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")

# The wrong pairing: another view's picture and facts under scope-step-response's name.
file(COPY_FILE "${SHOTS}/main-window.png" "${OUT_DIR}/scope-step-response.png")
file(COPY_FILE "${SHOTS}/main-window.png.facts" "${OUT_DIR}/scope-step-response.png.facts")

# A 200x150 plain-text PPM (QImage reads it) with the plot area 20,20 160x110: a grey ramp on row 0 for the
# colour count, a grey grid line, a black axis; with `trace`, a blue 3-pixel line across the plot area; with
# `marker`, a red vertical line 2 pixels wide through it.
function(write_plot path trace marker)
    set(white "255 255 255 ")
    set(ppm "P3\n200 150\n255\n")
    foreach(x RANGE 199)
        string(APPEND ppm "${x} ${x} ${x} ")
    endforeach()
    string(APPEND ppm "\n")
    foreach(y RANGE 1 149)
        if(y EQUAL 75)
            string(REPEAT "200 200 200 " 200 row)
        elseif(y EQUAL 129)
            string(REPEAT "0 0 0 " 200 row)
        elseif(y GREATER_EQUAL 20 AND y LESS 130 AND trace)
            math(EXPR before "20 + (${y} - 20) * 16 / 11")
            math(EXPR after "200 - ${before} - 3")
            string(REPEAT "${white}" ${before} left)
            string(REPEAT "26 115 232 " 3 line)
            string(REPEAT "${white}" ${after} right)
            set(row "${left}${line}${right}")
        elseif(y GREATER_EQUAL 20 AND y LESS 130 AND marker)
            string(REPEAT "${white}" 100 left)
            string(REPEAT "${white}" 98 right)
            set(row "${left}217 48 37 217 48 37 ${right}")
        else()
            string(REPEAT "${white}" 200 row)
        endif()
        string(APPEND ppm "${row}\n")
    endforeach()
    file(WRITE "${path}" "${ppm}")
    file(WRITE "${path}.facts" "window: Synthetic plot\nplot: 20,20 160x110\n")
endfunction()
write_plot("${OUT_DIR}/empty-plot.ppm" FALSE FALSE)
write_plot("${OUT_DIR}/blank-plot.ppm" FALSE TRUE)
write_plot("${OUT_DIR}/traced-plot.ppm" TRUE FALSE)

execute_process(COMMAND "${CHECK}" "${OUT_DIR}" "${SPEC}" empty-plot.ppm=200x150,plot blank-plot.ppm=200x150,plot
                        traced-plot.ppm=200x150,plot
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(result EQUAL 0)
    message(FATAL_ERROR "screenshot_check passed a wrong view and a blank plot")
endif()
foreach(expected "FAIL: scope-step-response.png: no fact contains" "FAIL: scope-step-response.png: no plot area"
                 "FAIL: empty-plot.ppm: the plot area 20,20 160x110 shows no trace: 0 trace pixels"
                 "FAIL: blank-plot.ppm: the plot area 20,20 160x110 shows no trace" "ok traced-plot.ppm")
    string(FIND "${out}${err}" "${expected}" at)
    if(at LESS 0)
        message(FATAL_ERROR "screenshot_check did not say \"${expected}\"")
    endif()
endforeach()
