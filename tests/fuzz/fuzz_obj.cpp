// Fuzz target: the OBJ reader (hinge/io/obj.hpp). On success every face's corners are vertices of the
// mesh, distinct, and every coordinate is finite; the mesh has a face.
#include <cmath>
#include <sstream>

#include "fuzz_target.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/obj.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using hinge::fuzz::require;
  std::istringstream in(hinge::fuzz::as_string(data, size));
  try {
    const hinge::Mesh mesh = hinge::io::read_obj(in, "fuzz.obj");
    require(!mesh.faces.empty(), "a mesh without faces was accepted");
    const auto n = static_cast<long long>(mesh.vertices.size());
    for (const auto& v : mesh.vertices)
      for (double c : v) require(std::isfinite(c), "a non-finite coordinate was accepted");
    for (const auto& f : mesh.faces)
      for (auto i : f) require(i >= 0 && i < n, "a face index outside the vertices was accepted");
  } catch (const hinge::InputError&) {
  }
  return 0;
}
