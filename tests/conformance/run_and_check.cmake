# cmake -DCOMMAND=prog;args... -DSTATUS=N -DREGEX=re -P run_and_check.cmake
# Runs COMMAND, fails unless its exit status is STATUS and its standard output matches REGEX.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status STREQUAL STATUS)
  message(FATAL_ERROR "exit status ${status}, expected ${STATUS}")
endif()
if(NOT REGEX STREQUAL "" AND NOT out MATCHES "${REGEX}")
  message(FATAL_ERROR "output does not match '${REGEX}'")
endif()
