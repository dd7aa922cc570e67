# Runs the generator of the symbolic baseline with a fixed hash seed and compares its output with the
# committed code, byte for byte.
set(ENV{PYTHONHASHSEED} 0)
execute_process(COMMAND ${PYTHON} ${GENERATOR} ${OUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${status})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${COMMITTED} RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "${COMMITTED} is not what ${GENERATOR} writes (diff ${OUT} ${COMMITTED})")
endif()
