// Explicit instantiations of hinge::reference for QD's dd and qd. One unit per scalar family keeps the
// heavy templates out of every other unit (their headers declare them extern).
#include "hinge/reference/assemble_impl.hpp"

HINGE_REFERENCE_INSTANTIATE(hinge::dd)
HINGE_REFERENCE_INSTANTIATE(hinge::qd)
