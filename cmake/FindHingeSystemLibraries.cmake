# FindHingeSystemLibraries: the C libraries hinge links that ship no CMake configuration (Debian 12:
# libgmp-dev, libmpfr-dev, libmpfi-dev, libqd-dev, and GCC's libquadmath), as imported targets found on
# the machine where they are used, so that neither the build nor the installed package bakes in a path:
#   GMP::gmp  GMP::gmpxx  MPFR::mpfr  MPFI::mpfi  QD::qd  Quadmath::quadmath
# Used by the build (cmake/HingeDependencies.cmake) and by the installed hingeConfig.cmake
# (find_dependency). Sets HingeSystemLibraries_FOUND.
include(FindPackageHandleStandardArgs)

# hinge_system_library(TARGET HEADER LIBRARY [DEPENDS target...] [HINTS dir...]): TARGET from HEADER and
# LIBRARY; HEADER "" for a library whose header the compiler finds by itself.
function(hinge_system_library target header library)
  cmake_parse_arguments(arg "OPTIONAL" "" "DEPENDS;HINTS" ${ARGN})
  string(MAKE_C_IDENTIFIER "${target}" var)
  find_library(${var}_LIBRARY ${library} HINTS ${arg_HINTS})
  set(required ${var}_LIBRARY)
  if(header)
    find_path(${var}_INCLUDE_DIR ${header} HINTS ${arg_HINTS})
    list(APPEND required ${var}_INCLUDE_DIR)
  endif()
  mark_as_advanced(${var}_INCLUDE_DIR ${var}_LIBRARY)
  if(${var}_LIBRARY AND (NOT header OR ${var}_INCLUDE_DIR) AND NOT TARGET ${target})
    add_library(${target} UNKNOWN IMPORTED)
    set_target_properties(${target} PROPERTIES IMPORTED_LOCATION "${${var}_LIBRARY}"
                          INTERFACE_LINK_LIBRARIES "${arg_DEPENDS}")
    if(header)
      set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${${var}_INCLUDE_DIR}")
    endif()
  endif()
  if(NOT arg_OPTIONAL)
    set(HingeSystemLibraries_REQUIRED_VARS ${HingeSystemLibraries_REQUIRED_VARS} ${required} PARENT_SCOPE)
  endif()
endfunction()

set(HingeSystemLibraries_REQUIRED_VARS)
hinge_system_library(GMP::gmp gmp.h gmp)
hinge_system_library(GMP::gmpxx gmpxx.h gmpxx DEPENDS GMP::gmp)
hinge_system_library(MPFR::mpfr mpfr.h mpfr DEPENDS GMP::gmp)
hinge_system_library(MPFI::mpfi mpfi.h mpfi DEPENDS MPFR::mpfr)
hinge_system_library(QD::qd qd/dd_real.h qd)
# libquadmath lives in GCC's own directories, searched for the library only: its header, which Boost's
# float128 includes, is the compiler's business (GCC finds it in its own include directory).
# Required where float128 is built (HINGE_FLOAT128; the installed package sets it as it was built);
# elsewhere linked when found: Boost.Multiprecision's bin128 calls it wherever the compiler has __float128.
if(NOT DEFINED HINGE_FLOAT128 OR HINGE_FLOAT128)
  hinge_system_library(Quadmath::quadmath "" quadmath HINTS ${CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES})
else()
  hinge_system_library(Quadmath::quadmath "" quadmath HINTS ${CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES} OPTIONAL)
endif()

find_package_handle_standard_args(HingeSystemLibraries REQUIRED_VARS ${HingeSystemLibraries_REQUIRED_VARS})
