# cmake -DHINGE=hinge -DWORK=dir -DWRONG=plugin;plugin... -P candidate_files.cmake
# 1. conform --inputs | oracle | conform --candidate: the oracle's own outputs pass (exit 0).
# 2. For each wrong plugin: conform --plugin --save (exit 1), then conform --candidate on the saved
#    outputs (exit 1), naming the same worst case.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status STREQUAL expected)
    message(FATAL_ERROR "${ARGN}: exit status ${status}, expected ${expected}\n${out}${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run(0 ${HINGE} conform --inputs --output ${WORK}/inputs.jsonl)
run(0 ${HINGE} oracle --input ${WORK}/inputs.jsonl --output ${WORK}/oracle.jsonl)
run(0 ${HINGE} conform --candidate ${WORK}/oracle.jsonl)
message("${out}")
if(NOT out MATCHES "PASS: every category")
  message(FATAL_ERROR "the oracle's own outputs do not pass")
endif()

foreach(plugin IN LISTS WRONG)
  get_filename_component(name ${plugin} NAME_WE)
  run(1 ${HINGE} conform --plugin ${plugin} --save ${WORK}/${name}.jsonl)
  string(REGEX MATCHALL "worst case [a-z-]+/[^:]+:" plugin_worst "${out}")
  run(1 ${HINGE} conform --candidate ${WORK}/${name}.jsonl)
  string(REGEX MATCHALL "worst case [a-z-]+/[^:]+:" file_worst "${out}")
  message("${name}: ${file_worst}")
  if(file_worst STREQUAL "" OR NOT plugin_worst STREQUAL file_worst)
    message(FATAL_ERROR "${name}: worst cases differ: plugin '${plugin_worst}', file '${file_worst}'\n${out}")
  endif()
endforeach()
