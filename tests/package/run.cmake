# ctest package.consumer: installs the build into a fresh prefix, moves the prefix (the package must be
# relocatable), then builds and runs tests/package against it twice: with CMake (find_package, as the
# README shows) and with pkg-config (the hinge.pc file), and imports the installed Python module.
# -DBUILD=<build tree> -DWORK=<scratch dir> -DSOURCE=<this folder> -DCXX=<compiler> [-DPYTHON=<python3>].
file(REMOVE_RECURSE ${WORK})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT status EQUAL 0)
    list(JOIN ARGN " " command)
    message(FATAL_ERROR "failed (${status}): ${command}\n${out}\n${err}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/installed)
file(RENAME ${WORK}/installed ${WORK}/moved)

run(${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/cmake-build -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${WORK}/moved)
run(${CMAKE_COMMAND} --build ${WORK}/cmake-build)
run(${WORK}/cmake-build/consumer)

find_program(PKG_CONFIG pkg-config REQUIRED)
file(GLOB pc_dir LIST_DIRECTORIES true ${WORK}/moved/lib*/pkgconfig ${WORK}/moved/lib/*/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "${pc_dir}")
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs hinge OUTPUT_VARIABLE flags RESULT_VARIABLE status
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs hinge failed (PKG_CONFIG_PATH=${pc_dir})")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
run(${CXX} -O2 ${SOURCE}/consumer.cpp -o ${WORK}/pkg-config-consumer ${flags})
run(${WORK}/pkg-config-consumer)

if(PYTHON)
  file(GLOB site LIST_DIRECTORIES true ${WORK}/moved/lib*/python3*/dist-packages)
  set(ENV{PYTHONPATH} "${site}")
  # (no semicolon in the code: run() takes its arguments as a CMake list)
  run(${PYTHON} -c "import hinge\nr = hinge.eval([0.1, 1.0, 0.2, 0, 0, 0, 1.0, 0, 0, 0.4, 0.1, 1.0])\nprint(hinge.__file__, r.theta)\nassert r.error == [None] and hinge.__file__.startswith('${WORK}/moved/')")
endif()
