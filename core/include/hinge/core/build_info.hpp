// hinge/core/build_info.hpp: how this build of hinge was made, as study.json and summary.json record it
// ("build": version, commit, compiler, build type, flags, library versions).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace hinge {

// (key, value) pairs, in this order: version, commit (at configure time), compiler, build_type, flags,
// eigen, boost, mpfr, gmp, mpfi.
std::vector<std::pair<std::string, std::string>> build_description();

}  // namespace hinge
