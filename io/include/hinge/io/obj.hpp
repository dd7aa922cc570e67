// hinge/io/obj.hpp: Wavefront OBJ input and output, exact to the bit (docs/contract.md, `hinge hessian`).
// Only `v x y z` and `f a b c` lines matter (1-based or negative relative indices, `a/b/c` forms); other
// lines are ignored. Coordinates are parsed with std::from_chars (correctly rounded), so a coordinate
// written with 17 significant digits reads back bit for bit; Debian's tinyobjloader does not (it misreads
// about two thirds of 17-digit coordinates by up to 3 ulp), which is why this reader exists.
#pragma once

#include <iosfwd>
#include <string>

#include "hinge/core/mesh.hpp"

namespace hinge::io {

// Throws hinge::InputError "FILE:LINE: why" for an unreadable file, a malformed or non-finite
// coordinate, a face with other than 3 vertices, or an index out of range; "FILE: the mesh has no faces
// (...)" for a file without faces, an empty one included (contract version 2).
Mesh read_obj(const std::string& path);
Mesh read_obj(std::istream& in, const std::string& name_for_errors);

// Writes `v` and `f` lines (after `# comment` when one is given); every coordinate printed so that it
// reads back exactly (number.hpp).
void write_obj(std::ostream& out, const Mesh& mesh, const std::string& comment = "");

}  // namespace hinge::io
