# Every dependency comes from Debian 12's packages (scripts/install-deps.sh); nothing is downloaded.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED) # header-only: Boost.Multiprecision

# MPFR and GMP (Boost.Multiprecision's mpfr_float and mpfi_float back ends) and MPFI ship no CMake config.
find_path(HINGE_MPFR_INCLUDE_DIR mpfr.h REQUIRED)
find_library(HINGE_MPFR_LIBRARY mpfr REQUIRED)
find_library(HINGE_GMP_LIBRARY gmp REQUIRED)
find_library(HINGE_MPFI_LIBRARY mpfi REQUIRED)
# QD (libqd-dev): dd_real and qd_real, configured in hinge/reference/scalar.hpp.
find_path(HINGE_QD_INCLUDE_DIR qd/dd_real.h REQUIRED)
find_library(HINGE_QD_LIBRARY qd REQUIRED)
find_library(HINGE_QUADMATH_LIBRARY quadmath
             HINTS ${CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES} REQUIRED)

find_package(nlohmann_json 3.11 REQUIRED) # hinge::io's JSON Lines
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
