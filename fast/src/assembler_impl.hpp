// fast/src/assembler_impl.hpp: the definitions of hinge/fast/assemble.hpp's Assembler, for the explicit
// instantiations (instantiate_*.cpp): the work arrays, the order of the passes, the exact error checks.
//
// Threads and determinism. The face and hinge passes split their items into fixed chunks (kFaceChunk,
// kHingeChunk: constants, not functions of the thread count) that the threads take in any order (results
// per item; the energy summed per chunk in hinge order, then over chunks in chunk order, so whichever
// thread ran a chunk does not matter). The assembly pass gives each thread a range of column vertices:
// a thread visits, in increasing order, every face that writes into its range and performs only the
// writes whose block column (or gradient vertex) lies in it; it also zeroes the gradient of its vertices
// (and, for a new matrix, writes the row indices of its columns) before its first face. So every entry
// receives the same contributions in the same order (face by face, increasing) whatever the ranges are:
// outputs are bit-for-bit identical for any thread count. The ranges themselves depend on the thread
// count: they balance an estimate of the work (every face a range touches counts in full for it: a face
// on the border between two ranges is computed by both threads, a small fraction on a mesh whose vertex
// order is spatially coherent), and each range also knows the first and last face it touches, so that
// a thread scans only that interval of faces. The threads are a team kept by the Assembler for all its
// evaluations (detail::Team): no thread is created per pass or per evaluation after the first.
//
#pragma once

#include "hinge/fast/isa.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <string>
#include <vector>

#include "assembly_plan.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/fp_environment.hpp"
#include "hinge/core/hinge_checks.hpp"
#include "hinge/fast/assemble.hpp"
#include "passes.hpp"
#include "team.hpp"

namespace hinge::fast {
namespace detail {

constexpr std::size_t kFaceChunk = 4096, kHingeChunk = 4096, kCompareChunk = 1 << 18;

// Meshes whose extent (the largest coordinate range) lies in [2^-kUnscaled, 2^(kUnscaled + 1)) are
// evaluated as they are; the passes form products of up to six edge lengths, which stay far inside every
// type's range there (float's included: 2^(6 * 17) < 2^128). Others are evaluated scaled by a power of two
// (Workspace::normalized).
constexpr int kUnscaled = 16;

// Everything an Assembler keeps between evaluations.
template <class Scalar>
class Workspace {
 public:
  Workspace(const Topology& topology, EdgeOrientation orientation)
      : topology_(&topology), pattern_(topology, orientation) {}

  std::vector<HingeCoefficients<Scalar>> rest_state(const Mesh& rest, const EnergyParameters& parameters, int threads);
  void set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients, const Mesh& previous, int threads);
  void evaluate(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                unsigned request, int threads, MeshDerivatives<Scalar>& out,
                std::vector<HingeCoefficients<Scalar>>* release);

  const Topology* topology_;
  Pattern pattern_;

 private:
  enum class Purpose { evaluate, rest, previous };
  void check_mesh_size(const Mesh& mesh, const char* what) const;
  const Mesh& normalized(const Mesh& mesh, int& p);
  void face_pass(const Mesh& mesh, int threads, const char* what);
  template <class PerHinge>
  bool hinge_pass(const Mesh& mesh, int threads, bool skip_suspects, PerHinge&& per_hinge);
  template <class PerHinge>
  void hinge_passes(const Mesh& mesh, int threads, Purpose purpose, PerHinge&& per_hinge);
  void report(const Mesh& mesh, Purpose purpose);
  bool hessian_matches(const Eigen::SparseMatrix<Scalar>& m, int threads);

  Team team_;
  AssemblyPlan plan_;                        // for plan_.parts threads (computed again when that changes)
  std::vector<std::array<Scalar, 4>> face_;  // per face: n, 1 / 2A
  std::vector<Scalar> psi1_, psi2_;          // per hinge: psi', psi''
  std::vector<Scalar> chunk_energy_;
  std::vector<char> suspect_face_, suspect_hinge_;
  bool want_theta_ = true;
  Model last_model_ = Model::tan;
  const std::vector<HingeCoefficients<Scalar>>* last_coefficients_ = nullptr;
  Mesh scaled_;  // a mesh far from unit size, scaled (normalized)
};

// The mesh the passes evaluate, and the power of two p with mesh = 2^p (what they evaluate): `mesh` itself
// (p = 0) when its extent lies in [2^-kUnscaled, 2^(kUnscaled + 1)), else a copy scaled by 2^-p so that its
// extent lies in [1, 2) (docs/numerics.md). The scaling is exact (a power of two; a coordinate small enough to
// lose bits to it is below 2^-1074 of the extent, far beneath the mesh's resolution), theta and every
// rest-state coefficient are scale-invariant, and the gradient and Hessian scale back exactly by 2^-p and
// 2^-2p: a mesh scaled by 2^k gives exactly scaled results, and one at 2^-300 or 2^300 is evaluated as
// one at unit size would be. Meshes with a non-finite coordinate are left to the checks.
template <class Scalar>
const Mesh& Workspace<Scalar>::normalized(const Mesh& mesh, int& p) {
  p = 0;
  if (mesh.vertices.empty()) return mesh;
  std::array<double, 3> lo = mesh.vertices[0], hi = lo;
  for (const auto& v : mesh.vertices)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], v[c]);
      hi[c] = std::max(hi[c], v[c]);
    }
  double extent = 0;
  for (int c = 0; c < 3; ++c) extent = std::max(extent, hi[c] - lo[c]);
  if (!(extent > 0) || !std::isfinite(extent)) return mesh;
  const int e = std::ilogb(extent);
  if (e >= -kUnscaled && e <= kUnscaled) return mesh;
  p = e;
  scaled_.faces = mesh.faces;
  scaled_.vertices.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int c = 0; c < 3; ++c) scaled_.vertices[i][c] = std::ldexp(mesh.vertices[i][c], -p);
  return scaled_;
}

// The face pass; it also compares the mesh's faces with the topology's, chunk by chunk (check_mesh_size
// has checked the counts, so the pass reads only valid vertices either way), and throws the same
// InputError as check_mesh_size if they differ.
template <class Scalar>
void Workspace<Scalar>::face_pass(const Mesh& mesh, int threads, const char* what) {
  const std::size_t count = topology_->faces.size();
  face_.resize(count);
  suspect_face_.resize(count);  // every flag is written by the pass
  std::atomic<bool> mismatch{false};
  for_chunks(team_, count, kFaceChunk, threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    Kernels<Scalar>::faces(mesh, pattern_, begin, end, face_.data(), suspect_face_.data());
    if (!std::equal(mesh.faces.begin() + static_cast<std::ptrdiff_t>(begin),
                    mesh.faces.begin() + static_cast<std::ptrdiff_t>(end),
                    topology_->faces.begin() + static_cast<std::ptrdiff_t>(begin)))
      mismatch.store(true, std::memory_order_relaxed);
  });
  if (mismatch.load()) throw_mesh_mismatch(what);
}

// per_hinge(h, bend angle) returns the hinge's energy; an exception flags the hinge for report(). Returns
// whether any hinge was flagged (suspect_hinge_ holds 0 or 1 for every hinge).
template <class Scalar>
template <class PerHinge>
bool Workspace<Scalar>::hinge_pass(const Mesh& mesh, int threads, bool skip_suspects, PerHinge&& per_hinge) {
  const auto& hinges = topology_->hinges;
  const std::size_t count = hinges.size();
  suspect_hinge_.resize(count);  // every flag is written by the pass
  chunk_energy_.resize((count + kHingeChunk - 1) / kHingeChunk);
  std::atomic<bool> flagged{false};
  for_chunks(team_, count, kHingeChunk, threads, [&](std::size_t begin, std::size_t end, std::size_t chunk) {
    Scalar energy(0);
    bool any = false;
    for (std::size_t h = begin; h < end; ++h) {
      const Hinge& hg = hinges[h];
      suspect_hinge_[h] = 0;
      if (skip_suspects && (suspect_face_[hg.upper] || suspect_face_[hg.lower])) {
        suspect_hinge_[h] = 1;
        any = true;
        continue;
      }
      try {
        energy += per_hinge(static_cast<Index>(h),
                            bend_angle<Scalar>(mesh, hg, face_[hg.upper], face_[hg.lower], want_theta_));
      } catch (const std::exception&) {
        suspect_hinge_[h] = 1;
        any = true;
      }
    }
    chunk_energy_[chunk] = energy;
    if (any) flagged.store(true, std::memory_order_relaxed);
  });
  return flagged.load();
}

// The vertex and face counts; the faces themselves are compared by the face pass (in parallel).
template <class Scalar>
void Workspace<Scalar>::check_mesh_size(const Mesh& mesh, const char* what) const {
  if (mesh.vertices.size() != topology_->vertex_count || mesh.faces.size() != topology_->faces.size())
    throw_mesh_mismatch(what);
}

// The hinge pass, and when anything was flagged: the exact checks (report, which throws for a real
// error), then the pass again without skipping (the flags were false alarms).
template <class Scalar>
template <class PerHinge>
void Workspace<Scalar>::hinge_passes(const Mesh& mesh, int threads, Purpose purpose, PerHinge&& per_hinge) {
  if (!hinge_pass(mesh, threads, true, per_hinge)) return;
  report(mesh, purpose);
  if (hinge_pass(mesh, threads, false, per_hinge))
    throw DomainError("bending energy: a hinge could not be evaluated");  // not reached: report() threw
}

// hinge::reference's checks, hinge by hinge in order, on the flagged hinges: the first real error is
// thrown with the hinge named (as hinge::reference::assemble, rest_state, set_previous_state would).
template <class Scalar>
void Workspace<Scalar>::report(const Mesh& mesh, Purpose purpose) {
  const auto& hinges = topology_->hinges;
  for (std::size_t h = 0; h < hinges.size(); ++h) {
    if (!suspect_hinge_[h]) continue;
    const Hinge& hg = hinges[h];
    for_hinge(*topology_, static_cast<Index>(h), [&] {
      check_hinge(hinge_coordinates(mesh, hg));  // the contract's checks, exactly, in their order
      // The faces are sound (a false alarm of the area filter): the angle is evaluated, and the energy's
      // own objection, if any, is the error.
      const BendAngle<Scalar> b = bend_angle<Scalar>(mesh, hg, face_[hg.upper], face_[hg.lower], true);
      if (purpose == Purpose::evaluate) psi(last_model_, (*last_coefficients_)[h], b);
      else if (purpose == Purpose::rest && infinite_at_pi(last_model_) && b.on_branch_cut)
        throw_folded_rest(last_model_);
      else if (purpose == Purpose::previous && b.on_branch_cut) throw_folded_previous();
    });
  }
}

// HINGE_ISA is read (and a bad value thrown as std::invalid_argument) here, on the caller's thread: the
// double passes that read it first run on the team's threads, which must not throw.
template <class Scalar>
void check_isa() {
  if constexpr (std::is_same_v<Scalar, double>) (void)active_isa();
}

template <class Scalar>
std::vector<HingeCoefficients<Scalar>> Workspace<Scalar>::rest_state(const Mesh& rest_given,
                                                                     const EnergyParameters& parameters, int threads) {
  check_fp_environment();
  check_isa<Scalar>();
  check_mesh_size(rest_given, "rest");
  threads = std::max(threads, 1);
  int p = 0;  // the coefficients are scale-invariant: nothing to scale back
  const Mesh& rest = normalized(rest_given, p);
  face_pass(rest, threads, "rest");
  std::vector<HingeCoefficients<Scalar>> coefficients(topology_->hinges.size());
  want_theta_ = true;
  last_model_ = parameters.model;
  const Scalar k = from_double<Scalar>(parameters.k), kd = from_double<Scalar>(parameters.k_d_over_dt);
  hinge_passes(rest, threads, Purpose::rest, [&](Index h, const BendAngle<Scalar>& b) {
    if (infinite_at_pi(parameters.model) && b.on_branch_cut) throw DomainError("folded rest hinge");
    const Hinge& hg = topology_->hinges[h];
    const Vec3<Scalar> e0 = vsub(point<Scalar>(rest, hg.x[2]), point<Scalar>(rest, hg.x[1]));
    HingeCoefficients<Scalar>& c = coefficients[h];
    c.k = k;
    c.a = 6 * vdot(e0, e0) / (Scalar(1) / face_[hg.upper][3] + Scalar(1) / face_[hg.lower][3]);  // 3 |e|^2 / A_bar
    c.theta_bar = b.theta;
    c.phi_bar = 2 * b.tan_half_theta;  // Algorithm 1, line 2 (eq. (12))
    c.phi_hat = c.phi_bar;
    c.k_d_over_dt = kd;
    return Scalar(0);
  });
  return coefficients;
}

template <class Scalar>
void Workspace<Scalar>::set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients,
                                           const Mesh& previous_given, int threads) {
  check_fp_environment();
  check_isa<Scalar>();
  check_mesh_size(previous_given, "previous");
  threads = std::max(threads, 1);
  int p = 0;  // phi_hat is scale-invariant
  const Mesh& previous = normalized(previous_given, p);
  face_pass(previous, threads, "previous");
  want_theta_ = false;
  hinge_passes(previous, threads, Purpose::previous, [&](Index h, const BendAngle<Scalar>& b) {
    if (b.on_branch_cut) throw DomainError("folded previous hinge");
    coefficients[h].phi_hat = 2 * b.tan_half_theta;
    return Scalar(0);
  });
}

template <class Scalar>
void Workspace<Scalar>::evaluate(const Mesh& deformed_given, const std::vector<HingeCoefficients<Scalar>>& coefficients,
                                 Model model, unsigned request, int threads, MeshDerivatives<Scalar>& out,
                                 std::vector<HingeCoefficients<Scalar>>* release) {
  check_fp_environment();  // the exact steps need rounding to nearest and subnormals
  check_isa<Scalar>();
  check_mesh_size(deformed_given, "deformed");
  threads = std::max(threads, 1);
  int scale = 0;  // deformed_given = 2^scale deformed: gradient 2^-scale, Hessian 2^-2 scale, energy unchanged
  const Mesh& deformed = normalized(deformed_given, scale);
  face_pass(deformed, threads, "deformed");  // line 8 (normals first: theta needs both of every edge)
  if (coefficients.size() != topology_->hinges.size())
    throw std::invalid_argument("assemble: one HingeCoefficients per hinge expected");
  const bool want_gradient = request & hinge::want_gradient, want_hessian = request & hinge::want_hessian;
  const std::size_t hinge_count = topology_->hinges.size();

  psi1_.resize(hinge_count);
  psi2_.resize(hinge_count);
  want_theta_ = needs_theta(model);
  last_model_ = model;
  last_coefficients_ = &coefficients;
  hinge_passes(deformed, threads, Purpose::evaluate, [&](Index h, const BendAngle<Scalar>& b) {
    const Psi<Scalar> p = psi(model, coefficients[h], b);  // lines 4-5
    psi1_[h] = p.d1;
    psi2_[h] = p.d2;
    return p.value;
  });
  out.energy = Scalar(0);
  for (const Scalar& e : chunk_energy_) out.energy += e;  // eq. (1), chunks in order
  last_coefficients_ = nullptr;
  if (release) std::vector<HingeCoefficients<Scalar>>().swap(*release);

  const Eigen::Index n = pattern_.size();
  if (want_gradient) out.gradient.resize(n);  // zeroed by the assembly's threads, each for its vertices
  else out.gradient.resize(0);
  Scalar* values = nullptr;
  SlotIndex* inner = nullptr;  // a new matrix: its row indices are written by the assembly's threads
  if (want_hessian) {
    if (!hessian_matches(out.hessian, threads)) {
      Eigen::SparseMatrix<Scalar> fresh = pattern_.allocate_matrix<Scalar>();
      out.hessian.swap(fresh);  // Eigen 3.4's SparseMatrix has no move assignment: a copy would double the peak
      inner = out.hessian.innerIndexPtr();
    }
    values = out.hessian.valuePtr();  // no zeroing: every block's first write stores (Pattern::Face::first)
  } else {
    Eigen::SparseMatrix<Scalar> empty;
    out.hessian.swap(empty);
  }
  if (!want_gradient && !want_hessian) return;
  // Lines 7-21, each thread on its columns (see the header comment). Few faces: fewer threads. The plan
  // depends only on the pattern and the number of ranges: kept for the next evaluation.
  const int parts = static_cast<int>(
      std::min<std::size_t>(static_cast<std::size_t>(threads), 1 + topology_->faces.size() / kFacesPerPart));
  if (plan_.parts != parts) plan_ = plan_assembly(pattern_, parts);
  Scalar* gradient = want_gradient ? out.gradient.data() : nullptr;
  const AssemblyFlags flags{want_gradient, want_hessian};
  team_.run(parts, [&](int t) {
    const AssemblyRange r{plan_.vertex[t], plan_.vertex[t + 1], plan_.face_begin[t], plan_.face_end[t]};
    if (gradient)
      std::fill(gradient + 3 * static_cast<std::size_t>(r.lo), gradient + 3 * static_cast<std::size_t>(r.hi),
                Scalar(0));
    if (inner) pattern_.fill_inner(inner, r.lo, r.hi);
    Kernels<Scalar>::assembly(deformed, pattern_, face_.data(), psi1_.data(), psi2_.data(), r, flags, values, gradient);
  });
  if (scale != 0) {  // undone exactly (in two steps: 2^-2 scale alone may be outside double's range)
    using std::ldexp;
    if (gradient)
      for (Eigen::Index i = 0; i < out.gradient.size(); ++i) gradient[i] = ldexp(gradient[i], -scale);
    if (values)
      for (Eigen::Index i = 0; i < out.hessian.nonZeros(); ++i) values[i] = ldexp(ldexp(values[i], -scale), -scale);
  }
}

// Pattern::matches, the outer index arrays compared by the team.
template <class Scalar>
bool Workspace<Scalar>::hessian_matches(const Eigen::SparseMatrix<Scalar>& m, int threads) {
  if (m.rows() != pattern_.size() || m.cols() != pattern_.size() || !m.isCompressed() ||
      m.nonZeros() != pattern_.nonzeros())
    return false;
  const SlotIndex* mine = pattern_.outer().data();
  const auto* theirs = m.outerIndexPtr();
  std::atomic<bool> differ{false};
  for_chunks(team_, pattern_.outer().size(), kCompareChunk, threads,
             [&](std::size_t begin, std::size_t end, std::size_t) {
               if (!std::equal(mine + begin, mine + end, theirs + begin)) differ.store(true, std::memory_order_relaxed);
             });
  return !differ.load();
}

}  // namespace detail

template <class Scalar>
Assembler<Scalar>::Assembler(const Topology& topology, EdgeOrientation orientation)
    : work_(std::make_unique<detail::Workspace<Scalar>>(topology, orientation)) {}
template <class Scalar>
Assembler<Scalar>::~Assembler() = default;
template <class Scalar>
Assembler<Scalar>::Assembler(const Assembler& other)
    : work_(std::make_unique<detail::Workspace<Scalar>>(*other.work_)) {}
template <class Scalar>
Assembler<Scalar>& Assembler<Scalar>::operator=(const Assembler& other) {
  if (this != &other) work_ = std::make_unique<detail::Workspace<Scalar>>(*other.work_);
  return *this;
}
template <class Scalar>
Assembler<Scalar>::Assembler(Assembler&&) noexcept = default;
template <class Scalar>
Assembler<Scalar>& Assembler<Scalar>::operator=(Assembler&&) noexcept = default;

template <class Scalar>
const Pattern& Assembler<Scalar>::pattern() const {
  return work_->pattern_;
}
template <class Scalar>
const Topology& Assembler<Scalar>::topology() const {
  return *work_->topology_;
}

template <class Scalar>
std::vector<HingeCoefficients<Scalar>> Assembler<Scalar>::rest_state(const Mesh& rest,
                                                                     const EnergyParameters& parameters, int threads) {
  return work_->rest_state(rest, parameters, threads);
}
template <class Scalar>
void Assembler<Scalar>::set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients, const Mesh& previous,
                                           int threads) {
  work_->set_previous_state(coefficients, previous, threads);
}
template <class Scalar>
void Assembler<Scalar>::evaluate(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients,
                                 Model model, unsigned request, int threads, MeshDerivatives<Scalar>& out) {
  work_->evaluate(deformed, coefficients, model, request, threads, out, nullptr);
}
template <class Scalar>
void Assembler<Scalar>::evaluate(const Mesh& deformed, std::vector<HingeCoefficients<Scalar>>&& coefficients,
                                 Model model, unsigned request, int threads, MeshDerivatives<Scalar>& out) {
  work_->evaluate(deformed, coefficients, model, request, threads, out, &coefficients);
}
template <class Scalar>
MeshDerivatives<Scalar> Assembler<Scalar>::evaluate(const Mesh& deformed,
                                                    const std::vector<HingeCoefficients<Scalar>>& coefficients,
                                                    Model model, unsigned request, int threads) {
  MeshDerivatives<Scalar> out;
  evaluate(deformed, coefficients, model, request, threads, out);
  return out;
}

}  // namespace hinge::fast
