# cmake -DHINGE=hinge -DANSWER=energy_answer -DWRONG=plugin -DWORK=dir -P energy_files.cmake
# The file route of `hinge conform --energy` (docs/energy-conformance-cli.md):
# 1. --inputs writes the graded pairs, then the consistency probes; energy_answer (an outside program: the tan term
#    of candidates/energy_term.hpp) answers every line; --candidate passes (exit 0), with --json and --report.
# 2. The same answers without the probes' lines: the consistency checks are not evaluated, and the run fails.
# 3. A wrong plugin's --save, read back through --candidate, fails as the plugin run does, naming the 1/3.
# 4. custom: --inputs writes the probes alone; their answers pass the consistency checks.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status STREQUAL expected)
    message(FATAL_ERROR "${ARGN}: exit status ${status}, expected ${expected}\n${out}${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
function(expect text regex)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "output does not match '${regex}':\n${text}")
  endif()
endfunction()
# The number of lines of a file, and of those whose category is "consistency".
function(count_lines file)
  file(STRINGS ${file} lines)
  list(LENGTH lines total)
  file(STRINGS ${file} lines REGEX "^{\"id\": \"consistency/")
  list(LENGTH lines probes)
  set(total ${total} PARENT_SCOPE)
  set(probes ${probes} PARENT_SCOPE)
endfunction()

# 1.
run(0 ${HINGE} conform --energy tan --inputs --output ${WORK}/inputs.jsonl)
count_lines(${WORK}/inputs.jsonl)
math(EXPR pairs "${total} - ${probes}")
message("--inputs: ${pairs} graded pairs, ${probes} consistency probes")
if(pairs LESS 100 OR probes LESS 100)
  message(FATAL_ERROR "--inputs wrote ${pairs} pairs and ${probes} probes")
endif()
run(0 ${ANSWER} ${WORK}/inputs.jsonl ${WORK}/answers.jsonl)
run(0 ${HINGE} conform --energy tan --candidate ${WORK}/answers.jsonl --json ${WORK}/report.json
    --report ${WORK}/report.html)
message("${out}")
expect("${out}" "PASS: every category is within the tolerance policy and every consistency check passes")
file(READ ${WORK}/report.json json)
string(JSON passed GET "${json}" pass)
string(JSON energy GET "${json}" settings energy)
string(JSON checks LENGTH "${json}" consistency)
if(NOT passed OR NOT energy STREQUAL "tan" OR checks LESS 100)
  message(FATAL_ERROR "report.json: pass ${passed}, energy ${energy}, ${checks} checks")
endif()
file(READ ${WORK}/report.html html LIMIT 200)
expect("${html}" "<!DOCTYPE html>")

# 2.
run(0 ${ANSWER} ${WORK}/inputs.jsonl ${WORK}/no-probes.jsonl --no-probes)
run(1 ${HINGE} conform --energy tan --candidate ${WORK}/no-probes.jsonl)
message("${out}")
expect("${out}" "note: the candidate file has no line for the ${probes} consistency probes")
expect("${out}" "FAIL gradient against differences of the energy: [0-9]+ hinges, [0-9]+ failed; worst [^;]+; not evaluated")
expect("${out}" "FAIL: the candidate is outside the tolerance policy or fails a consistency check")

# 3.
run(1 ${HINGE} conform --energy tan --plugin ${WRONG} --save ${WORK}/wrong.jsonl)
string(REGEX MATCHALL "worst case [a-z-]+/[a-z-]+/[^:]+:" plugin_worst "${out}")
math(EXPR expected_lines "${pairs} + ${probes}")
count_lines(${WORK}/wrong.jsonl)
if(NOT total EQUAL expected_lines)
  message(FATAL_ERROR "--save wrote ${total} lines, expected ${pairs} + ${probes}")
endif()
run(1 ${HINGE} conform --energy tan --candidate ${WORK}/wrong.jsonl)
string(REGEX MATCHALL "worst case [a-z-]+/[a-z-]+/[^:]+:" file_worst "${out}")
expect("${out}" "1/3 times the declared one")
if(file_worst STREQUAL "" OR NOT plugin_worst STREQUAL file_worst)
  message(FATAL_ERROR "worst cases differ: plugin '${plugin_worst}', file '${file_worst}'\n${out}")
endif()

# 4.
run(0 ${HINGE} conform --energy custom --inputs --output ${WORK}/custom.jsonl)
count_lines(${WORK}/custom.jsonl)
if(NOT total EQUAL probes)
  message(FATAL_ERROR "custom --inputs wrote ${total} lines, ${probes} of them probes: expected the probes alone")
endif()
run(0 ${ANSWER} ${WORK}/custom.jsonl ${WORK}/custom-answers.jsonl)
run(0 ${HINGE} conform --energy custom --candidate ${WORK}/custom-answers.jsonl)
message("${out}")
expect("${out}" "PASS: every consistency check passes")
