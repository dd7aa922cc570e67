# cmake -DHINGE=hinge -DWORK=dir -DVECTORS=conformance/meshes -P mesh.cmake
# For every mesh vector of conformance/meshes/meshes.jsonl: the committed certified Hessian and gradient
# pass `hinge conform --mesh` (exit 0), and so do those of `hinge hessian` (the reference in double);
# those of the reference in float do not (exit 1).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(STRINGS ${VECTORS}/meshes.jsonl lines)
foreach(line IN LISTS lines)
  string(JSON mesh GET "${line}" mesh)
  string(JSON rest GET "${line}" rest)
  string(JSON energy GET "${line}" energy)
  string(JSON hessian GET "${line}" hessian)
  string(JSON gradient GET "${line}" gradient)
  set(common --mesh ${VECTORS}/${mesh} --rest ${VECTORS}/${rest} --energy ${energy} --k 1)
  execute_process(COMMAND ${HINGE} conform ${common} --hessian ${VECTORS}/${hessian} --gradient ${VECTORS}/${gradient}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "the committed ${hessian} does not pass (${status})")
  endif()
  execute_process(COMMAND ${HINGE} hessian ${common} --out ${WORK}/${hessian} --gradient ${WORK}/${gradient}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "hinge hessian failed on ${mesh} (${status}): ${out}${err}")
  endif()
  execute_process(COMMAND ${HINGE} conform ${common} --hessian ${WORK}/${hessian} --gradient ${WORK}/${gradient}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "hinge hessian's ${hessian} does not pass (${status})")
  endif()
  execute_process(COMMAND ${HINGE} hessian ${common} --scalar float --out ${WORK}/float-${hessian}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  execute_process(COMMAND ${HINGE} conform ${common} --hessian ${WORK}/float-${hessian}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT status EQUAL 1)
    message(FATAL_ERROR "the Hessian in float passes (${status}): the check cannot fail")
  endif()
endforeach()
