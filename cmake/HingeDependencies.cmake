# Every dependency comes from Debian 12's packages (scripts/install-deps.sh); nothing is downloaded.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED) # header-only: Boost.Multiprecision

# GMP, MPFR, MPFI, QD and libquadmath ship no CMake configuration: imported targets from
# cmake/FindHingeSystemLibraries.cmake (GMP::gmp, GMP::gmpxx, MPFR::mpfr, MPFI::mpfi, QD::qd,
# Quadmath::quadmath), which the installed package uses too.
find_package(HingeSystemLibraries REQUIRED)

find_package(nlohmann_json 3.11 REQUIRED) # hinge::io's JSON Lines
find_package(CHOLMOD REQUIRED) # hinge::sim's sparse solver (cmake/FindCHOLMOD.cmake)
if(HINGE_BUILD_TOOLS OR HINGE_BUILD_TESTS)
  find_package(CLI11 2.1 REQUIRED)
endif()
if(HINGE_BUILD_TESTS)
  find_package(GTest REQUIRED)
  find_package(rapidcheck REQUIRED)
  # Debian's python3-sympy lives in the system interpreter; pyenv or venv interpreters may lack it.
  find_program(HINGE_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
  if(NOT HINGE_PYTHON)
    find_program(HINGE_PYTHON NAMES python3 REQUIRED)
  endif()
endif()
if(HINGE_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
find_package(Threads REQUIRED)
