// Algorithm 2's hot passes in double (passes.hpp), compiled for the baseline x86-64, for x86-64-v3 and (the
// face pass) x86-64-v4, and chosen at run time (dispatch.hpp); the same bits either way. The face pass works
// on eight faces at a time in double-double (face_pass_lanes.hpp); the assembly pass has no x86-64-v4
// version, which measured slower than x86-64-v3 (docs/performance-log.md).
#include "dispatch.hpp"
#include "face_pass_lanes.hpp"
#include "hinge/fast/isa.hpp"
#include "passes.hpp"

namespace hinge::fast::detail {
namespace {

HINGE_FAST_TARGET_V4 void faces_v4(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                                   std::array<double, 4>* face, char* suspect) {
  face_pass_lanes<Zmm8>(mesh, pattern, begin, end, face, suspect);
}
HINGE_FAST_TARGET_V3 void faces_v3(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                                   std::array<double, 4>* face, char* suspect) {
  face_pass_lanes<Ymm8>(mesh, pattern, begin, end, face, suspect);
}
void faces_baseline(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                    std::array<double, 4>* face, char* suspect) {
  face_pass_lanes<Sse8>(mesh, pattern, begin, end, face, suspect);
}
HINGE_FAST_TARGET_V3 void assembly_v3(const Mesh& mesh, const Pattern& pattern, const std::array<double, 4>* face,
                                      const double* psi1, const double* psi2, AssemblyRange r, AssemblyFlags flags,
                                      double* values, double* gradient) {
  assembly_pass_body<double>(mesh, pattern, face, psi1, psi2, r, flags, values, gradient);
}
void assembly_baseline(const Mesh& mesh, const Pattern& pattern, const std::array<double, 4>* face, const double* psi1,
                       const double* psi2, AssemblyRange r, AssemblyFlags flags, double* values, double* gradient) {
  assembly_pass_body<double>(mesh, pattern, face, psi1, psi2, r, flags, values, gradient);
}

}  // namespace

template <>
void Kernels<double>::faces(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                            std::array<double, 4>* face, char* suspect) {
  static const auto kernel = active_isa() == Isa::avx512 ? faces_v4
                             : active_isa() == Isa::avx2 ? faces_v3
                                                         : faces_baseline;
  kernel(mesh, pattern, begin, end, face, suspect);
}

template <>
void Kernels<double>::assembly(const Mesh& mesh, const Pattern& pattern, const std::array<double, 4>* face,
                               const double* psi1, const double* psi2, AssemblyRange r, AssemblyFlags flags,
                               double* values, double* gradient) {
  static const auto kernel = active_isa() == Isa::baseline ? assembly_baseline : assembly_v3;  // v4: v3's
  kernel(mesh, pattern, face, psi1, psi2, r, flags, values, gradient);
}

}  // namespace hinge::fast::detail
