# FindCHOLMOD: SuiteSparse's CHOLMOD (Debian 12: libsuitesparse-dev, SuiteSparse 5, which ships no CMake
# configuration) as the imported target CHOLMOD::cholmod, for hinge::sim's linear solver (through Eigen's
# CholmodSupport). Its header lives in include/suitesparse/. Sets CHOLMOD_FOUND.
include(FindPackageHandleStandardArgs)
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(CHOLMOD_SUITESPARSECONFIG_LIBRARY suitesparseconfig)
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY CHOLMOD_SUITESPARSECONFIG_LIBRARY)
find_package_handle_standard_args(CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_SUITESPARSECONFIG_LIBRARY CHOLMOD_INCLUDE_DIR)
if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::cholmod)
  add_library(CHOLMOD::cholmod UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::cholmod PROPERTIES IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES "${CHOLMOD_SUITESPARSECONFIG_LIBRARY}")
endif()
