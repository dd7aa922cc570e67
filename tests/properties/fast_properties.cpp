// Properties of hinge::fast: its per-hinge kernel against hinge::reference and against MPFR at 256 bits
// (double and bin128), its exact invariances, and its mesh assembly (Algorithm 2) against
// hinge::reference::assemble, including the choice of edge orientation (the conditional transpose of
// eq. (7)). docs/testing.md lists them with their bounds.
#include <boost/math/constants/constants.hpp>

#include "hinge/fast/assemble.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "mesh_support.hpp"

namespace hinge::fast {
inline void showValue(EdgeOrientation o, std::ostream& os) {
  os << (o == EdgeOrientation::first_face ? "edge orientation first_face" : "edge orientation second_face");
}
}  // namespace hinge::fast

namespace hinge::test {
namespace {

template <class S>
fast::HingeDerivatives<S> fast_evaluate(const Coordinates& x) {
  return fast::hinge_derivatives<S>(x, true);
}

template <class S>
std::string name(const std::string& property) {
  return "fast " + type_name<S>() + ": " + property;
}

template <class S>
bool finite(const fast::HingeDerivatives<S>& d) {
  using std::isfinite;
  if (!isfinite(d.theta)) return false;
  for (const S& v : d.grad)
    if (!isfinite(v)) return false;
  for (const S& v : d.hess.reshaped())
    if (!isfinite(v)) return false;
  return true;
}

// ---------------------------------------------------------------------------------------------------
// fast == reference: each against MPFR at 256 bits (fast within its bound, the reference within its own),
// and the two within the sum of the bounds of each other. Also: finite, and theta never of the sign
// opposite to (N x Nt) . e0.
// ---------------------------------------------------------------------------------------------------
template <class S>
void agrees_with_reference(const HingeCase& h, const std::string& property) {
  const double u = u_of<S>(), kappa = condition_number(h.x);
  const auto f = fast_evaluate<S>(h.x);
  const auto r = reference::theta_derivatives<S>(h.x);
  const auto e = exact_derivatives(h.x);
  auto report = [&](double units, double bound, const std::string& reason) {
    Report rep(property, h.x);
    rep.line("family " + h.family + " (" + h.recipe + ")");
    rep.value("theta (fast)", f.theta)
        .value("theta (reference)", r.angle.theta)
        .value("theta (MPFR 256)", e.angle.theta);
    rep.values("grad (fast)", f.grad).values("grad (reference)", r.grad).values("grad (MPFR 256)", e.grad);
    rep.values("hess (fast)", f.hess).values("hess (reference)", r.hess).values("hess (MPFR 256)", e.hess);
    return rep.finish(units, bound, reason, f.hess, r.hess);
  };
  if (!finite(f)) RC_FAIL(report(INFINITY, 0, "a valid hinge must give finite results"));
  const Coordinates& x = h.x;
  const int sign =
      hinge_orientation_exact({x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}, {x[9], x[10], x[11]});
  if ((sign > 0 && f.theta < 0) || (sign < 0 && f.theta > 0) || (sign == 0 && f.theta != 0 && !f.on_branch_cut))
    RC_FAIL(report(INFINITY, 0, "theta must not have the sign opposite to (N x Nt) . e0"));
  const double fast_error = std::max({scalar_units(f.theta, S(e.angle.theta), u, 1.0),
                                      normwise_units(f.grad, e.grad, u), normwise_units(f.hess, e.hess, u)});
  const double fast_bound = fast_units<S>(kappa);
  RC_TAG(h.family);
  Measurements::get().record(property + " (fast vs MPFR) [per kappa_shape]", fast_error, shape_condition_number(h.x));
  check_units(property + " (fast vs MPFR)", fast_error, fast_bound, kappa,
              [&] { return report(fast_error, fast_bound, fast_reason<S>()); });
  const double between =
      std::max({scalar_units(f.theta, r.angle.theta, u, 1.0), normwise_units_between(f.grad, r.grad, u),
                normwise_units_between(f.hess, r.hess, u)});
  const double bound = fast_bound + reference_units<S>(kappa);
  check_units(property + " (fast vs reference)", between, bound, kappa, [&] {
    return report(
        between, bound,
        "each within its bound of the exact result: (" + fast_reason<S>() + ") + (" + reference_reason<S>() + ")");
  });
}
RC_GTEST_PROP(FastDouble, AgreesWithReferenceOnWellShapedHinges, ()) {
  agrees_with_reference<double>(*gen::well_shaped_hinge(wide_scales), name<double>("agreement, well-shaped"));
}
RC_GTEST_PROP(FastBin128, AgreesWithReferenceOnWellShapedHinges, ()) {
  agrees_with_reference<bin128>(*gen::well_shaped_hinge(wide_scales), name<bin128>("agreement, well-shaped"));
}
RC_GTEST_PROP(FastDouble, AgreesWithReferenceOnNearDegenerateHinges, ()) {
  agrees_with_reference<double>(*gen::hard_hinge(wide_scales), name<double>("agreement, hard families"));
}
RC_GTEST_PROP(FastBin128, AgreesWithReferenceOnNearDegenerateHinges, ()) {
  agrees_with_reference<bin128>(*gen::hard_hinge(wide_scales), name<bin128>("agreement, hard families"));
}

// The stronger claim for the double kernel: within c kappa_shape u (its stencil is computed in
// double-double from exact differences and rounded once, so no kappa_angle amplification of stencil
// errors appears; tolerance.hpp).
RC_GTEST_PROP(FastDouble, NearDegenerateWithinShapeCondition, ()) {
  const HingeCase h = *gen::hard_hinge(wide_scales);
  const double u = u_of<double>(), kappa_shape = shape_condition_number(h.x);
  const auto f = fast_evaluate<double>(h.x);
  const auto e = exact_derivatives(h.x);
  const double units = std::max({scalar_units(f.theta, double(e.angle.theta), u, 1.0),
                                 normwise_units(f.grad, e.grad, u), normwise_units(f.hess, e.hess, u)});
  const double bound = fast_units<double>(kappa_shape);
  RC_TAG(h.family);
  check_units("fast double: accuracy within c kappa_shape", units, bound, kappa_shape, [&] {
    Report r("fast double: accuracy within c kappa_shape", h.x);
    r.line("family " + h.family + " (" + h.recipe + ")");
    r.value("theta", f.theta).value("theta (MPFR 256)", e.angle.theta);
    r.values("grad", f.grad).values("grad (MPFR 256)", e.grad);
    r.values("hess", f.hess).values("hess (MPFR 256)", e.hess);
    return r.finish(units, bound, "c kappa_shape, c = " + std::to_string(fast_units_per_kappa<double>()), f.hess,
                    e.hess.cast<double>().eval());
  });
}

// ---------------------------------------------------------------------------------------------------
// Exact properties of the kernel: symmetric Hessian (built with mirrored writes); rotations by pi about
// an axis and reflections in coordinate planes (sign-symmetric arithmetic, as for the reference); power-
// of-two scalings (exact in the double-double arithmetic and in the kernel's own power-of-two rescaling).
// ---------------------------------------------------------------------------------------------------
template <class S>
void expect_same_bits(const std::string& property, const Coordinates& x, const Coordinates& y, const S& theta,
                      const Eigen::Matrix<S, 12, 1>& grad, const Eigen::Matrix<S, 12, 12>& hess,
                      const fast::HingeDerivatives<S>& got) {
  const bool same = got.theta == theta && got.grad == grad && got.hess == hess;
  Measurements::get().record(property, same ? 0 : 1, 0);
  if (!same) {
    const double units =
        std::max(normwise_units_between(got.hess, hess, u_of<S>()), normwise_units_between(got.grad, grad, u_of<S>()));
    Report r(property, x);
    r.line("second input " + describe(y));
    r.value("theta (expected)", theta).value("theta", got.theta);
    r.values("grad (expected)", grad).values("grad", got.grad);
    r.values("hess (expected)", hess).values("hess", got.hess);
    RC_FAIL(r.finish(units, 0, std::isnan(units) ? "bit-exact claim; a result is not finite" : "bit-exact claim",
                     got.hess, hess));
  }
}

template <class S>
void symmetric(const HingeCase& h, const std::string& property) {
  const auto f = fast_evaluate<S>(h.x);
  const Eigen::Matrix<S, 12, 12> t = f.hess.transpose();
  expect_same_bits<S>(property, h.x, h.x, f.theta, f.grad, t, f);
}
RC_GTEST_PROP(FastDouble, HessianIsExactlySymmetric, ()) {
  symmetric<double>(*gen::any_hinge(wide_scales), name<double>("Hessian symmetry"));
}
RC_GTEST_PROP(FastBin128, HessianIsExactlySymmetric, ()) {
  symmetric<bin128>(*gen::any_hinge(wide_scales), name<bin128>("Hessian symmetry"));
}

template <class S>
void exact_motion(const HingeCase& h, const Motion& m, const std::string& property) {
  const Coordinates y = apply_motion(m, h.x);
  const auto f = fast_evaluate<S>(h.x);
  const Eigen::Matrix<S, 12, 12> B = block_diagonal(m.R).cast<S>();
  const S sign(m.det);
  const S theta = (m.det < 0 && !f.on_branch_cut) ? S(-f.theta) : f.theta;
  const Eigen::Matrix<S, 12, 1> grad = sign * (B * f.grad);
  const Eigen::Matrix<S, 12, 12> hess = sign * (B * f.hess * B.transpose());
  expect_same_bits<S>(property, h.x, y, theta, grad, hess, fast_evaluate<S>(y));
}
RC_GTEST_PROP(FastDouble, PiRotationOrCoordinateReflectionIsBitExact, ()) {
  exact_motion<double>(*gen::any_hinge(wide_scales), *rc::gen::oneOf(gen::pi_rotation(), gen::coordinate_reflection()),
                       name<double>("pi rotation or reflection"));
}
RC_GTEST_PROP(FastBin128, PiRotationOrCoordinateReflectionIsBitExact, ()) {
  exact_motion<bin128>(*gen::any_hinge(wide_scales), *rc::gen::oneOf(gen::pi_rotation(), gen::coordinate_reflection()),
                       name<bin128>("pi rotation or reflection"));
}

template <class S>
void power_of_two(const HingeCase& h, int j, const std::string& property) {
  Coordinates y;
  for (int i = 0; i < 12; ++i) y[i] = std::ldexp(h.x[i], j);
  const auto f = fast_evaluate<S>(h.x);
  Eigen::Matrix<S, 12, 1> grad = f.grad;
  Eigen::Matrix<S, 12, 12> hess = f.hess;
  using std::ldexp;
  for (auto& g : grad) g = ldexp(g, -j);
  for (auto& v : hess.reshaped()) v = ldexp(v, -2 * j);
  expect_same_bits<S>(property, h.x, y, f.theta, grad, hess, fast_evaluate<S>(y));
}
RC_GTEST_PROP(FastDouble, PowerOfTwoScalingIsBitExact, ()) {
  power_of_two<double>(*gen::any_hinge({-240, 240}), *rc::gen::inRange(-60, 61), name<double>("2^j scaling"));
}
RC_GTEST_PROP(FastBin128, PowerOfTwoScalingIsBitExact, ()) {
  power_of_two<bin128>(*gen::any_hinge({-240, 240}), *rc::gen::inRange(-60, 61), name<bin128>("2^j scaling"));
}

// Relabelling (x3, x2, x1, x0): the same hinge; theta unchanged, derivatives permuted. Within twice the
// fast bound (two evaluations of one exact result).
template <class S>
void relabelling(const HingeCase& h, const std::string& property) {
  const Coordinates y = relabel_hinge(h.x);
  const double kappa = condition_number(h.x);
  const auto f = fast_evaluate<S>(h.x), g = fast_evaluate<S>(y);
  const Eigen::Matrix<S, 12, 12> P = vertex_permutation({3, 2, 1, 0}).cast<S>();
  const Eigen::Matrix<S, 12, 1> grad = P * f.grad;
  const Eigen::Matrix<S, 12, 12> hess = P * f.hess * P.transpose();
  const double u = u_of<S>();
  const double units = std::max({scalar_units(g.theta, f.theta, u, 1.0), normwise_units_between(g.grad, grad, u),
                                 normwise_units_between(g.hess, hess, u)});
  const double bound = 2 * fast_units<S>(kappa);
  check_units(property, units, bound, kappa, [&] {
    Report r(property, h.x);
    r.value("theta", f.theta).value("theta (relabelled)", g.theta);
    r.values("grad (permuted)", grad).values("grad (relabelled)", g.grad);
    r.values("hess (permuted)", hess).values("hess (relabelled)", g.hess);
    return r.finish(units, bound, "2 x (" + fast_reason<S>() + ")", g.hess, hess);
  });
}
RC_GTEST_PROP(FastDouble, RelabellingX0X3AndX1X2LeavesThetaUnchanged, ()) {
  relabelling<double>(*gen::any_hinge(wide_scales), name<double>("relabelling (x3, x2, x1, x0)"));
}
RC_GTEST_PROP(FastBin128, RelabellingX0X3AndX1X2LeavesThetaUnchanged, ()) {
  relabelling<bin128>(*gen::any_hinge(wide_scales), name<bin128>("relabelling (x3, x2, x1, x0)"));
}

// Invalid input: hinge::InputError. Exactly folded: theta = +pi, on the branch cut, finite derivatives.
template <class S>
void rejects(const HingeCase& h, const std::string& property) {
  std::string outcome;
  try {
    outcome = "evaluated: theta = " + show_exactly(fast_evaluate<S>(h.x).theta);
  } catch (const InputError&) {
    return;
  } catch (const std::exception& e) {
    outcome = std::string("threw another exception: ") + e.what();
  }
  RC_FAIL(Report(property, h.x).line(h.family).line(outcome).finish(INFINITY, 0, "must throw hinge::InputError"));
}
RC_GTEST_PROP(FastDouble, InvalidInputRejectedWithInputError, ()) {
  rejects<double>(*gen::invalid_hinge(), name<double>("invalid input"));
}
RC_GTEST_PROP(FastBin128, InvalidInputRejectedWithInputError, ()) {
  rejects<bin128>(*gen::invalid_hinge(), name<bin128>("invalid input"));
}

template <class S>
void folded(const HingeCase& h, const Motion& m, const std::string& property) {
  const Coordinates y = apply_motion(m, h.x);
  fast::HingeDerivatives<S> f;
  try {
    f = fast_evaluate<S>(y);
  } catch (const std::exception& e) {
    RC_FAIL(Report(property, y).line(std::string("threw: ") + e.what()).finish(INFINITY, 0, "must be evaluated"));
  }
  const bool ok = f.theta == boost::math::constants::pi<S>() && f.on_branch_cut && finite(f);
  Measurements::get().record(property, ok ? 0 : 1, 0);
  if (!ok)
    RC_FAIL(Report(property, y)
                .line("motion " + m.kind)
                .value("theta", f.theta)
                .line(std::string("on_branch_cut ") + (f.on_branch_cut ? "true" : "false"))
                .values("grad", f.grad)
                .finish(INFINITY, 0, "theta = +pi exactly, finite derivatives"));
}
RC_GTEST_PROP(FastDouble, FoldedHingeHasThetaPlusPiExactly, ()) {
  folded<double>(*gen::coplanar_hinge(true), *gen::exact_motion(), name<double>("folded: +pi"));
}
RC_GTEST_PROP(FastBin128, FoldedHingeHasThetaPlusPiExactly, ()) {
  folded<bin128>(*gen::coplanar_hinge(true), *gen::exact_motion(), name<bin128>("folded: +pi"));
}

// ---------------------------------------------------------------------------------------------------
// Mesh assembly (Algorithm 2, with its own rest state, Algorithm 1) against hinge::reference::assemble.
// ---------------------------------------------------------------------------------------------------
template <class S>
MeshDerivatives<S> fast_mesh(const Mesh& deformed, const Mesh& rest, const Topology& topology, Model model, double k,
                             fast::EdgeOrientation orientation) {
  fast::Assembler<S> a(topology, orientation);
  const auto coefficients = a.rest_state(rest, EnergyParameters{model, k, 0});
  return a.evaluate(deformed, coefficients, model);
}

rc::Gen<Model> models() { return rc::gen::element(Model::shells, Model::tan, Model::willmore, Model::bridson); }

template <class S>
void mesh_agrees(const MeshCase& mc, Model model, double k, fast::EdgeOrientation orientation,
                 const std::string& property) {
  const MeshEvaluation<S> ref = evaluate_mesh<S>(mc.deformed, mc.rest, model, k);
  const auto f = fast_mesh<S>(mc.deformed, mc.rest, ref.topology, model, k, orientation);
  RC_TAG(std::string(model_name(model)));
  const Eigen::Matrix<S, Eigen::Dynamic, 1> g = f.gradient;
  expect_same_mesh(property, mc, ref, f.energy, g, dense(f.hessian),
                   fast_mesh_units<S>(ref.kappa) + mesh_units<S>(ref.kappa),
                   "each within its bound: (" + fast_mesh_reason<S>() + ") + (" + mesh_reason<S>() + ")");
}
RC_GTEST_PROP(FastMeshDouble, AssemblyAgreesWithReference, ()) {
  const auto o = *rc::gen::element(fast::EdgeOrientation::first_face, fast::EdgeOrientation::second_face);
  mesh_agrees<double>(*gen::mesh(), *models(), *gen::uniform(0.5, 2), o, "fast mesh double: agreement");
}
RC_GTEST_PROP(FastMeshBin128, AssemblyAgreesWithReference, ()) {
  const auto o = *rc::gen::element(fast::EdgeOrientation::first_face, fast::EdgeOrientation::second_face);
  mesh_agrees<bin128>(*gen::mesh(), *models(), *gen::uniform(0.5, 2), o, "fast mesh bin128: agreement");
}

// Edge orientation (which face of each interior edge takes the conditional transpose of eq. (7)): in exact
// arithmetic immaterial (N0 + N~0 is symmetric); the two assembled Hessians are two evaluations of one
// exact result: within twice the bound.
RC_GTEST_PROP(FastMeshDouble, EdgeOrientationChangesTheHessianByAFewUlps, ()) {
  const MeshCase mc = *gen::mesh();
  const Model model = *models();
  const double k = *gen::uniform(0.5, 2);
  MeshEvaluation<double> first;
  first.topology = build_topology(mc.deformed);
  const auto a = fast_mesh<double>(mc.deformed, mc.rest, first.topology, model, k, fast::EdgeOrientation::first_face);
  const auto b = fast_mesh<double>(mc.deformed, mc.rest, first.topology, model, k, fast::EdgeOrientation::second_face);
  first.energy = a.energy;
  first.gradient = a.gradient;
  first.hessian = dense(a.hessian);
  measure_scales(mc.deformed, reference::rest_state<double>(mc.rest, first.topology, {model, k, 0}), model, first);
  const Eigen::VectorXd g = b.gradient;
  expect_same_mesh("fast mesh double: edge orientation", mc, first, b.energy, g, dense(b.hessian),
                   2 * fast_mesh_units<double>(first.kappa), "2 x (" + fast_mesh_reason<double>() + ")");
}

}  // namespace
}  // namespace hinge::test
