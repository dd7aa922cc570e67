// cloth_obj N SEED FILE: writes the benchmark's N x N cloth (hinge/core/samples.hpp) as an OBJ file (seed 1: the rest
// state, seed 2: the deformed state of the benchmarks), for timing whole processes such as `hinge hessian --mesh
// deformed.obj --rest rest.obj --repeat R` (bench/README.md).
#include <charconv>
#include <cstdio>
#include <fstream>
#include <string>

#include "hinge/core/samples.hpp"
#include "hinge/io/obj.hpp"

int main(int argc, char** argv) {
  int n = 0;
  unsigned seed = 0;
  if (argc != 4 || std::from_chars(argv[1], argv[1] + std::char_traits<char>::length(argv[1]), n).ec != std::errc() ||
      std::from_chars(argv[2], argv[2] + std::char_traits<char>::length(argv[2]), seed).ec != std::errc() || n < 2) {
    std::fprintf(stderr, "usage: cloth_obj N SEED FILE   (N >= 2 vertices per side)\n");
    return 2;
  }
  std::ofstream out(argv[3]);
  hinge::io::write_obj(out, hinge::cloth(n, seed));
  out.flush();
  if (!out) {
    std::fprintf(stderr, "cloth_obj: writing %s failed\n", argv[3]);
    return 1;
  }
  return 0;
}
