// Properties of the certified oracle's fast path (oracle/src/fast_path.cpp, mesh_fast_path.cpp,
// proofs/oracle-fast-path.md): on any hinge the generators make (well-shaped, the hard families, exactly
// flat and folded, scales 2^-300 to 2^300), and on any mesh with a random rest state, it gives the exact
// stage's and the enclosures' doubles bit for bit, and on an invalid hinge the same error. No tolerance:
// a decided output is the correctly rounded one. Runs in the sanitizer build too (label properties).
#include <functional>
#include <string>

#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"
#include "mesh_support.hpp"
#include "support/same_results.hpp"

namespace hinge::test {
namespace {

oracle::Options enclosures_only() {
  oracle::Options o;
  o.fast_path = false;
  return o;
}

// Runs f with and without the fast path; the same results (or the same error message) expected.
template <class F>
void same_either_way(F f, const std::string& property, const std::function<void(Report&)>& describe) {
  decltype(f(oracle::Options{})) slow, fast;
  std::string slow_error, fast_error;
  try {
    slow = f(enclosures_only());
  } catch (const std::exception& e) {
    slow_error = e.what();
  }
  try {
    fast = f(oracle::Options{});
  } catch (const std::exception& e) {
    fast_error = e.what();
  }
  RC_ASSERT(fast_error == slow_error);
  if (!slow_error.empty()) return;
  const std::string difference = first_difference(fast, slow);
  if (!difference.empty()) {
    Report rep(property);
    describe(rep);
    rep.line(difference + " differs");
    RC_FAIL(rep.finish(INFINITY, 0, "a decided output is the correctly rounded one"));
  }
}

void hinge_same_either_way(const HingeCase& h) {
  same_either_way([&](const oracle::Options& o) { return oracle::certified_theta_derivatives(h.x, o); },
                  "oracle: the fast path gives the enclosures' doubles",
                  [&](Report& rep) { rep.line("family " + h.family + " (" + h.recipe + "), input " + describe(h.x)); });
}

RC_GTEST_PROP(OracleFastPath, GivesTheEnclosuresDoublesOnAnyHinge, ()) {
  hinge_same_either_way(*gen::any_hinge(wide_scales));
}

RC_GTEST_PROP(OracleFastPath, GivesTheEnclosuresDoublesOnFlatAndFoldedHinges, ()) {
  hinge_same_either_way(*gen::coplanar_hinge(*rc::gen::arbitrary<bool>()));
}

RC_GTEST_PROP(OracleFastPath, GivesTheSameErrorOnInvalidHinges, ()) { hinge_same_either_way(*gen::invalid_hinge()); }

RC_GTEST_PROP(OracleFastPath, GivesTheEnclosuresDoublesOnAnyMesh, ()) {
  const MeshCase mc = *gen::mesh();
  EnergyParameters p;
  p.model = *rc::gen::element(Model::shells, Model::tan, Model::viscoelastic);
  p.k = *gen::uniform(0.5, 2);
  p.k_d_over_dt = 0.25;
  const Topology t = build_topology(mc.deformed);
  same_either_way(
      [&](const oracle::Options& o) { return oracle::certified_mesh(mc.deformed, mc.rest, t, p, want_all, o); },
      "oracle: the mesh fast path gives the enclosures' doubles",
      [&](Report& rep) { rep.line(mc.family + " mesh, " + std::string(model_name(p.model))); });
}

}  // namespace
}  // namespace hinge::test
