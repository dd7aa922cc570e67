// Properties of hinge::reference's energies and of whole meshes: the energy derivatives against finite
// differences of an independent energy (one hinge, every model), and the invariances of a mesh's energy,
// gradient and Hessian: reversing every face, relabelling vertices and faces, exact motions, power-of-two
// scalings. docs/testing.md lists them with their bounds.
#include <map>

#include "hinge/reference/assemble.hpp"
#include "mesh_support.hpp"

namespace hinge::test {
namespace {

// ---------------------------------------------------------------------------------------------------
// Energy derivatives (eqs. (2)-(3)) of one hinge (a two-face mesh) against central differences of an
// independent energy: psi(theta) of docs/contract.md and docs/quantities.md written here, with the
// independent theta and a = 3 |e_bar|^2 / A_bar from the rest hinge, all in MPFR.
// ---------------------------------------------------------------------------------------------------
Mesh two_faces(const Coordinates& x) {
  Mesh m;
  for (int v = 0; v < 4; ++v) m.vertices.push_back({x[3 * v], x[3 * v + 1], x[3 * v + 2]});
  m.faces = {{0, 1, 2}, {3, 2, 1}};
  return m;
}

// psi and its first three derivatives in theta, for the scale of the comparison (docs/testing.md).
struct PsiSeries {
  mpfr value, d1, d2, d3;
};
PsiSeries psi_series(Model model, const mpfr& k, const mpfr& a, const mpfr& theta, const mpfr& theta_bar) {
  const mpfr ka = k * a;
  switch (model) {
    case Model::shells: {  // k a (theta - theta_bar)^2
      const mpfr d = theta - theta_bar;
      return {ka * d * d, 2 * ka * d, 2 * ka, mpfr(0)};
    }
    case Model::tan: {  // k a (phi - phi_bar)^2, phi = 2 tan(theta/2): phi' = 1 + t^2, phi'' = t phi', phi''' = phi' (1
                        // + 3 t^2) / 2
      const mpfr t = tan(theta / 2), e = 2 * t - 2 * tan(theta_bar / 2);
      const mpfr p1 = 1 + t * t, p2 = t * p1, p3 = p1 * (1 + 3 * t * t) / 2;
      return {ka * e * e, 2 * ka * e * p1, 2 * ka * (p1 * p1 + e * p2), 2 * ka * (3 * p1 * p2 + e * p3)};
    }
    case Model::willmore: {  // k a sin^2(theta/2)
      const mpfr s = sin(theta / 2);
      return {ka * s * s, ka * sin(theta) / 2, ka * cos(theta) / 2, -ka * sin(theta) / 2};
    }
    default: {  // bridson: A (cos(theta/2) - B theta), A = -2 k a, B = -sin(theta_bar/2) / 2
      const mpfr A = -2 * ka, B = -sin(theta_bar / 2) / 2;
      return {A * (cos(theta / 2) - B * theta), A * (-sin(theta / 2) / 2 - B), -A * cos(theta / 2) / 4,
              A * sin(theta / 2) / 8};
    }
  }
}

std::array<mpfr, 12> to_mpfr(const Coordinates& x) {
  std::array<mpfr, 12> p;
  for (int i = 0; i < 12; ++i) p[i] = x[i];
  return p;
}

// a = 3 |e_bar|^2 / A_bar (docs/contract.md), A_bar the two rest areas summed.
mpfr stiffness_weight(const Coordinates& rest) {
  const auto p = to_mpfr(rest);
  auto sub = [&p](int a, int b) {
    return std::array<mpfr, 3>{p[3 * a] - p[3 * b], p[3 * a + 1] - p[3 * b + 1], p[3 * a + 2] - p[3 * b + 2]};
  };
  auto cross_norm = [](const std::array<mpfr, 3>& u, const std::array<mpfr, 3>& v) {
    const mpfr c0 = u[1] * v[2] - u[2] * v[1], c1 = u[2] * v[0] - u[0] * v[2], c2 = u[0] * v[1] - u[1] * v[0];
    return mpfr(sqrt(c0 * c0 + c1 * c1 + c2 * c2));
  };
  const auto e0 = sub(2, 1);
  const mpfr area = (cross_norm(sub(1, 0), sub(2, 0)) + cross_norm(sub(2, 3), sub(1, 3))) / 2;
  return 3 * (e0[0] * e0[0] + e0[1] * e0[1] + e0[2] * e0[2]) / area;
}

template <class S>
void energy_finite_differences(const HingeCase& deformed, const HingeCase& rest, Model model, double k,
                               const std::string& property) {
  const double u = u_of<S>(), kappa = condition_number(deformed.x);
  // theta (and theta_bar) within 2.5 of 0: the tan energy's derivatives grow as (1 + tan^2(theta/2))^k.
  const auto d = reference::theta_derivatives<double>(deformed.x);
  const auto r = reference::theta_derivatives<double>(rest.x);
  RC_PRE(std::abs(d.angle.theta) <= 2.5 && std::abs(r.angle.theta) <= 2.5);
  const Mesh m = two_faces(deformed.x), m_rest = two_faces(rest.x);
  const Topology topology = build_topology(m);
  const EnergyParameters parameters{model, k, 0};
  const auto coefficients = reference::rest_state<S>(m_rest, topology, parameters);
  const auto got = reference::assemble<S>(m, topology, coefficients, model);
  const Eigen::Matrix<S, 12, 12> hess = dense(got.hessian);
  const Eigen::Matrix<S, 12, 1> grad = got.gradient;

  set_mpfr_bits(fd_bits);
  const mpfr kk(k), a = stiffness_weight(rest.x), theta_bar = independent_theta(to_mpfr(rest.x));
  const Independent fd = test::finite_differences(deformed.x, [&](const std::array<mpfr, 12>& p) {
    return psi_series(model, kk, a, independent_theta(p), theta_bar).value;
  });
  // Scale: psi', psi'', psi''' at the exact theta times the sizes of grad theta and Hess theta (from the
  // reference in MPFR: a size only). An error delta in theta moves psi' by psi'' delta and psi'' by
  // psi''' delta: the scale covers those as well as the relative errors of grad and Hess theta.
  set_mpfr_bits(fd_bits);
  const PsiSeries ps = psi_series(model, kk, a, independent_theta(to_mpfr(deformed.x)), theta_bar);
  const auto e = exact_derivatives(deformed.x);
  const double w = to_double(mpfr(abs(ps.d1) + abs(ps.d2) + abs(ps.d3)));
  const double g = to_double(mpfr(e.grad.norm())), h = to_double(mpfr(e.hess.norm()));
  const double energy_scale = to_double(mpfr(abs(ps.value))) + w, gradient_scale = w * g,
               hessian_scale = w * (h + g * g);
  const double units = std::max({scalar_units(got.energy, S(fd.theta), u, energy_scale),
                                 normwise_units_between(grad, fd.grad.template cast<S>().eval(), u, gradient_scale),
                                 normwise_units_between(hess, fd.hess.template cast<S>().eval(), u, hessian_scale)});
  const double bound = energy_units<S>(kappa);
  RC_TAG(std::string(model_name(model)));
  check_units(property, units, bound, kappa, [&] {
    Report rep(property, deformed.x);
    rep.line("rest " + describe(rest.x) + ", model " + std::string(model_name(model)) + ", k = " + show_exactly(k));
    rep.value("energy", got.energy).value("energy (independent, MPFR 400)", fd.theta);
    rep.values("gradient", grad).values("gradient (central differences)", fd.grad);
    rep.values("hessian", hess).values("hessian (central differences)", fd.hess);
    rep.line("scales: energy " + show_exactly(energy_scale) + ", gradient " + show_exactly(gradient_scale) +
             ", hessian " + show_exactly(hessian_scale));
    return rep.finish(units, bound, energy_reason<S>(), hess, fd.hess.template cast<S>().eval());
  });
}

rc::Gen<Model> models() { return rc::gen::element(Model::shells, Model::tan, Model::willmore, Model::bridson); }

RC_GTEST_PROP(ReferenceDouble, EnergyDerivativesMatchFiniteDifferences, ()) {
  energy_finite_differences<double>(*gen::well_shaped_hinge(), *gen::well_shaped_hinge(), *models(),
                                    *gen::uniform(0.5, 2), "reference double: energy finite differences");
}
RC_GTEST_PROP(ReferenceBin128, EnergyDerivativesMatchFiniteDifferences, ()) {
  energy_finite_differences<bin128>(*gen::well_shaped_hinge(), *gen::well_shaped_hinge(), *models(),
                                    *gen::uniform(0.5, 2), "reference bin128: energy finite differences");
}

// ---------------------------------------------------------------------------------------------------
// Whole meshes (hinge::reference::assemble in double).
// ---------------------------------------------------------------------------------------------------

// Reversing every face reverses every hinge (docs/testing.md): for the edge x1 -> x2 of the upper face
// (x0, x1, x2), the reversed face (x0, x2, x1) holds x2 -> x1, so the hinge becomes (x0, x2, x1, x3) (or
// its relabelling (x3, x1, x2, x0), the same hinge): N -> -N, Nt -> -Nt, e0 -> -e0, and theta -> -theta
// (+pi stays +pi). The rest angles change sign too, and every energy depends on theta - theta_bar through
// an odd phi (theta, 2 tan(theta/2)) or is even (Willmore), so E, grad E and Hess E are unchanged.
// Two evaluations of the same exact result: within twice the bound.
RC_GTEST_PROP(ReferenceMesh, ReversingEveryFaceNegatesThetaAndKeepsTheEnergy, ()) {
  const MeshCase mc = *gen::mesh();
  const Model model = *models();
  const double k = *gen::uniform(0.5, 2);
  const std::string property = "reference mesh: reversal of every face";
  const MeshEvaluation<double> a = evaluate_mesh<double>(mc.deformed, mc.rest, model, k);
  const MeshEvaluation<double> b = evaluate_mesh<double>(reversed(mc.deformed), reversed(mc.rest), model, k);
  // theta per hinge, matched by the undirected edge.
  std::map<std::pair<Index, Index>, double> theta_b;
  for (std::size_t i = 0; i < b.topology.hinges.size(); ++i) {
    const Hinge& h = b.topology.hinges[i];
    theta_b[std::minmax(h.x[1], h.x[2])] = b.theta[i];
  }
  RC_ASSERT(theta_b.size() == a.topology.hinges.size());
  const double bound = 2 * reference_units<double>(a.kappa);
  double worst = 0;
  for (std::size_t i = 0; i < a.topology.hinges.size(); ++i) {
    const Hinge& h = a.topology.hinges[i];
    const double t = theta_b.at(std::minmax(h.x[1], h.x[2]));
    const double units = scalar_units(t, -a.theta[i], 0x1p-53, 1.0);
    worst = std::max(worst, units);
    if (!(units <= bound))
      RC_FAIL(Report(property, hinge_coordinates(mc.deformed, h))
                  .line("hinge " + std::to_string(i) + " of the mesh (edge " + std::to_string(h.x[1]) + "-" +
                        std::to_string(h.x[2]) + ")")
                  .value("theta", a.theta[i])
                  .value("theta of the reversed mesh", t)
                  .finish(units, bound, "theta -> -theta within 2 x (" + reference_reason<double>() + ")"));
  }
  Measurements::get().record(property + " (theta)", worst, a.kappa);
  expect_same_mesh(property, mc, a, b.energy, b.gradient, b.hessian, 2 * mesh_units<double>(a.kappa),
                   "two evaluations of one exact result: 2 x (" + mesh_reason<double>() + ")");
}

// Relabelling vertices and faces and rotating each face's vertex list: the same surface. E is unchanged,
// grad E and Hess E are permuted. Within twice the bound (the sums run in another order).
RC_GTEST_PROP(ReferenceMesh, RelabellingVerticesAndFacesPermutesTheDerivatives, ()) {
  const MeshCase mc = *gen::mesh();
  const Model model = *models();
  const double k = *gen::uniform(0.5, 2);
  const auto r = *gen::mesh_relabelling(mc.deformed.vertices.size(), mc.deformed.faces.size());
  const MeshEvaluation<double> a = evaluate_mesh<double>(mc.deformed, mc.rest, model, k);
  const MeshEvaluation<double> b = evaluate_mesh<double>(relabel(mc.deformed, r), relabel(mc.rest, r), model, k);
  // Back to the original numbering: old vertex v is new vertex r.vertex_map[v].
  const Eigen::Index n = static_cast<Eigen::Index>(mc.deformed.vertices.size());
  Eigen::VectorXd g(3 * n);
  Eigen::MatrixXd H(3 * n, 3 * n);
  for (Eigen::Index v = 0; v < n; ++v)
    for (int c = 0; c < 3; ++c) g[3 * v + c] = b.gradient[3 * r.vertex_map[static_cast<std::size_t>(v)] + c];
  for (Eigen::Index v = 0; v < n; ++v)
    for (Eigen::Index w = 0; w < n; ++w)
      H.block<3, 3>(3 * v, 3 * w) = b.hessian.block<3, 3>(3 * r.vertex_map[static_cast<std::size_t>(v)],
                                                          3 * r.vertex_map[static_cast<std::size_t>(w)]);
  expect_same_mesh("reference mesh: relabelling", mc, a, b.energy, g, H, 2 * mesh_units<double>(a.kappa),
                   "two evaluations of one exact result: 2 x (" + mesh_reason<double>() + ")");
}

// Exact motions of both meshes: a rotation by pi about an axis or a reflection in a coordinate plane.
// Per hinge the results are bit-exact (ReferenceDouble.*BitExact), theta_bar transforms alike, psi and its
// derivatives are odd or even in theta - theta_bar exactly, and the sums run in the same order: E is
// bit-exact, grad E -> R grad E, Hess E -> R Hess E R^T bit for bit.
RC_GTEST_PROP(ReferenceMesh, ExactMotionIsBitExact, ()) {
  const MeshCase mc = *gen::mesh();
  const Model model = *models();
  const double k = *gen::uniform(0.5, 2);
  const Motion m = *rc::gen::oneOf(gen::pi_rotation(), gen::coordinate_reflection());
  const MeshEvaluation<double> a = evaluate_mesh<double>(mc.deformed, mc.rest, model, k);
  const MeshEvaluation<double> b = evaluate_mesh<double>(moved(mc.deformed, m), moved(mc.rest, m), model, k);
  const Eigen::Index n = static_cast<Eigen::Index>(mc.deformed.vertices.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (Eigen::Index v = 0; v < n; ++v) B.block<3, 3>(3 * v, 3 * v) = m.R;
  const Eigen::VectorXd g = B * a.gradient;
  const Eigen::MatrixXd H = B * a.hessian * B.transpose();
  expect_same_mesh("reference mesh: " + m.kind, mc, b, a.energy, g, H, 0, "bit-exact claim");
}

// Power-of-two scaling of the deformed mesh (the rest state kept): theta is bit-exactly invariant per
// hinge, so E is bit-exact, grad E scales by 2^-j and Hess E by 2^-2j exactly.
RC_GTEST_PROP(ReferenceMesh, PowerOfTwoScalingIsBitExact, ()) {
  const MeshCase mc = *gen::mesh();
  const Model model = *models();
  const double k = *gen::uniform(0.5, 2);
  const int j = *rc::gen::inRange(-200, 201);
  Mesh scaled = mc.deformed;
  for (auto& v : scaled.vertices)
    for (double& c : v) c = std::ldexp(c, j);
  const MeshEvaluation<double> a = evaluate_mesh<double>(mc.deformed, mc.rest, model, k);
  const MeshEvaluation<double> b = evaluate_mesh<double>(scaled, mc.rest, model, k);
  Eigen::VectorXd g = a.gradient;
  Eigen::MatrixXd H = a.hessian;
  for (double& v : g.reshaped()) v = std::ldexp(v, -j);
  for (double& v : H.reshaped()) v = std::ldexp(v, -2 * j);
  expect_same_mesh("reference mesh: 2^j scaling", mc, b, a.energy, g, H, 0, "bit-exact claim");
}

}  // namespace
}  // namespace hinge::test
