// hinge/fast/assemble.hpp: Algorithm 2 (and Algorithm 1 for the rest state), the combined loop over
// triangles that assembles a mesh's bending energy E = sum_i psi_i(theta_i) (eq. 1), its gradient
// (eq. 2) and Hessian (eq. 3), in parallel and deterministic.
//
// The passes, each citing Algorithm 2:
//   faces    per face: N = e_1 x e_2, 2A = |N|, n (line 8; theta needs both normals of every edge first)
//   hinges   per interior edge: tan(theta/2) by eq. (12) and theta (lines 1-4), psi, psi', psi'' (line 5),
//            the energy (eq. 1)
//   assembly per face: cos(alpha_i), 1/h_i, m_i (lines 9-11), eq. (7) with the conditional transpose
//            (lines 12-14); per owned interior edge: grad theta (eq. 4, line 16), the force psi' grad theta
//            (eq. 2, line 17) and psi'' grad theta grad theta^T (lines 18-19), whose blocks among the
//            face's vertices join H^D before the scatter (6F + 4E block updates, section 4.2)
// Only what is requested is computed: energy alone stops after the hinge pass; the gradient alone skips
// eq. (7). The viscoelastic model evaluates grad theta and Hess theta once (its two parts live in psi).
//
// Output: hinge::reference::MeshDerivatives (the same layout as hinge::reference::assemble: gradient 3n,
// Hessian upper triangle, row <= col, compressed columns, global index 3 v + c), the Hessian's structure
// from the Pattern (pattern.hpp): evaluate() writes straight into its values array.
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
// Errors are found on the way (a floating-point filter flags possibly degenerate faces and infinite
// energies) and then decided exactly, hinge by hinge in order, with hinge::reference's checks and
// messages: InputError or DomainError naming the first offending hinge, its edge and faces.
//
// Sign of theta. The filter of exact.hpp decides it for almost every hinge; when it cannot, a hinge on
// the folded side (n . n~ < 0) asks hinge_orientation_exact, so that theta = +pi exactly on the branch cut;
// a hinge on the flat side takes the sign of the computed determinant (theta is then within rounding of
// 0 and continuous there: either sign gives the same result to within that rounding).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "hinge/fast/pattern.hpp"
#include "hinge/fast/triangle_kernel.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/energy.hpp"
#include "hinge/reference/errors.hpp"
#include "hinge/reference/predicates.hpp"
#include "hinge/reference/scalar.hpp"

namespace hinge::fast {

using reference::EnergyParameters;
using reference::HingeCoefficients;
using reference::MeshDerivatives;
using reference::Model;

namespace detail {

// A team of worker threads that stays for many parallel regions: run(threads, body) calls body(t) for
// t = 0 .. threads - 1, t = 0 on the caller's thread, the others on workers (created on first need and
// kept), and returns when all have returned. Between regions a worker spins briefly (the next pass or
// evaluation usually follows at once) and then sleeps on a futex (std::atomic::wait). One region at a
// time: not for concurrent use. A body must not throw (it would terminate the program). A copy or a
// moved-to team starts without workers (the threads belong to the original).
class Team {
 public:
  Team() = default;
  Team(const Team&) {}
  Team& operator=(const Team&) { return *this; }
  ~Team();

  template <class F>
  void run(int threads, F&& body) {
    if (threads <= 1) {
      body(0);
      return;
    }
    using Body = std::remove_reference_t<F>;
    dispatch(threads, [](void* b, int t) noexcept { (*static_cast<Body*>(b))(t); },
             const_cast<void*>(static_cast<const void*>(std::addressof(body))));
  }
  int workers() const { return static_cast<int>(workers_.size()); }

 private:
  using Job = void (*)(void*, int) noexcept;
  void dispatch(int threads, Job job, void* body);
  void work(int t, std::uint32_t seen);

  alignas(64) std::atomic<std::uint32_t> generation_{0};  // bumped by the caller to start a region
  alignas(64) std::atomic<int> pending_{0};               // workers that have not finished the region
  Job job_ = nullptr;
  void* body_ = nullptr;
  int threads_ = 0;
  bool stop_ = false;
  std::vector<std::thread> workers_;
};

// The assembly pass's split of the column vertices for `parts` threads: range t is vertices
// [vertex[t], vertex[t+1]), whose faces all lie in [face_begin[t], face_end[t]) (empty: begin == end).
struct AssemblyPlan {
  int parts = 0;
  std::vector<Index> vertex;
  std::vector<std::size_t> face_begin, face_end;
};

}  // namespace detail

// Algorithm 2 for one topology: the pattern and the work arrays are built once and reused by every
// evaluation (no allocation after the first). Not thread-safe itself: one evaluation at a time (each
// runs on as many threads as asked; the worker threads are kept between evaluations and joined by the
// destructor; a copy gets its own).
template <class Scalar>
class Assembler {
 public:
  explicit Assembler(const Topology& topology, EdgeOrientation orientation = EdgeOrientation::first_face)
      : topology_(&topology), pattern_(topology, orientation) {}

  const Pattern& pattern() const { return pattern_; }
  const Topology& topology() const { return *topology_; }

  // Algorithm 1 on the rest mesh: a = 3 |e_bar|^2 / A_bar, theta_bar, phi_bar = 2 tan(theta_bar / 2)
  // (eq. 12), k and k_d / dt from `parameters`, per hinge in Topology::hinges order. Throws InputError for
  // a degenerate rest hinge, DomainError for a rest hinge folded flat under an energy infinite at pi.
  std::vector<HingeCoefficients<Scalar>> rest_state(const Mesh& rest, const EnergyParameters& parameters,
                                                    int threads = 1);
  // Viscoelastic model: phi_hat of every hinge from the mesh at the previous time step.
  void set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients, const Mesh& previous, int threads = 1);

  // Algorithm 2: what `request` asks (reference::want_energy | want_gradient | want_hessian) into `out`;
  // out.hessian keeps its storage when it already has this pattern.
  void evaluate(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                unsigned request, int threads, MeshDerivatives<Scalar>& out) {
    evaluate_(deformed, coefficients, model, request, threads, out, nullptr);
  }
  // The same, consuming the coefficients: they are freed as soon as psi has been evaluated, before the
  // Hessian is allocated, which lowers the peak memory of a one-off evaluation (`hinge hessian`).
  void evaluate(const Mesh& deformed, std::vector<HingeCoefficients<Scalar>>&& coefficients, Model model,
                unsigned request, int threads, MeshDerivatives<Scalar>& out) {
    evaluate_(deformed, coefficients, model, request, threads, out, &coefficients);
  }
  MeshDerivatives<Scalar> evaluate(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients,
                                   Model model, unsigned request = reference::want_all, int threads = 1) {
    MeshDerivatives<Scalar> out;
    evaluate(deformed, coefficients, model, request, threads, out);
    return out;
  }

 private:
  enum class Purpose { evaluate, rest, previous };
  void evaluate_(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                 unsigned request, int threads, MeshDerivatives<Scalar>& out,
                 std::vector<HingeCoefficients<Scalar>>* release);
  void check_mesh_size(const Mesh& mesh, const char* what) const;
  [[noreturn]] void mesh_mismatch(const char* what) const;
  void face_pass(const Mesh& mesh, int threads, const char* what);
  template <class PerHinge>
  bool hinge_pass(const Mesh& mesh, int threads, bool skip_suspects, PerHinge&& per_hinge);
  template <class PerHinge>
  void hinge_passes(const Mesh& mesh, int threads, Purpose purpose, PerHinge&& per_hinge);
  void report(const Mesh& mesh, Purpose purpose);
  bool hessian_matches(const Eigen::SparseMatrix<Scalar>& m, int threads);

  const Topology* topology_;
  Pattern pattern_;
  detail::Team team_;
  detail::AssemblyPlan plan_;  // for plan_.parts threads (computed again when that changes)
  std::vector<std::array<Scalar, 4>> face_;  // per face: n, 1 / 2A
  std::vector<Scalar> psi1_, psi2_;          // per hinge: psi', psi''
  std::vector<Scalar> chunk_energy_;
  std::vector<char> suspect_face_, suspect_hinge_;
  bool want_theta_ = true;
  Model last_model_ = Model::tan;
  const std::vector<HingeCoefficients<Scalar>>* last_coefficients_ = nullptr;
};

// Convenience: one evaluation with a pattern built for it.
template <class Scalar>
MeshDerivatives<Scalar> assemble(const Mesh& deformed, const Topology& topology,
                                 const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                                 unsigned request = reference::want_all, int threads = 1,
                                 EdgeOrientation orientation = EdgeOrientation::first_face) {
  Assembler<Scalar> a(topology, orientation);
  return a.evaluate(deformed, coefficients, model, request, threads);
}

namespace detail {

constexpr std::size_t kFaceChunk = 4096, kHingeChunk = 4096, kCompareChunk = 1 << 18;

// body(begin, end, chunk) over fixed chunks of [0, count), taken in turn by up to `threads` threads of
// `team` (no more threads than chunks).
template <class F>
void for_chunks(Team& team, std::size_t count, std::size_t chunk, int threads, F&& body) {
  const std::size_t chunks = (count + chunk - 1) / chunk;
  std::atomic<std::size_t> next{0};
  team.run(static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), std::max<std::size_t>(chunks, 1))),
           [&](int) {
             for (std::size_t c; (c = next.fetch_add(1, std::memory_order_relaxed)) < chunks;)
               body(c * chunk, std::min(count, (c + 1) * chunk), c);
           });
}

template <class Scalar>
HINGE_FAST_INLINE Vec3<Scalar> point(const Mesh& mesh, Index v) {
  const auto& p = mesh.vertices[v];
  return {from_double<Scalar>(p[0]), from_double<Scalar>(p[1]), from_double<Scalar>(p[2])};
}

// The face pass for faces [begin, end): n and 1 / 2A (Algorithm 2, line 8); flags a face whose area the
// filter cannot certify nonzero (or that is not finite) for the exact check (suspect[f] is written for
// every face: 0 or 1, so the flags need no clearing before the pass). In Scalar itself; double has its own,
// in double-double (src/face_pass_lanes.hpp).
template <class Scalar>
HINGE_FAST_INLINE void face_pass_body(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                                      std::array<Scalar, 4>* face, char* suspect) {
  using std::sqrt;
  const auto& faces = pattern.faces();
  for (std::size_t f = begin; f < end; ++f) {
    const Pattern::Face& F = faces[f];
    if (F.highest < 0) {  // in no hinge
      suspect[f] = 0;
      continue;
    }
    const Vec3<Scalar> x0 = point<Scalar>(mesh, F.v[0]), x1 = point<Scalar>(mesh, F.v[1]), x2 = point<Scalar>(mesh, F.v[2]);
    const Vec3<Scalar> a = vsub(x1, x0), b = vsub(x2, x0);
    const Vec3<Scalar> N{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const Scalar area2 = sqrt(vdot(N, N));
    const Scalar inv = Scalar(1) / area2;
    face[f] = {N[0] * inv, N[1] * inv, N[2] * inv, inv};
    // Certified nonzero when some component exceeds its error bound: 2 roundings in each difference,
    // one in each product and the subtraction: 8 units of the permanent is generous (only a flag: the
    // exact check follows).
    bool certain = false;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      using std::abs;
      const Scalar perm = abs(a[i] * b[j]) + abs(a[j] * b[i]);
      certain = certain || abs(N[k]) > 8 * std::numeric_limits<Scalar>::epsilon() * perm;
    }
    using std::isfinite;
    suspect[f] = !certain || !isfinite(inv) || !isfinite(face[f][0] + face[f][1] + face[f][2]) ? 1 : 0;
  }
}

// The bend angle of hinge h from the face normals: tan(theta/2) by eq. (12), theta = 2 atan2(|n - n~|,
// |n + n~|) (Fig. 3) when `want_theta`; the sign of theta on the flat side (n . n~ >= 0) that of the
// computed determinant, on the folded side the filter's or, when it cannot decide, the exact one.
template <class Scalar>
HINGE_FAST_INLINE reference::BendAngle<Scalar> bend_angle(const Mesh& mesh, const Hinge& h, const std::array<Scalar, 4>& nu,
                                                          const std::array<Scalar, 4>& nl, bool want_theta) {
  using std::atan2;
  using std::sqrt;
  const Vec3<Scalar> minus{nu[0] - nl[0], nu[1] - nl[1], nu[2] - nl[2]}, plus{nu[0] + nl[0], nu[1] + nl[1], nu[2] + nl[2]};
  const Scalar sm = sqrt(vdot(minus, minus)), sp = sqrt(vdot(plus, plus));  // 2 sin(theta/2), 2 cos(theta/2)
  const auto& x0 = mesh.vertices[h.x[0]];
  const auto& x1 = mesh.vertices[h.x[1]];
  const auto& x2 = mesh.vertices[h.x[2]];
  const auto& x3 = mesh.vertices[h.x[3]];
  double p[3], q[3], r[3];
  for (int k = 0; k < 3; ++k) {
    p[k] = x2[k] - x1[k];
    q[k] = x0[k] - x1[k];
    r[k] = x3[k] - x1[k];
  }
  const bool folded_side = nu[0] * nl[0] + nu[1] * nl[1] + nu[2] * nl[2] < 0;
  int sign;
  if (!folded_side) {  // the sign of the computed determinant, which is the filter's answer when it has one
    const double computed = hinge_determinant(p, q, r);
    sign = computed > 0 ? 1 : computed < 0 ? -1 : 0;
  } else {
    double computed;
    sign = orientation_filter(p, q, r, computed);
    if (sign == kUndecided) sign = hinge_orientation_exact(x0, x1, x2, x3);
  }
  reference::BendAngle<Scalar> b;
  if (sign == 0) {  // coplanar: theta is 0 or pi
    b.on_branch_cut = folded_side;
    b.theta = folded_side ? Scalar(boost::math::constants::pi<Scalar>()) : Scalar(0);
    b.tan_half_theta = folded_side ? Scalar(std::numeric_limits<Scalar>::infinity()) : Scalar(0);
    return b;
  }
  b.on_branch_cut = false;
  const Scalar t = sm / sp;  // eq. (12)
  b.tan_half_theta = sign < 0 ? Scalar(-t) : t;
  if (want_theta) {
    const Scalar theta = 2 * atan2(sm, sp);
    b.theta = sign < 0 ? Scalar(-theta) : theta;
  } else {
    b.theta = Scalar(0);  // not used by the tan-based energies
  }
  return b;
}

inline bool needs_theta(Model model) { return model != Model::tan && model != Model::viscoelastic; }

// Scatter helpers: entry (r, c) of the block with `base` and column vertex b is at base + c stride_b +
// (c == 2) + r (pattern.hpp).

// p[0..2] += v. For the vector Column the fourth lane adds +-0 to p[3], which leaves it unchanged: p[3] is
// then the next entry of the same matrix column, which the same thread owns (an off-diagonal block is
// never the last in its column: the diagonal block follows). Not for diagonal blocks.
template <class Scalar>
HINGE_FAST_INLINE void accumulate(Scalar* p, const Column<Scalar>& v) {
  if constexpr (std::is_same_v<Column<Scalar>, Triple<Scalar>>) {
    p[0] += v[0];
    p[1] += v[1];
    p[2] += v[2];
  } else {
    Column<Scalar> x;
    std::memcpy(&x, p, sizeof x);
    x += v;
    std::memcpy(p, &x, sizeof x);
  }
}
// p[0..2] += s g: a vertex's three gradient entries (the next one may be another thread's: not touched).
template <class Scalar>
HINGE_FAST_INLINE void add_scaled(Scalar* p, const Scalar& s, const Vec3<Scalar>& g) {
  if constexpr (std::is_same_v<Column<Scalar>, Triple<Scalar>>) {
    for (int c = 0; c < 3; ++c) p[c] += s * g[c];
  } else {  // the same operations, x and y in one vector
    typedef Scalar Pair __attribute__((vector_size(2 * sizeof(Scalar))));
    Pair x;
    std::memcpy(&x, p, sizeof x);
    x += Pair{s, s} * Pair{g[0], g[1]};
    std::memcpy(p, &x, sizeof x);
    p[2] += s * g[2];
  }
}
// The block with columns B into the off-diagonal block `base` of column vertex b: added, or stored when
// this is the block's first write (Pattern::Face::first: then the values need no zeroing).
template <class Scalar>
HINGE_FAST_INLINE void add_block(Scalar* values, SlotIndex base, SlotIndex stride, const Columns3<Scalar>& B, bool first) {
  Scalar* col[3] = {values + base, values + base + stride, values + base + 2 * stride + 1};
  if (first) {
    HINGE_FAST_UNROLL
    for (int c = 0; c < 3; ++c) store<Scalar>(col[c], B[c]);
  } else {
    HINGE_FAST_UNROLL
    for (int c = 0; c < 3; ++c) accumulate(col[c], B[c]);
  }
}
// The upper triangle of B into the diagonal block `base` (stride of its vertex), added or stored.
template <class Scalar>
HINGE_FAST_INLINE void add_diagonal(Scalar* values, SlotIndex base, SlotIndex stride, const Columns3<Scalar>& B,
                                    bool first) {
  Scalar* col1 = values + base + stride;
  Scalar* col2 = values + base + 2 * stride + 1;
  if (first) {
    values[base] = B[0][0];
    col1[0] = B[1][0];
    col1[1] = B[1][1];
    col2[0] = B[2][0];
    col2[1] = B[2][1];
    col2[2] = B[2][2];
  } else {
    values[base] += B[0][0];
    col1[0] += B[1][0];
    col1[1] += B[1][1];
    col2[0] += B[2][0];
    col2[1] += B[2][1];
    col2[2] += B[2][2];
  }
}

struct AssemblyFlags {
  bool gradient, hessian;
};
// Column vertices [lo, hi), all of whose faces lie in [face_begin, face_end) (AssemblyPlan).
struct AssemblyRange {
  Index lo, hi;
  std::size_t face_begin, face_end;
};

// The assembly's prefetches: kPrefetchFaces faces ahead, and only for matrices above kPrefetchEntries
// entries (8 MB of doubles: smaller ones live in the cache, where the prefetches only cost). 32 faces:
// once the loop ran ~10% faster (fewer instructions per face), 16 left the first writes waiting at
// 401^2 and 1001^2 (32 against 16, side by side: 0.94 and 0.95 of the time; 64 no better than 32).
constexpr std::size_t kPrefetchFaces = 32;
constexpr std::int64_t kPrefetchEntries = std::int64_t(1) << 20;

// The assembly pass over every face that writes into column vertices [r.lo, r.hi), in increasing order.
template <class Scalar>
HINGE_FAST_INLINE void assembly_pass_body(const Mesh& mesh, const Pattern& pattern, const std::array<Scalar, 4>* face,
                                          const Scalar* psi1, const Scalar* psi2, AssemblyRange r, AssemblyFlags flags,
                                          Scalar* values, Scalar* gradient) {
  const auto& faces = pattern.faces();
  const auto& hinges = pattern.hinges();
  const SlotIndex* stride = pattern.strides().data();
  const SlotIndex* diagonal = pattern.diagonal_bases().data();
  const Index lo = r.lo, hi = r.hi;
  auto mine = [lo, hi](Index v) { return v >= lo && v < hi; };
  // Prefetch (for writing) the columns of each vertex kPrefetchFaces faces before the first face that
  // writes into them: on a matrix larger than the cache those first writes otherwise wait for memory.
  const SlotIndex* outer = pattern.outer().data();
  const Index* order = pattern.first_write_order().data();
  const Index* first_writer = pattern.first_writer().data();
  const std::size_t order_size = pattern.first_write_order().size();
  const bool prefetch = values && pattern.nonzeros() > kPrefetchEntries;
  std::size_t next = 0;
  if (prefetch)
    while (next < order_size && first_writer[order[next]] < static_cast<Index>(r.face_begin)) ++next;
  for (std::size_t f = r.face_begin; f < r.face_end; ++f) {
    if (prefetch)
      for (; next < order_size && first_writer[order[next]] <= static_cast<Index>(f + kPrefetchFaces); ++next) {
        const Index v = order[next];
        if (!mine(v)) continue;
        const char* p = reinterpret_cast<const char*>(values + outer[3 * static_cast<std::size_t>(v)]);
        const char* end = reinterpret_cast<const char*>(values + outer[3 * static_cast<std::size_t>(v) + 3]);
        for (p = reinterpret_cast<const char*>(reinterpret_cast<std::uintptr_t>(p) & ~std::uintptr_t(63)); p < end; p += 64)
          __builtin_prefetch(p, 1, 3);
      }
    const Pattern::Face& F = faces[f];
    if (F.highest < lo || F.lowest >= hi) continue;  // writes nothing here (or nothing at all)
    const std::array<Vec3<Scalar>, 3> x{point<Scalar>(mesh, F.v[0]), point<Scalar>(mesh, F.v[1]), point<Scalar>(mesh, F.v[2])};
    const auto& fd = face[f];
    TriangleGeometry<Scalar> t;
    triangle_geometry(x[0], x[1], x[2], Vec3<Scalar>{fd[0], fd[1], fd[2]}, fd[3], t);  // lines 8-11
    std::array<Scalar, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = F.hinge[i] >= 0 ? psi1[F.hinge[i]] : Scalar(0);  // c_i = sigma_i psi'_i
    // off[i] joins x_i and x_{i+1}; it is kept as stored, transposed when x_{i+1} has the smaller index
    unsigned mirror = 0;
    for (int i = 0; i < 3; ++i) mirror |= unsigned(F.v[(i + 1) % 3] < F.v[i]) << i;
    std::array<Columns3<Scalar>, 3> diag, off;
    if (flags.hessian) triangle_hessian(t, c, F.owns, mirror, diag, off);  // lines 12-13, eq. (7)
    for (int k = 0; k < 3; ++k) {
      if (!((F.owns >> k) & 1u)) continue;  // line 15: the interior edges this face owns
      const Index h = F.hinge[k];
      const Pattern::OwnedHinge& o = hinges[h];
      const int j = next3(k), i = prev3(k);
      const Vec3<Scalar> xs = point<Scalar>(mesh, o.s);
      const auto& ft = face[o.other_face];
      std::array<Vec3<Scalar>, 4> g;  // p, q, r, s
      hinge_gradient(t, k, x[j], x[i], xs, Vec3<Scalar>{ft[0], ft[1], ft[2]}, ft[3], g);  // line 16, eq. (4)
      const Index v[4] = {F.v[k], F.v[j], F.v[i], o.s};
      if (flags.gradient) {
        const Scalar p1 = psi1[h];
        HINGE_FAST_UNROLL4
        for (int a = 0; a < 4; ++a)
          if (mine(v[a])) add_scaled(gradient + 3 * static_cast<std::size_t>(v[a]), p1, g[a]);  // line 17, eq. (2)
      }
      if (flags.hessian) {  // lines 18-19
        const Scalar p2 = psi2[h];
        std::array<Column<Scalar>, 4> pg;
        for (int a = 0; a < 4; ++a) pg[a] = column(g[a]) * p2;
        add_hinge_outer_product(k, pg, g, mirror, diag, off);
        const Index s = o.s;
        Columns3<Scalar> B;
        auto first = [&F, k](int which) { return bool((F.first >> Pattern::hinge_bit(k, which)) & 1u); };
        if (mine(s)) {
          for (int cc = 0; cc < 3; ++cc) B[cc] = pg[3] * g[3][cc];
          add_diagonal(values, diagonal[s], stride[s], B, first(0));
        }
        const SlotIndex slots[3] = {o.slot_ps, o.slot_qs, o.slot_rs};
        HINGE_FAST_UNROLL
        for (int a = 0; a < 3; ++a) {
          const Index u = v[a];
          if (!mine(std::max(u, s))) continue;
          if (u < s) {  // block (u, s): columns pg[a] g_s[c]
            for (int cc = 0; cc < 3; ++cc) B[cc] = pg[a] * g[3][cc];
            add_block(values, slots[a], stride[s], B, first(1 + a));
          } else if (u > s) {  // block (s, u) = its transpose: columns pg[s] g_a[c]
            for (int cc = 0; cc < 3; ++cc) B[cc] = pg[3] * g[a][cc];
            add_block(values, slots[a], stride[u], B, first(1 + a));
          } else {  // u == s (two faces sharing two edges): a diagonal block, B + B^T
            for (int cc = 0; cc < 3; ++cc) B[cc] = pg[a] * g[3][cc] + pg[3] * g[a][cc];
            add_diagonal(values, diagonal[s], stride[s], B, first(1 + a));
          }
        }
      }
    }
    if (flags.hessian) {  // line 14: assemble H^D
      HINGE_FAST_UNROLL
      for (int i = 0; i < 3; ++i) {
        const Index u = F.v[i], w = F.v[(i + 1) % 3];
        if (mine(u)) add_diagonal(values, diagonal[u], stride[u], diag[i], (F.first >> Pattern::diagonal_bit(i)) & 1u);
        const Index top = std::max(u, w);
        if (mine(top))
          add_block(values, F.edge_slot[(i + 2) % 3], stride[top], off[i], (F.first >> Pattern::edge_bit(i)) & 1u);
      }
    }
  }
}

// The two hot passes; for double compiled twice (dispatch.hpp) in src/assemble_double.cpp.
template <class Scalar>
struct Kernels {
  static void faces(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                    std::array<Scalar, 4>* face, char* suspect) {
    face_pass_body<Scalar>(mesh, pattern, begin, end, face, suspect);
  }
  static void assembly(const Mesh& mesh, const Pattern& pattern, const std::array<Scalar, 4>* face, const Scalar* psi1,
                       const Scalar* psi2, AssemblyRange r, AssemblyFlags flags, Scalar* values, Scalar* gradient) {
    assembly_pass_body<Scalar>(mesh, pattern, face, psi1, psi2, r, flags, values, gradient);
  }
};
template <>
void Kernels<double>::faces(const Mesh&, const Pattern&, std::size_t, std::size_t, std::array<double, 4>*, char*);
template <>
void Kernels<double>::assembly(const Mesh&, const Pattern&, const std::array<double, 4>*, const double*, const double*,
                               AssemblyRange, AssemblyFlags, double*, double*);

// "hinge 7 (edge 3-9, faces 2 and 5; OBJ numbering: vertices 4-10, faces 3 and 6): ", as hinge::reference.
std::string describe_hinge(const Topology& topology, Index hinge);

// The assembly pass's split into `parts` column-vertex ranges (parts >= 1) that balance the estimated
// work: each face costs every range it writes into kFaceCost plus kOwnedHingeCost per hinge it owns
// (its geometry, eq. 7 and its owned edges' terms are computed in full by every such range). The ranges
// minimise the largest cost; some may be empty. Linear in the mesh (computed once per thread count).
constexpr std::int64_t kFaceCost = 2, kOwnedHingeCost = 3;
AssemblyPlan plan_assembly(const Pattern& pattern, int parts);
// The assembly uses at most 1 + faces / kFacesPerPart threads (a range of about a thousand faces takes
// some 100 microseconds; starting a region of the team takes microseconds).
constexpr std::size_t kFacesPerPart = 1024;

}  // namespace detail

// ---- Assembler ---------------------------------------------------------------------------------------

// The face pass; it also compares the mesh's faces with the topology's, chunk by chunk (check_mesh_size
// has checked the counts, so the pass reads only valid vertices either way), and throws the same
// InputError as check_mesh_size if they differ.
template <class Scalar>
void Assembler<Scalar>::face_pass(const Mesh& mesh, int threads, const char* what) {
  const std::size_t count = topology_->faces.size();
  face_.resize(count);
  suspect_face_.resize(count);  // every flag is written by the pass
  std::atomic<bool> mismatch{false};
  detail::for_chunks(team_, count, detail::kFaceChunk, threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    detail::Kernels<Scalar>::faces(mesh, pattern_, begin, end, face_.data(), suspect_face_.data());
    if (!std::equal(mesh.faces.begin() + static_cast<std::ptrdiff_t>(begin), mesh.faces.begin() + static_cast<std::ptrdiff_t>(end),
                    topology_->faces.begin() + static_cast<std::ptrdiff_t>(begin)))
      mismatch.store(true, std::memory_order_relaxed);
  });
  if (mismatch.load()) mesh_mismatch(what);
}

// per_hinge(h, bend angle) returns the hinge's energy; an exception flags the hinge for report(). Returns
// whether any hinge was flagged (suspect_hinge_ holds 0 or 1 for every hinge).
template <class Scalar>
template <class PerHinge>
bool Assembler<Scalar>::hinge_pass(const Mesh& mesh, int threads, bool skip_suspects, PerHinge&& per_hinge) {
  const auto& hinges = topology_->hinges;
  const std::size_t count = hinges.size();
  suspect_hinge_.resize(count);  // every flag is written by the pass
  chunk_energy_.resize((count + detail::kHingeChunk - 1) / detail::kHingeChunk);
  std::atomic<bool> flagged{false};
  detail::for_chunks(team_, count, detail::kHingeChunk, threads, [&](std::size_t begin, std::size_t end, std::size_t chunk) {
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
        energy += per_hinge(static_cast<Index>(h), detail::bend_angle<Scalar>(mesh, hg, face_[hg.upper], face_[hg.lower],
                                                                            want_theta_));
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
void Assembler<Scalar>::check_mesh_size(const Mesh& mesh, const char* what) const {
  if (mesh.vertices.size() != topology_->vertex_count || mesh.faces.size() != topology_->faces.size()) mesh_mismatch(what);
}

template <class Scalar>
void Assembler<Scalar>::mesh_mismatch(const char* what) const {
  throw InputError(std::string("the ") + what + " mesh must have the same vertices (count) and faces as the deformed mesh");
}

// The hinge pass, and when anything was flagged: the exact checks (report, which throws for a real
// error), then the pass again without skipping (the flags were false alarms).
template <class Scalar>
template <class PerHinge>
void Assembler<Scalar>::hinge_passes(const Mesh& mesh, int threads, Purpose purpose, PerHinge&& per_hinge) {
  if (!hinge_pass(mesh, threads, true, per_hinge)) return;
  report(mesh, purpose);
  if (hinge_pass(mesh, threads, false, per_hinge))
    throw DomainError("bending energy: a hinge could not be evaluated");  // not reached: report() threw
}

// hinge::reference's checks, hinge by hinge in order, on the flagged hinges: the first real error is
// thrown with the hinge named (as hinge::reference::assemble, rest_state, set_previous_state would).
template <class Scalar>
void Assembler<Scalar>::report(const Mesh& mesh, Purpose purpose) {
  static const char* const names[12] = {"x0.x", "x0.y", "x0.z", "x1.x", "x1.y", "x1.z",
                                        "x2.x", "x2.y", "x2.z", "x3.x", "x3.y", "x3.z"};
  const auto& hinges = topology_->hinges;
  for (std::size_t h = 0; h < hinges.size(); ++h) {
    if (!suspect_hinge_[h]) continue;
    const Hinge& hg = hinges[h];
    const std::string where = detail::describe_hinge(*topology_, static_cast<Index>(h));
    const Point& x0 = mesh.vertices[hg.x[0]];
    const Point& x1 = mesh.vertices[hg.x[1]];
    const Point& x2 = mesh.vertices[hg.x[2]];
    const Point& x3 = mesh.vertices[hg.x[3]];
    const Point* x[4] = {&x0, &x1, &x2, &x3};
    for (int i = 0; i < 12; ++i)
      if (!std::isfinite((*x[i / 3])[i % 3])) throw InputError(where + "coordinate " + names[i] + " is not finite");
    if (x1 == x2) throw InputError(where + "degenerate hinge: the hinge edge has zero length (x1 == x2)");
    if (zero_area_exact(x0, x1, x2)) throw InputError(where + "degenerate hinge: the upper triangle (x0, x1, x2) has zero area");
    if (zero_area_exact(x3, x2, x1)) throw InputError(where + "degenerate hinge: the lower triangle (x3, x2, x1) has zero area");
    // The faces are sound (a false alarm of the area filter): the angle is evaluated, and the energy's
    // own objection, if any, is the error.
    const reference::BendAngle<Scalar> b =
        detail::bend_angle<Scalar>(mesh, hg, face_[hg.upper], face_[hg.lower], true);
    if (purpose == Purpose::evaluate) {
      try {
        reference::psi(last_model_, (*last_coefficients_)[h], b);
      } catch (const InputError& e) {
        throw InputError(where + e.what());
      } catch (const DomainError& e) {
        throw DomainError(where + e.what());
      }
    } else if (purpose == Purpose::rest) {
      if (reference::infinite_at_pi(last_model_) && b.on_branch_cut)
        throw DomainError(where + "rest hinge is folded flat (theta_bar = pi): the " +
                          std::string(reference::model_name(last_model_)) + " energy needs theta_bar in (-pi, pi) (eq. 10)");
    } else if (b.on_branch_cut) {
      throw DomainError(where + "the previous state is folded flat (theta_hat = pi)");
    }
  }
}

template <class Scalar>
std::vector<HingeCoefficients<Scalar>> Assembler<Scalar>::rest_state(const Mesh& rest, const EnergyParameters& parameters,
                                                                     int threads) {
  check_mesh_size(rest, "rest");
  threads = std::max(threads, 1);
  face_pass(rest, threads, "rest");
  std::vector<HingeCoefficients<Scalar>> coefficients(topology_->hinges.size());
  want_theta_ = true;
  last_model_ = parameters.model;
  const Scalar k = from_double<Scalar>(parameters.k), kd = from_double<Scalar>(parameters.k_d_over_dt);
  hinge_passes(rest, threads, Purpose::rest, [&](Index h, const reference::BendAngle<Scalar>& b) {
    if (reference::infinite_at_pi(parameters.model) && b.on_branch_cut) throw DomainError("folded rest hinge");
    const Hinge& hg = topology_->hinges[h];
    const Vec3<Scalar> e0 = vsub(detail::point<Scalar>(rest, hg.x[2]), detail::point<Scalar>(rest, hg.x[1]));
    HingeCoefficients<Scalar>& c = coefficients[h];
    c.k = k;
    c.a = 6 * vdot(e0, e0) / (Scalar(1) / face_[hg.upper][3] + Scalar(1) / face_[hg.lower][3]);  // 3 |e|^2 / A_bar
    c.theta_bar = b.theta;
    c.phi_bar = 2 * b.tan_half_theta;  // Algorithm 1, line 2 (eq. 12)
    c.phi_hat = c.phi_bar;
    c.k_d_over_dt = kd;
    return Scalar(0);
  });
  return coefficients;
}

template <class Scalar>
void Assembler<Scalar>::set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients, const Mesh& previous,
                                           int threads) {
  check_mesh_size(previous, "previous");
  threads = std::max(threads, 1);
  face_pass(previous, threads, "previous");
  want_theta_ = false;
  hinge_passes(previous, threads, Purpose::previous, [&](Index h, const reference::BendAngle<Scalar>& b) {
    if (b.on_branch_cut) throw DomainError("folded previous hinge");
    coefficients[h].phi_hat = 2 * b.tan_half_theta;
    return Scalar(0);
  });
}

template <class Scalar>
void Assembler<Scalar>::evaluate_(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients,
                                  Model model, unsigned request, int threads, MeshDerivatives<Scalar>& out,
                                  std::vector<HingeCoefficients<Scalar>>* release) {
  check_mesh_size(deformed, "deformed");
  threads = std::max(threads, 1);
  face_pass(deformed, threads, "deformed");  // line 8 (normals first: theta needs both of every edge)
  if (coefficients.size() != topology_->hinges.size())
    throw std::invalid_argument("assemble: one HingeCoefficients per hinge expected");
  const bool want_gradient = request & reference::want_gradient, want_hessian = request & reference::want_hessian;
  const std::size_t hinge_count = topology_->hinges.size();

  psi1_.resize(hinge_count);
  psi2_.resize(hinge_count);
  want_theta_ = detail::needs_theta(model);
  last_model_ = model;
  last_coefficients_ = &coefficients;
  hinge_passes(deformed, threads, Purpose::evaluate, [&](Index h, const reference::BendAngle<Scalar>& b) {
    const reference::Psi<Scalar> p = reference::psi(model, coefficients[h], b);  // lines 4-5
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
      std::min<std::size_t>(static_cast<std::size_t>(threads), 1 + topology_->faces.size() / detail::kFacesPerPart));
  if (plan_.parts != parts) plan_ = detail::plan_assembly(pattern_, parts);
  Scalar* gradient = want_gradient ? out.gradient.data() : nullptr;
  const detail::AssemblyFlags flags{want_gradient, want_hessian};
  team_.run(parts, [&](int t) {
    const detail::AssemblyRange r{plan_.vertex[t], plan_.vertex[t + 1], plan_.face_begin[t], plan_.face_end[t]};
    if (gradient) std::fill(gradient + 3 * static_cast<std::size_t>(r.lo), gradient + 3 * static_cast<std::size_t>(r.hi), Scalar(0));
    if (inner) pattern_.fill_inner(inner, r.lo, r.hi);
    detail::Kernels<Scalar>::assembly(deformed, pattern_, face_.data(), psi1_.data(), psi2_.data(), r, flags, values,
                                      gradient);
  });
}

// Pattern::matches, the outer index arrays compared by the team.
template <class Scalar>
bool Assembler<Scalar>::hessian_matches(const Eigen::SparseMatrix<Scalar>& m, int threads) {
  if (m.rows() != pattern_.size() || m.cols() != pattern_.size() || !m.isCompressed() || m.nonZeros() != pattern_.nonzeros())
    return false;
  const SlotIndex* mine = pattern_.outer().data();
  const auto* theirs = m.outerIndexPtr();
  std::atomic<bool> differ{false};
  detail::for_chunks(team_, pattern_.outer().size(), detail::kCompareChunk, threads,
                     [&](std::size_t begin, std::size_t end, std::size_t) {
                       if (!std::equal(mine + begin, mine + end, theirs + begin)) differ.store(true, std::memory_order_relaxed);
                     });
  return !differ.load();
}

#define HINGE_FAST_ASSEMBLE_EXTERN(S) extern template class Assembler<S>;
HINGE_FOR_EACH_SCALAR(HINGE_FAST_ASSEMBLE_EXTERN)
#undef HINGE_FAST_ASSEMBLE_EXTERN

}  // namespace hinge::fast
