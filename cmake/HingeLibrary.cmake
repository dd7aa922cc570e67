# hinge_library(NAME source...): the static library hinge_NAME with its alias hinge::NAME (also the name
# the installed package exports), its public headers in include/, C++20, the project's warnings, and
# position-independent code (the plugins in conformance/plugins/ and the Python module link the libraries into shared
# objects).
function(hinge_library name)
  add_library(hinge_${name} STATIC ${ARGN})
  add_library(hinge::${name} ALIAS hinge_${name})
  set_target_properties(hinge_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(hinge_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(hinge_${name} PUBLIC cxx_std_20)
  target_link_libraries(hinge_${name} PRIVATE $<BUILD_INTERFACE:hinge::warnings>)
endfunction()

# hinge_multiprecision_sources(file...): the units that instantiate the templates for the multiprecision
# types (and the nested AutoDiff and generated code of hinge::baselines). Under the sanitizers they take
# minutes each at -O1 (the kernels inlined into Boost.Multiprecision and QD arithmetic, then instrumented:
# the generated code in mpfr 183 s at -O1 -g1, 66 s at -O0); there they are tested, not timed, so they
# build at -O0 without debug information.
function(hinge_multiprecision_sources)
  if(HINGE_SANITIZE OR HINGE_SANITIZE_THREAD)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS "-O0;-g0")
  endif()
endfunction()
