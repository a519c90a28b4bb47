# Runs CMD with ARGS (separated by "@@") and fails unless it exits non-zero; its output is
# passed through so that the test can check the message.
string(REPLACE "@@" ";" args "${ARGS}")
execute_process(COMMAND ${CMD} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit code, got 0")
endif()
