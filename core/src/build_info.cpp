// How this build was made (hinge/core/build_info.hpp), from the configure step (build_info.hpp.in) and the
// libraries' own version macros and functions.
#include "hinge/core/build_info.hpp"

#include <gmp.h>
#include <mpfi.h>  // MPFI_VERSION_STRING only: the header, no library
#include <mpfr.h>

#include <Eigen/Core>
#include <boost/version.hpp>

#include "build_info.hpp"

namespace hinge {

std::vector<std::pair<std::string, std::string>> build_description() {
  return {{"version", HINGE_BUILD_VERSION},
          {"commit", HINGE_BUILD_COMMIT},
          {"compiler", HINGE_BUILD_COMPILER},
          {"build_type", HINGE_BUILD_TYPE},
          {"flags", HINGE_BUILD_FLAGS},
          {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                        std::to_string(EIGEN_MINOR_VERSION)},
          {"boost", BOOST_LIB_VERSION},
          {"mpfr", mpfr_get_version()},
          {"gmp", gmp_version},
          {"mpfi", MPFI_VERSION_STRING}};
}

}  // namespace hinge
