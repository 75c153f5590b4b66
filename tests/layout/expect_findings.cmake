# Runs a layout check on the planted tree (cmake -P, see CMakeLists.txt):
#   -D PYTHON=... -D CHECK=<script> -D ARGS=<its arguments, joined by |> -D EXPECTED=<file>
# It must exit 1 and print exactly EXPECTED: the check can fail, and names file and line.
string(REPLACE "|" ";" arguments "${ARGS}")
execute_process(COMMAND "${PYTHON}" "${CHECK}" ${arguments}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
file(READ "${EXPECTED}" expected)
message("${output}${errors}")
if(NOT result EQUAL 1)
  message(FATAL_ERROR "${CHECK} exited with ${result} on the planted violations, not 1")
endif()
if(NOT output STREQUAL expected)
  message(FATAL_ERROR "${CHECK}'s findings differ from ${EXPECTED}:\n${expected}")
endif()
