// Why a bending term fails (hinge/conformance/energy_diagnosis.hpp). Every hypothesis is a forward one: it
// predicts what a term with the mistake returns, from the certified theta, grad theta and Hess theta of X
// and theta_bar of R, evaluated in double (psi of hinge/core/energy.hpp; eqs. (2) and (3) per hinge), or as
// the certified outputs times a factor; where the mistake changes nothing (a rest angle in [0, pi] under
// "[0, 2 pi)") the certified outputs themselves. A prediction in double is within a few units of u times
// the case's condition number of the exact one, far inside the `approximate` tier a hypothesis must reach.
#include "hinge/conformance/energy_diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include <Eigen/Eigenvalues>

#include "diagnosis_engine.hpp"
#include "hinge/conformance/energy_sets.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

using detail::Hypothesis;
using detail::Outputs;
constexpr double pi = std::numbers::pi;

// What the prediction needs of a case, computed once.
struct CaseData {
  oracle::CertifiedTheta x;  // theta, grad theta, Hess theta of X (certified)
  double theta_bar = 0;      // of R (certified)
  double weight = 0;
  RestShape rest;
};

class EnergyHypotheses {
 public:
  EnergyHypotheses(const std::vector<Expected>& expected, const EnergyProblem& problem,
                   const std::vector<double>& weights, bool diagonal_blocks)
      : expected_(expected), problem_(problem), diagonal_(diagonal_blocks) {
    data_.reserve(expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      CaseData d;
      d.x = oracle::certified_theta_derivatives(expected[i].input.x);
      d.theta_bar = oracle::certified_theta_derivatives(*expected[i].input.rest).theta;
      d.weight = weights[i];
      d.rest = rest_shape(*expected[i].input.rest);
      data_.push_back(std::move(d));
    }
  }

  std::vector<Hypothesis> build() {
    std::vector<Hypothesis> out;
    const bool exact = problem_.hessian == HessianKind::exact;
    // The Hessian treatment (not for quadratic: its Hessian is constant, with no Gauss-Newton one).
    if (problem_.hessian == HessianKind::projected) {
      out.push_back(treatment("exact-given-projected",
                              "the exact Hessian given where the projected one was declared (its negative "
                              "eigenvalues kept)",
                              "declare hessian=\"exact\", or set each hinge's negative eigenvalues to zero", false));
      out.push_back(treatment("gauss-newton-given-projected",
                              "a Gauss-Newton Hessian (c f'' grad theta grad theta^T) given where the projected one "
                              "was declared",
                              "declare hessian=\"gauss-newton\", or project each hinge's exact Hessian", true));
    } else if (!problem_.quadratic)
      out.push_back(predicting(
          exact ? "gauss-newton-given" : "exact-given",
          exact ? "a Gauss-Newton Hessian (c f'' grad theta grad theta^T) given where the exact one "
                  "was declared"
                : "the exact Hessian given where the Gauss-Newton one was declared",
          exact ? "declare hessian=\"gauss-newton\" if that is what the solver wants, or add "
                  "c f' Hess theta"
                : "declare hessian=\"exact\", or drop the term c f' Hess theta",
          [](double tb) { return tb; }, exact));  // the other treatment: GN where exact was declared
    // The rest angle.
    const bool rest_angle = !problem_.quadratic && problem_.model != Model::willmore;  // no theta_bar in psi
    if (rest_angle) {
      out.push_back(predicting("rest-angle-ignored", "the rest angle ignored (theta_bar = 0: a force at rest)",
                               "compute theta_bar from the rest hinge R (with the contract's sign and (-pi, pi] "
                               "range), do not assume a flat rest state",
                               [](double) { return 0.0; }));
      out.push_back(predicting("rest-angle-negated", "the rest angle negated (-theta_bar)",
                               "measure theta_bar with the same sign convention as theta",
                               [](double tb) { return -tb; }));
      out.push_back(predicting(
          "rest-angle-0-2pi", "the rest angle in [0, 2 pi) (theta_bar + 2 pi where it is negative)",
          "bring theta_bar into (-pi, pi], the range of theta", [](double tb) { return tb < 0 ? tb + 2 * pi : tb; }));
      out.push_back(predicting(
          "rest-angle-minus-2pi", "the rest angle in (-2 pi, 0] (theta_bar - 2 pi where it is positive)",
          "bring theta_bar into (-pi, pi], the range of theta", [](double tb) { return tb > 0 ? tb - 2 * pi : tb; }));
      out.push_back(predicting("rest-angle-degrees", "the rest angle in degrees (theta_bar * 180 / pi)",
                               "give theta_bar in radians", [](double tb) { return tb * 180 / pi; }));
    }
    // A constant factor on every hinge: p/q, then (180/pi)^(+-1, +-2).
    for (int p = 1; p <= 12; ++p)
      for (int q = 1; q <= 12; ++q) {
        if (p == q || std::gcd(p, q) != 1) continue;
        const double f = static_cast<double>(p) / q;
        const std::string ratio = q == 1 ? std::to_string(p) : std::to_string(p) + "/" + std::to_string(q);
        std::string change = "remove the factor " + ratio;
        if (p == 1 && q == 3) change += " (with the contract's weight w = 3 |e_bar|^2 / A_bar: its 3 is missing)";
        if (p == 1 && q == 2)
          change += " (a 1/2 in front of the energy: psi = k w f has none; fold it into k or the weight)";
        out.push_back(scaling("factor:" + ratio, "the term is " + ratio + " times the declared one on every hinge",
                              change, [f](std::size_t) { return f; }));
      }
    for (const int power : {1, -1, 2, -2}) {
      const double f = std::pow(180 / pi, power);
      const std::string name = "(180/pi)^" + std::to_string(power);
      out.push_back(scaling("factor:" + name,
                            "the term is " + name + " times the declared one on every hinge (degrees)",
                            "measure the angles in radians", [f](std::size_t) { return f; }));
    }
    // A factor of the rest hinge.
    const auto edge = [this](std::size_t i) { return data_[i].rest.edge; };
    const auto area = [this](std::size_t i) { return data_[i].rest.area0 + data_[i].rest.area3; };
    const auto h0 = [this](std::size_t i) { return 2 * data_[i].rest.area0 / data_[i].rest.edge; };
    const auto h3 = [this](std::size_t i) { return 2 * data_[i].rest.area3 / data_[i].rest.edge; };
    const std::string weight = ", or declare the weight the term uses (weight=: a name or a callable of R)";
    out.push_back(scaling("factor:edge", "the term has an extra factor |e_bar| (the rest hinge edge's length)",
                          "remove the |e_bar|" + weight, edge));
    out.push_back(scaling("factor:1/edge", "the term misses a factor |e_bar| (divided by the rest edge length)",
                          "multiply by |e_bar|" + weight, [edge](std::size_t i) { return 1 / edge(i); }));
    out.push_back(scaling("factor:edge^2", "the term has an extra factor |e_bar|^2", "remove the |e_bar|^2" + weight,
                          [edge](std::size_t i) { return edge(i) * edge(i); }));
    out.push_back(scaling("factor:area", "the term has an extra factor A_bar (the rest triangles' area)",
                          "remove the A_bar" + weight, area));
    out.push_back(scaling("factor:1/area", "the term misses a factor A_bar (divided by the rest area once more)",
                          "divide by A_bar once" + weight, [area](std::size_t i) { return 1 / area(i); }));
    out.push_back(scaling("factor:h0", "the term has an extra factor h0 (the rest altitude of x0 over the hinge edge)",
                          "remove the altitude" + weight, h0));
    out.push_back(scaling("factor:h3", "the term has an extra factor h3 (the rest altitude of x3 over the hinge edge)",
                          "remove the altitude" + weight, h3));
    out.push_back(scaling("factor:1/h0", "the term misses a factor h0 (divided by the rest altitude of x0)",
                          "do not divide by the altitude" + weight, [h0](std::size_t i) { return 1 / h0(i); }));
    out.push_back(scaling("factor:1/h3", "the term misses a factor h3 (divided by the rest altitude of x3)",
                          "do not divide by the altitude" + weight, [h3](std::size_t i) { return 1 / h3(i); }));
    return out;
  }

 private:
  // psi, its gradient and Hessian (exact or Gauss-Newton) in double with rest angle `theta_bar`; nothing where
  // the energy is infinite there.
  std::optional<Outputs> evaluate(std::size_t i, double theta_bar, bool gauss_newton, bool project = false) const {
    const CaseData& d = data_[i];
    HingeCoefficients<double> c;
    c.k = problem_.k;
    c.a = d.weight;
    c.theta_bar = theta_bar;
    c.phi_bar = 2 * std::tan(theta_bar / 2);
    const BendAngle<double> b{d.x.theta, std::tan(d.x.theta / 2), d.x.theta == pi};
    Psi<double> p;
    try {
      p = psi(problem_.model, c, b);
    } catch (const DomainError&) {
      return std::nullopt;
    }
    // With L = 2^e the size of the hinges (exact scalings): grad theta L and Hess theta L^2 are of order one,
    // so that the products neither over- nor underflow where the scales category reaches 2^-500 and 2^500.
    const int e = std::ilogb(expected_[i].conditioning.length);
    std::array<double, 12> g{};
    for (int r = 0; r < 12; ++r) g[r] = std::ldexp(d.x.grad[r], e);
    Outputs o;
    o.theta = p.value;
    for (int r = 0; r < 12; ++r) o.grad[r] = std::ldexp(p.d1 * g[r], -e);  // eq. (2), one hinge
    for (int r = 0; r < 12; ++r)
      for (int col = 0; col < 12; ++col) {  // eq. (3), one hinge
        const double h = gauss_newton ? 0.0 : p.d1 * std::ldexp(d.x.hess[12 * r + col], 2 * e);
        o.hess[12 * r + col] = std::ldexp(h + p.d2 * g[r] * g[col], -2 * e);
      }
    if (project) {  // the projected treatment, in double (Eigen's self-adjoint solver)
      using Matrix12 = Eigen::Matrix<double, 12, 12, Eigen::RowMajor>;
      const Eigen::SelfAdjointEigenSolver<Matrix12> eig(Eigen::Map<const Matrix12>(o.hess.data()));
      const Matrix12 projected =
          eig.eigenvectors() * eig.eigenvalues().cwiseMax(0).asDiagonal() * eig.eigenvectors().transpose();
      Eigen::Map<Matrix12>(o.hess.data()) = projected;
    }
    if (diagonal_) keep_diagonal_blocks(o.hess.data());
    return o;
  }

  // A term with rest angle rest(theta_bar) and the Hessian `gauss_newton` (default: the declared one); where
  // that changes neither, the certified outputs.
  template <class Rest>
  Hypothesis predicting(std::string key, std::string explanation, std::string change, Rest rest,
                        std::optional<bool> gauss_newton = std::nullopt) const {
    Hypothesis h;
    h.key = std::move(key);
    h.explanation = std::move(explanation);
    h.change = std::move(change);
    const bool declared = problem_.hessian == HessianKind::gauss_newton;
    const bool gn = gauss_newton.value_or(declared);
    if (gn == declared) h.changes = {true, true, false};
    else h.changes = {false, false, true};
    h.apply = [this, rest, gn, declared](std::size_t i) -> std::optional<Outputs> {
      const double theta_bar = rest(data_[i].theta_bar);
      if (theta_bar == data_[i].theta_bar && gn == declared) return detail::outputs_of(expected_[i].values);
      std::optional<Outputs> o = evaluate(i, theta_bar, gn, problem_.hessian == HessianKind::projected);
      if (o && gn != declared) {  // only the Hessian differs: psi and the gradient stay certified
        o->theta = expected_[i].values.theta;
        o->grad = expected_[i].values.grad;
      }
      return o;
    };
    return h;
  }

  // The certified energy and gradient with the exact (or Gauss-Newton) Hessian evaluated in double: a term
  // that gives that Hessian where the projected one was declared.
  Hypothesis treatment(std::string key, std::string explanation, std::string change, bool gauss_newton) const {
    Hypothesis h;
    h.key = std::move(key);
    h.explanation = std::move(explanation);
    h.change = std::move(change);
    h.changes = {false, false, true};
    h.apply = [this, gauss_newton](std::size_t i) -> std::optional<Outputs> {
      std::optional<Outputs> o = evaluate(i, data_[i].theta_bar, gauss_newton);
      if (o) {
        o->theta = expected_[i].values.theta;
        o->grad = expected_[i].values.grad;
      }
      return o;
    };
    return h;
  }

  // The certified outputs times factor(i).
  template <class Factor>
  Hypothesis scaling(std::string key, std::string explanation, std::string change, Factor factor) const {
    Hypothesis h;
    h.key = std::move(key);
    h.explanation = std::move(explanation);
    h.change = std::move(change);
    h.apply = [this, factor](std::size_t i) -> std::optional<Outputs> {
      Outputs o = detail::outputs_of(expected_[i].values);
      const double f = factor(i);
      o.theta *= f;
      for (double& v : o.grad) v *= f;
      for (double& v : o.hess) v *= f;
      return o;
    };
    return h;
  }

  const std::vector<Expected>& expected_;
  EnergyProblem problem_;
  bool diagonal_;
  std::vector<CaseData> data_;
};

}  // namespace

std::vector<Finding> diagnose_energy(const std::vector<Expected>& expected, const std::vector<CandidateResult>& results,
                                     const std::vector<CaseOutcome>& outcomes, const Grading& grading,
                                     const EnergyProblem& problem, const std::vector<double>& weights,
                                     bool diagonal_blocks) {
  bool any_failing = false;
  for (const CaseOutcome& o : outcomes) any_failing = any_failing || !o.pass;
  if (!any_failing) return {};
  EnergyHypotheses hypotheses(expected, problem, weights, diagonal_blocks);
  std::vector<Finding> findings = detail::explain_failures(hypotheses.build(), expected, results, outcomes, grading);
  // A factor applies to every hinge: where several factors each lift some categories (ill-conditioned ones, whose
  // `approximate` band is wide, admit many), only those lifting the most are the term's; the others are dropped.
  std::size_t most = 0;
  for (const Finding& f : findings)
    if (f.key.starts_with("factor:")) most = std::max(most, f.categories.size());
  std::erase_if(findings, [&](const Finding& f) { return f.key.starts_with("factor:") && f.categories.size() < most; });
  // Up to 36 categories: a finding that explains many is said in a few words, not listed.
  std::vector<std::string> failing;
  for (const CaseOutcome& o : outcomes)
    if (!o.pass && std::find(failing.begin(), failing.end(), o.category) == failing.end())
      failing.push_back(o.category);
  for (Finding& f : findings) {
    if (f.categories.size() <= 4) continue;
    std::string where = f.categories.size() == failing.size()
                            ? "every failing category (" + std::to_string(failing.size()) + ")"
                            : f.categories[0] + ", " + f.categories[1] + ", " + f.categories[2] + " and " +
                                  std::to_string(f.categories.size() - 3) + " more of the " +
                                  std::to_string(failing.size()) + " failing categories";
    f.sentence = where + ": " + f.explanation + ". Change: " + f.change + ".";
  }
  return findings;
}

}  // namespace hinge::conformance
