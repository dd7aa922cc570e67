// Algorithm 2 (hinge/fast/assemble.hpp) against hinge::reference::assemble: Hessian, gradient, energy and
// rest state, in double and in bin128; bit-identical results for any thread count; the edge orientation;
// only what is requested; errors named as the reference names them.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "fast_support.hpp"
#include "hinge/fast/assemble.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/evaluate.hpp"
#include "src/assembly_plan.hpp"  // detail::plan_assembly
#include "support/tolerance.hpp"

namespace hinge::fast {
namespace {

constexpr double u = 0x1p-53;

TEST(Assemble, FastMatchesReferenceInDouble) {
  const Mesh rest = test::bumpy_grid(9, 41), deformed = test::bumpy_grid(9, 42);
  const Topology t = build_topology(rest);
  for (Model model : {Model::tan, Model::shells, Model::willmore, Model::bridson})
    for (EdgeOrientation o : {EdgeOrientation::first_face, EdgeOrientation::second_face}) {
      const std::string what =
          std::string(model_name(model)) + (o == EdgeOrientation::first_face ? " first" : " second");
      Assembler<double> a(t, o);
      const auto c = reference::rest_state<double>(rest, t, {model, 0.7, 0});  // the same coefficients for both
      const auto f = a.evaluate(deformed, c, model, want_all, 2);
      const auto r = reference::assemble<double>(deformed, t, c, model);
      // The same pattern, entry for entry (pattern.hpp).
      ASSERT_EQ(f.hessian.nonZeros(), r.hessian.nonZeros()) << what;
      EXPECT_TRUE(std::equal(f.hessian.outerIndexPtr(), f.hessian.outerIndexPtr() + f.hessian.outerSize() + 1,
                             r.hessian.outerIndexPtr()))
          << what;
      EXPECT_TRUE(std::equal(f.hessian.innerIndexPtr(), f.hessian.innerIndexPtr() + f.hessian.nonZeros(),
                             r.hessian.innerIndexPtr()))
          << what;
      // The bound: 8 units of 2^-53 normwise (each within a few units of the exact sum; measured
      // 2.6). Gradient alike. The energies here are sums of psi >= 0 (but Bridson's): relative 8 units.
      EXPECT_LE(test::sparse_units(f.hessian, r.hessian, u), 8) << what;
      EXPECT_LE(test::vector_units(f.gradient, r.gradient, u), 8) << what;
      if (model != Model::bridson) {
        EXPECT_LE(std::fabs(f.energy - r.energy), 8 * u * std::fabs(r.energy)) << what;
      }
    }
}

TEST(Assemble, RestStateMatchesReference) {
  const Mesh rest = test::bumpy_grid(8, 43);
  const Topology t = build_topology(rest);
  for (Model model : {Model::tan, Model::shells}) {
    Assembler<double> a(t);
    const auto f = a.rest_state(rest, {model, 0.7, 0.1}, 2);
    const auto r = reference::rest_state<double>(rest, t, {model, 0.7, 0.1});
    ASSERT_EQ(f.size(), r.size());
    for (std::size_t h = 0; h < f.size(); ++h) {
      // a = 6 |e|^2 / (2A + 2A~): each area from a unit-normal pass, a few roundings: 8 units.
      EXPECT_LE(std::fabs(f[h].a - r[h].a), 8 * u * r[h].a) << h;
      // theta_bar from unit normals accurate to a few units (n, n~ each within ~2): 8 units absolute.
      EXPECT_LE(std::fabs(f[h].theta_bar - r[h].theta_bar), 8 * u) << h;
      // phi_bar = 2 tan(theta_bar / 2) has derivative 1 + t^2.
      const double t2 = r[h].phi_bar * r[h].phi_bar / 4;
      EXPECT_LE(std::fabs(f[h].phi_bar - r[h].phi_bar), 16 * u * (1 + t2)) << h;
      EXPECT_EQ(f[h].k, r[h].k);
      EXPECT_EQ(f[h].k_d_over_dt, r[h].k_d_over_dt);
    }
  }
}

TEST(Assemble, RestStateHasZeroEnergyAndGradient) {
  const Mesh mesh = test::bumpy_grid(6, 44);
  const Topology t = build_topology(mesh);
  for (Model model : {Model::shells, Model::tan}) {
    Assembler<double> a(t);
    const auto m = a.evaluate(mesh, a.rest_state(mesh, {model, 1.0, 0}), model);
    EXPECT_EQ(m.energy, 0.0);
    EXPECT_EQ(m.gradient.norm(), 0.0);
  }
}

TEST(Assemble, Bin128MatchesReferenceBin128) {
  // Both in bin128 throughout (plain arithmetic): each a few tens of units of 2^-113 from the exact
  // sums at worst (the per-hinge bound is 32); 64 units apart.
  const Mesh rest = test::bumpy_grid(5, 45), deformed = test::bumpy_grid(5, 46);
  const Topology t = build_topology(rest);
  const auto c = reference::rest_state<bin128>(rest, t, {Model::tan, 0.7, 0});
  Assembler<bin128> a(t);
  const auto f = a.evaluate(deformed, c, Model::tan, want_all, 1);
  const auto r = reference::assemble<bin128>(deformed, t, c, Model::tan);
  const double ub = test::unit_roundoff_double<bin128>();
  EXPECT_LE(test::sparse_units(f.hessian, r.hessian, ub), 64);
  EXPECT_LE(test::vector_units(f.gradient, r.gradient, ub), 64);
  EXPECT_LE(to_double(bin128(abs(f.energy - r.energy) / abs(r.energy))), 64 * ub);
}

TEST(Assemble, ViscoelasticMatchesReference) {
  const Mesh rest = test::bumpy_grid(6, 47), previous = test::bumpy_grid(6, 48), deformed = test::bumpy_grid(6, 49);
  const Topology t = build_topology(rest);
  auto c = reference::rest_state<double>(rest, t, {Model::viscoelastic, 0.7, 0.3});
  reference::set_previous_state(c, previous, t);
  Assembler<double> a(t);
  auto cf = c;
  a.set_previous_state(cf, previous, 1);
  for (std::size_t h = 0; h < c.size(); ++h) {
    const double t2 = c[h].phi_hat * c[h].phi_hat / 4;
    EXPECT_LE(std::fabs(cf[h].phi_hat - c[h].phi_hat), 16 * u * (1 + t2)) << h;  // as phi_bar above
  }
  const auto f = a.evaluate(deformed, c, Model::viscoelastic);
  const auto r = reference::assemble<double>(deformed, t, c, Model::viscoelastic);
  EXPECT_LE(test::sparse_units(f.hessian, r.hessian, u), 8);
  EXPECT_LE(test::vector_units(f.gradient, r.gradient, u), 8);
}

TEST(Assemble, ThreadsGiveIdenticalBytes) {
  // 2 x 60^2 faces: enough for several column ranges (assemble.hpp), whose borders cross faces.
  const Mesh rest = test::bumpy_grid(61, 50, 0.3), deformed = test::bumpy_grid(61, 51, 0.3);
  const Topology t = build_topology(rest);
  Assembler<double> a(t);
  const auto c = a.rest_state(rest, {Model::tan, 1.0, 0}, 1);
  const auto one = a.evaluate(deformed, c, Model::tan, want_all, 1);
  for (int threads : {2, 3, 4, 7}) {
    const auto many = a.evaluate(deformed, c, Model::tan, want_all, threads);
    EXPECT_EQ(std::memcmp(&one.energy, &many.energy, sizeof(double)), 0) << threads;
    ASSERT_EQ(one.gradient.size(), many.gradient.size());
    EXPECT_EQ(std::memcmp(one.gradient.data(), many.gradient.data(), sizeof(double) * one.gradient.size()), 0)
        << threads;
    ASSERT_EQ(one.hessian.nonZeros(), many.hessian.nonZeros());
    EXPECT_EQ(std::memcmp(one.hessian.valuePtr(), many.hessian.valuePtr(), sizeof(double) * one.hessian.nonZeros()), 0)
        << threads;
    const auto rest_many = a.rest_state(rest, {Model::tan, 1.0, 0}, threads);
    EXPECT_EQ(std::memcmp(c.data(), rest_many.data(), sizeof(c[0]) * c.size()), 0) << threads;
  }
}

template <class E, class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "(no error)";
}

// The bytes of an evaluation's outputs.
struct Bytes {
  double energy = 0;
  std::vector<double> gradient, values;
  std::vector<int> inner;
  explicit Bytes(const MeshDerivatives<double>& m)
      : energy(m.energy), gradient(m.gradient.data(), m.gradient.data() + m.gradient.size()),
        values(m.hessian.valuePtr(), m.hessian.valuePtr() + m.hessian.nonZeros()),
        inner(m.hessian.innerIndexPtr(), m.hessian.innerIndexPtr() + m.hessian.nonZeros()) {}
};
// n doubles identical bit for bit (memcmp must not see the null data of an empty vector).
bool same_bytes(const double* a, const double* b, std::size_t n) {
  return n == 0 || std::memcmp(a, b, sizeof(double) * n) == 0;
}
void expect_same_bytes(const Bytes& a, const Bytes& b, const std::string& what) {
  EXPECT_TRUE(same_bytes(&a.energy, &b.energy, 1)) << what;
  ASSERT_EQ(a.gradient.size(), b.gradient.size()) << what;
  EXPECT_TRUE(same_bytes(a.gradient.data(), b.gradient.data(), a.gradient.size())) << what;
  ASSERT_EQ(a.values.size(), b.values.size()) << what;
  EXPECT_TRUE(same_bytes(a.values.data(), b.values.data(), a.values.size())) << what;
  EXPECT_EQ(a.inner, b.inner) << what;
}

// The vertices of `m` renumbered at random: faces are then far from spatially coherent, and most faces
// straddle the assembly's column ranges.
Mesh shuffled(const Mesh& m, unsigned seed) {
  std::vector<Index> order(m.vertices.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<Index>(i);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  Mesh out;
  out.vertices.resize(m.vertices.size());
  for (std::size_t i = 0; i < order.size(); ++i) out.vertices[static_cast<std::size_t>(order[i])] = m.vertices[i];
  for (const auto& f : m.faces)
    out.faces.push_back({order[static_cast<std::size_t>(f[0])], order[static_cast<std::size_t>(f[1])],
                         order[static_cast<std::size_t>(f[2])]});
  return out;
}

TEST(Assemble, ThreadCountsOneToSevenGiveIdenticalBytes) {
  // Meshes with enough faces for up to 7 column ranges (detail::kFacesPerPart), one in row order and one
  // renumbered at random; each thread count evaluated into a fresh output (a new matrix, its row indices
  // written by the threads), into an output last written by another thread count and another mesh (stale
  // values, which must all be overwritten), and for the gradient alone.
  const Mesh grid_rest = test::bumpy_grid(101, 60, 0.3), grid = test::bumpy_grid(101, 61, 0.3);
  const Mesh small_rest = test::bumpy_grid(61, 62, 0.3), small = test::bumpy_grid(61, 63, 0.3);
  for (const bool shuffle : {false, true}) {
    const Mesh rest = shuffle ? shuffled(small_rest, 7) : grid_rest, deformed = shuffle ? shuffled(small, 7) : grid;
    const Topology t = build_topology(rest);
    Assembler<double> a(t);
    const auto c = a.rest_state(rest, {Model::tan, 1.0, 0}, 1);
    const Bytes one(a.evaluate(deformed, c, Model::tan, want_all, 1));
    const Bytes one_gradient(a.evaluate(deformed, c, Model::tan, want_gradient, 1));
    EXPECT_EQ(one.inner, Bytes(MeshDerivatives<double>{0, {}, a.pattern().make_matrix<double>()}).inner);
    MeshDerivatives<double> reused;
    for (int threads = 1; threads <= 7; ++threads) {
      const std::string what = (shuffle ? "shuffled, " : "grid, ") + std::to_string(threads) + " threads";
      expect_same_bytes(one, Bytes(a.evaluate(deformed, c, Model::tan, want_all, threads)), what + ", fresh");
      a.evaluate(rest, c, Model::tan, want_all, 8 - threads, reused);  // other values, other ranges
      a.evaluate(deformed, c, Model::tan, want_all, threads, reused);
      expect_same_bytes(one, Bytes(reused), what + ", reused");
      expect_same_bytes(one_gradient, Bytes(a.evaluate(deformed, c, Model::tan, want_gradient, threads)),
                        what + ", gradient");
      const auto rest_many = a.rest_state(rest, {Model::tan, 1.0, 0}, threads);
      EXPECT_EQ(std::memcmp(c.data(), rest_many.data(), sizeof(c[0]) * c.size()), 0) << what;
    }
    if (shuffle) {  // and still the reference's Hessian
      const auto r = reference::assemble<double>(deformed, t, c, Model::tan);
      const auto f = a.evaluate(deformed, c, Model::tan, want_all, 3);
      EXPECT_LE(test::sparse_units(f.hessian, r.hessian, u), 8);
      EXPECT_LE(test::vector_units(f.gradient, r.gradient, u), 8);
    }
  }
}

TEST(Assemble, AssemblyPlanCoversEveryWriteAndBalancesTheWork) {
  // Every face writing into a range lies in the range's face interval; the ranges tile the vertices; on
  // a grid in row order the largest range costs little more than an equal share of the work, and the
  // faces computed by two ranges (on their border) are few.
  const Mesh grid = test::bumpy_grid(101, 64, 0.3);
  for (const bool shuffle : {false, true}) {
    const Mesh mesh = shuffle ? shuffled(grid, 8) : grid;
    const Topology t = build_topology(mesh);
    const Pattern pattern(t);
    std::int64_t total = 0;
    for (const auto& F : pattern.faces())
      if (F.highest >= 0) total += detail::kFaceCost + detail::kOwnedHingeCost * std::popcount(F.owns);
    for (int parts = 1; parts <= 7; ++parts) {
      const detail::AssemblyPlan plan = detail::plan_assembly(pattern, parts);
      ASSERT_EQ(plan.parts, parts);
      ASSERT_EQ(plan.vertex.size(), static_cast<std::size_t>(parts) + 1);
      EXPECT_EQ(plan.vertex.front(), 0);
      EXPECT_EQ(plan.vertex.back(), static_cast<Index>(t.vertex_count));
      std::int64_t largest = 0, sum = 0;  // the sum counts a face once per range it is computed for
      for (int p = 0; p < parts; ++p) {
        EXPECT_LE(plan.vertex[p], plan.vertex[p + 1]);
        std::int64_t cost = 0;
        for (std::size_t f = 0; f < pattern.faces().size(); ++f) {
          const auto& F = pattern.faces()[f];
          if (F.highest < plan.vertex[p] || F.lowest >= plan.vertex[p + 1]) continue;
          EXPECT_GE(f, plan.face_begin[p]) << parts << " " << p;
          EXPECT_LT(f, plan.face_end[p]) << parts << " " << p;
          cost += detail::kFaceCost + detail::kOwnedHingeCost * std::popcount(F.owns);
        }
        largest = std::max(largest, cost);
        sum += cost;
      }
      EXPECT_GE(sum, total);
      if (!shuffle) {  // balanced, and few faces computed twice
        EXPECT_LE(static_cast<double>(largest), 1.02 * static_cast<double>(sum) / parts) << parts;
        EXPECT_LE(static_cast<double>(sum), (1 + 0.02 * (parts - 1)) * static_cast<double>(total)) << parts;
      }
    }
  }
}

TEST(Assemble, AssemblersRunConcurrentlyAndCopiesHaveTheirOwnThreads) {
  // Each Assembler has its own team: two evaluating at once on two threads each, a copy and a moved-to
  // Assembler (which start without workers) all give the bytes of one thread.
  const Mesh rest = test::bumpy_grid(61, 65, 0.3), deformed = test::bumpy_grid(61, 66, 0.3);
  const Topology t = build_topology(rest);
  Assembler<double> a(t);
  const auto c = a.rest_state(rest, {Model::tan, 1.0, 0}, 2);
  const Bytes one(a.evaluate(deformed, c, Model::tan, want_all, 1));
  Assembler<double> b = a;
  std::vector<MeshDerivatives<double>> outs(2);
  {
    std::thread other([&] {
      for (int i = 0; i < 20; ++i) b.evaluate(deformed, c, Model::tan, want_all, 2, outs[1]);
    });
    for (int i = 0; i < 20; ++i) a.evaluate(deformed, c, Model::tan, want_all, 2, outs[0]);
    other.join();
  }
  expect_same_bytes(one, Bytes(outs[0]), "a");
  expect_same_bytes(one, Bytes(outs[1]), "copy");
  Assembler<double> moved = std::move(b);
  expect_same_bytes(one, Bytes(moved.evaluate(deformed, c, Model::tan, want_all, 3)), "moved");
  b = moved;  // assignment keeps b's (here: no) workers
  expect_same_bytes(one, Bytes(b.evaluate(deformed, c, Model::tan, want_all, 2)), "assigned");
}

TEST(Assemble, OtherFacesAreRejectedWhateverTheThreads) {
  // The faces are compared with the topology's in the (parallel) face pass: the same error as before.
  const Mesh rest = test::bumpy_grid(61, 67, 0.3);
  const Topology t = build_topology(rest);
  Assembler<double> a(t);
  const auto c = a.rest_state(rest, {Model::tan, 1.0, 0}, 2);
  Mesh other = rest;
  std::swap(other.faces.back()[0], other.faces.back()[1]);
  for (int threads : {1, 2, 3}) {
    const std::string e = error_of<InputError>([&] { a.evaluate(other, c, Model::tan, want_all, threads); });
    EXPECT_NE(e.find("the deformed mesh must have the same vertices (count) and faces"), std::string::npos) << e;
    const std::string r = error_of<InputError>([&] { a.rest_state(other, {Model::tan, 1.0, 0}, threads); });
    EXPECT_NE(r.find("the rest mesh must have the same"), std::string::npos) << r;
    auto cc = c;
    const std::string p = error_of<InputError>([&] { a.set_previous_state(cc, other, threads); });
    EXPECT_NE(p.find("the previous mesh must have the same"), std::string::npos) << p;
  }
  // and the assembler is still sound afterwards
  const Bytes one(a.evaluate(rest, c, Model::tan, want_all, 1));
  expect_same_bytes(one, Bytes(a.evaluate(rest, c, Model::tan, want_all, 2)), "after errors");
}

TEST(Assemble, EdgeOrientationChangesTheHessianByAFewUlp) {
  // Which face transposes and owns each edge changes only the order of roundings: a few units (measured
  // 1.5); 4 units of 2^-53 normwise.
  const Mesh rest = test::bumpy_grid(9, 52), deformed = test::bumpy_grid(9, 53);
  const Topology t = build_topology(rest);
  const auto c = reference::rest_state<double>(rest, t, {Model::tan, 1.0, 0});
  const auto first = assemble<double>(deformed, t, c, Model::tan, want_all, 1, EdgeOrientation::first_face);
  const auto second = assemble<double>(deformed, t, c, Model::tan, want_all, 1, EdgeOrientation::second_face);
  EXPECT_LE(test::sparse_units(second.hessian, first.hessian, u), 4);
  EXPECT_LE(test::vector_units(second.gradient, first.gradient, u), 4);
  EXPECT_EQ(first.energy, second.energy);  // the hinge pass does not depend on it
}

TEST(Assemble, OnlyRequestedOutputsAreComputedAndStorageIsReused) {
  const Mesh mesh = test::bumpy_grid(6, 54), deformed = test::bumpy_grid(6, 55);
  const Topology t = build_topology(mesh);
  Assembler<double> a(t);
  const auto c = a.rest_state(mesh, {});
  MeshDerivatives<double> out;
  a.evaluate(deformed, c, Model::tan, want_energy, 1, out);
  EXPECT_EQ(out.gradient.size(), 0);
  EXPECT_EQ(out.hessian.size(), 0);
  const double energy = out.energy;
  a.evaluate(deformed, c, Model::tan, want_gradient, 1, out);
  EXPECT_EQ(out.gradient.size(), 3 * 36);
  EXPECT_EQ(out.hessian.size(), 0);
  EXPECT_EQ(out.energy, energy);
  const Eigen::VectorXd gradient = out.gradient;
  a.evaluate(deformed, c, Model::tan, want_all, 1, out);
  EXPECT_EQ(out.gradient, gradient);  // the Hessian does not change the gradient's bits
  const double* values = out.hessian.valuePtr();
  const Eigen::SparseMatrix<double> first = out.hessian;
  a.evaluate(deformed, c, Model::tan, want_hessian, 1, out);
  EXPECT_EQ(out.hessian.valuePtr(), values);  // written in place: no new allocation
  EXPECT_EQ(std::memcmp(first.valuePtr(), values, sizeof(double) * first.nonZeros()), 0);
}

TEST(Assemble, StaleValuesAreOverwritten) {
  // No zeroing between evaluations (each block's first write stores, pattern.hpp): evaluating one mesh
  // after another must give the bytes of a fresh evaluation.
  const Mesh rest = test::bumpy_grid(12, 57), a = test::bumpy_grid(12, 58), b = test::bumpy_grid(12, 59);
  const Topology t = build_topology(rest);
  Assembler<double> assembler(t);
  const auto c = assembler.rest_state(rest, {Model::tan, 1.0, 0});
  MeshDerivatives<double> reused;
  assembler.evaluate(a, c, Model::tan, want_all, 2, reused);
  assembler.evaluate(b, c, Model::tan, want_all, 2, reused);
  Assembler<double> other(t);
  const auto fresh = other.evaluate(b, c, Model::tan, want_all, 1);
  ASSERT_EQ(reused.hessian.nonZeros(), fresh.hessian.nonZeros());
  EXPECT_EQ(std::memcmp(reused.hessian.valuePtr(), fresh.hessian.valuePtr(), sizeof(double) * fresh.hessian.nonZeros()),
            0);
}

// The sizes of the terms the mesh sums are made of (hinge::reference, per hinge): |psi'| |grad theta|
// and the norm of the hinge's energy Hessian, each plus psi'' |theta| times |grad theta| (|Hess theta|):
// psi' = 2 k a (theta - theta_bar) inherits the absolute error of theta, a few units of u |theta|, whatever
// the size of theta - theta_bar. Where the sums cancel (closed surfaces), errors are relative to these.
std::pair<double, double> term_scales(const Mesh& mesh, const Topology& t,
                                      const std::vector<HingeCoefficients<double>>& c, Model model) {
  double gradient = 0, hessian = 0;
  for (std::size_t h = 0; h < t.hinges.size(); ++h) {
    const auto d = reference::theta_derivatives<double>(hinge_coordinates(mesh, t.hinges[h]));
    const auto p = psi(model, c[h], d.angle);
    const double sensitivity = std::fabs(p.d2 * d.angle.theta);
    gradient += (std::fabs(p.d1) + sensitivity) * d.grad.norm();
    hessian += reference::energy_hessian(p, d.grad, d.hess).norm() + sensitivity * d.hess.norm();
  }
  return {gradient, hessian};
}

TEST(Assemble, ClosedAndDegenerateTopologies) {
  // Closed surfaces (every edge a hinge; the hinge terms cancel in part at every vertex), and the
  // "pillow": two faces on the same three vertices, where every hinge has x0 == x3 (its (x0, x3) block is
  // a diagonal block) and is folded flat (theta = pi, finite for the shells energy), and the two faces'
  // terms cancel completely. 8 units of 2^-53 of the size of the terms summed (each side a few units).
  Mesh tetrahedron, octahedron, pillow;
  tetrahedron.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.3, 1}};
  tetrahedron.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  octahedron.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  octahedron.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  pillow.vertices = {{0, 0, 0}, {1, 0, 0}, {0.3, 1, 0}};
  pillow.faces = {{0, 1, 2}, {0, 2, 1}};
  for (const Mesh* m : {&tetrahedron, &octahedron, &pillow}) {
    const Topology t = build_topology(*m);
    Mesh deformed = *m;
    for (auto& v : deformed.vertices) v[2] += 0.3 * v[0] * v[1] + 0.2 * v[0];
    const auto c = reference::rest_state<double>(*m, t, {Model::shells, 1.0, 0});
    const auto [gradient_scale, hessian_scale] = term_scales(deformed, t, c, Model::shells);
    for (EdgeOrientation o : {EdgeOrientation::first_face, EdgeOrientation::second_face}) {
      const auto f = assemble<double>(deformed, t, c, Model::shells, want_all, 1, o);
      const auto r = reference::assemble<double>(deformed, t, c, Model::shells);
      const Eigen::SparseMatrix<double> d = f.hessian - r.hessian;
      EXPECT_LE(d.norm(), 8 * u * hessian_scale) << m->faces.size() << " faces";
      EXPECT_LE((f.gradient - r.gradient).norm(), 8 * u * gradient_scale) << m->faces.size() << " faces";
    }
  }
}

TEST(Assemble, ErrorsNameTheHingeAsTheReferenceDoes) {
  const Mesh rest = test::bumpy_grid(5, 56);
  const Topology t = build_topology(rest);
  const auto c = reference::rest_state<double>(rest, t, {Model::tan, 1.0, 0});
  Assembler<double> a(t);
  {  // a zero-length edge: zero-area faces
    Mesh bad = rest;
    bad.vertices[12] = bad.vertices[7];
    const auto f = error_of<InputError>([&] { a.evaluate(bad, c, Model::shells); });
    EXPECT_EQ(f, error_of<InputError>([&] { reference::assemble<double>(bad, t, c, Model::shells); }));
    EXPECT_NE(f.find("OBJ numbering"), std::string::npos) << f;
    EXPECT_EQ(error_of<InputError>([&] {
                a.rest_state(bad, {Model::shells, 1, 0});
              }),
              error_of<InputError>([&] {
                reference::rest_state<double>(bad, t, {Model::shells, 1, 0});
              }));
  }
  {  // collinear but distinct vertices
    Mesh bad = rest;
    const auto& p = bad.vertices[6];
    const auto& q = bad.vertices[8];
    bad.vertices[7] = {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};  // may round off the line
    const auto f = error_of<InputError>([&] { a.evaluate(bad, c, Model::shells); });
    EXPECT_EQ(f, error_of<InputError>([&] { reference::assemble<double>(bad, t, c, Model::shells); }));
  }
  {  // a coordinate that is not finite
    Mesh bad = rest;
    bad.vertices[13][2] = INFINITY;
    EXPECT_EQ(error_of<InputError>([&] { a.evaluate(bad, c, Model::tan); }),
              error_of<InputError>([&] { reference::assemble<double>(bad, t, c, Model::tan); }));
  }
  {  // a hinge folded flat onto itself: infinite tan energy, DomainError; shells is finite there
    Mesh flat = rest;
    for (auto& v : flat.vertices) v[2] = 0;
    const Hinge& h = t.hinges[5];
    flat.vertices[h.x[3]] = flat.vertices[h.x[0]];
    flat.vertices[h.x[3]][0] += 0.01;  // not the same point: only the hinge folds, no face degenerates
    const std::string f = error_of<DomainError>([&] { a.evaluate(flat, c, Model::tan); });
    EXPECT_EQ(f, error_of<DomainError>([&] { reference::assemble<double>(flat, t, c, Model::tan); }));
    EXPECT_NE(f.find("folded flat"), std::string::npos) << f;
    EXPECT_EQ(error_of<DomainError>([&] {
                a.rest_state(flat, {Model::tan, 1, 0});
              }),
              error_of<DomainError>([&] {
                reference::rest_state<double>(flat, t, {Model::tan, 1, 0});
              }));
  }
}

}  // namespace
}  // namespace hinge::fast
