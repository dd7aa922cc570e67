// hinge/conformance/sets.hpp: the committed conformance sets with their expected values and condition
// numbers, as every route of the kit grades against them (docs/conformance-format.md): the quick set in
// float64 (hinges/, the nine categories of inputs()), the float32 set (hinges-float32/: per category,
// inputs and nonzero expected outputs normal floats, expected values the exact ones correctly rounded to
// float), and the deep sets (deep/, deep-float32/: at least 1000 more hinges from the hard families).
// The files are compiled into the library, so an installed program or Python module needs no data path;
// `hinge conform --write-vectors` regenerates them bit for bit.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "hinge/conformance/grading.hpp"

namespace hinge::conformance {

enum class Depth { quick, deep };
const char* depth_name(Depth d);        // "quick", "deep"
Depth parse_depth(const std::string&);  // std::invalid_argument naming the choices

// The cases of a set with their expected values (in the dtype: doubles holding floats for float32) and
// conditioning, grouped by category in the order of set_categories; within a category, the quick set's
// cases, then (deep) the deep set's. Parsed from the compiled-in files on first use, once (thread-safe);
// the reference stays valid for the program's lifetime. Throws std::logic_error if a compiled-in file
// does not parse (a build from a broken tree).
const std::vector<Expected>& conformance_set(Dtype dtype, Depth depth);

// The text of a compiled-in file ("energies/tan.jsonl"); empty when there is none.
std::string_view embedded_file(const std::string& name);

// The categories of a set, in report order: categories() (inputs.hpp); deep adds the hard families that
// are not among them (folded, combined), in hard_families() order.
std::vector<std::string> set_categories(Dtype dtype, Depth depth);

}  // namespace hinge::conformance
