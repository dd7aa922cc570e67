// Why a candidate fails: the usual convention mismatches tried on its outputs (hinge/conformance/diagnosis.hpp).
//
// A hypothesis gives, for each case, the pair graded in its place: a forward hypothesis predicts what a
// kernel with that convention returns (from the certified values, or for another vertex order from the
// oracle on the permuted hinge) and grades the candidate against the prediction; an inverse hypothesis
// repairs the candidate's outputs (a Hessian triangle mirrored, coordinate-major variables reordered) and
// grades them against the certified values. Tolerances are the case's own (Grading).
//
// The 24 vertex orders: a kernel whose true order is s' while s was declared evaluates theta at z, z_a =
// x_{pi(a)} with pi = s o s'^-1, and its outputs, mapped back by s, are theta(z) with the derivative of z_b
// at the contract's vertex pi(b). Swapping z1, z2 together with z0, z3 changes nothing and swapping one
// pair negates theta, so the 24 orders, alone and with theta negated, make 12 predictions: one per
// choice of hinge edge {pi(1), pi(2)} (six: the tetrahedron's edges) and sign. The identity is the
// candidate as graded, its negation is "theta negated"; the other ten are the order hypotheses.
#include "hinge/conformance/diagnosis.hpp"

#include "diagnosis_engine.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <optional>

#include "hinge/core/errors.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

constexpr double pi = std::numbers::pi;

using detail::Hypothesis;
using detail::Outputs;
using detail::outputs_of;

Outputs scaled(Outputs o, double theta, double grad, double hess) {
  o.theta *= theta;
  for (double& v : o.grad) v *= grad;
  for (double& v : o.hess) v *= hess;
  return o;
}

// Variable i of the candidate's order is the contract's variable variable_map[i].
std::array<int, 12> variable_map(const Stencil& s) {
  std::array<int, 12> m{};
  for (int j = 0; j < 4; ++j)
    for (int c = 0; c < 3; ++c) m[3 * j + c] = 3 * s[j] + c;
  return m;
}

// The candidate's own arrays (its order, as it returned them) from the contract's, and back.
Outputs to_candidate(const Outputs& o, const Stencil& s) {
  const std::array<int, 12> m = variable_map(s);
  Outputs c;
  c.theta = o.theta;
  for (int i = 0; i < 12; ++i) c.grad[i] = o.grad[m[i]];
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) c.hess[12 * i + j] = o.hess[12 * m[i] + m[j]];
  return c;
}
Outputs to_contract(const Outputs& c, const Stencil& s) {
  const std::array<int, 12> m = variable_map(s);
  Outputs o;
  o.theta = c.theta;
  for (int i = 0; i < 12; ++i) o.grad[m[i]] = c.grad[i];
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) o.hess[12 * m[i] + m[j]] = c.hess[12 * i + j];
  return o;
}

std::string label_tuple(const Stencil& s, bool quoted) {
  std::string out = "(";
  for (int j = 0; j < 4; ++j) {
    if (j) out += ", ";
    if (quoted) out += '"';
    out += {'x', static_cast<char>('0' + s[j])};
    if (quoted) out += '"';
  }
  return out + ")";
}

// -theta. On the branch cut (+pi) either sign: a kernel that negates its atan2 returns -pi there, one that
// reads the hinge in the other orientation (x1 and x2 exchanged) +pi, and both are this mismatch; `got` is
// the candidate's theta.
// theta on the branch cut: +pi, as the certified value holds it in double or in float.
bool on_cut(double theta) { return theta == pi || theta == static_cast<double>(static_cast<float>(pi)); }

Outputs negated_theta(Outputs o, double got) {
  if (!on_cut(o.theta) || on_cut(-got)) o.theta = -o.theta;
  return o;
}

const char* const kSignConvention =
    "the contract's theta has the sign of (n x nt) . e0 (lifting x0 along n makes it negative): ";
const char* const kAtan2 = "theta = atan2(((N x Nt) . e0) / |e0|, N . Nt), signed, in (-pi, pi]";

// ||a - b|| per given group, relative to ||reference|| (to the case's scale where that is zero), in units
// of u, within the case's tolerance in every given group.
bool within_tolerance(const Outputs& a, const Outputs& b, const Expected& e, const CaseOutcome& o,
                      const Grading& grading) {
  const double u = unit_roundoff(grading.dtype);
  const std::array<std::pair<const double*, const double*>, 3> groups{
      {{&a.theta, &b.theta}, {a.grad.data(), b.grad.data()}, {a.hess.data(), b.hess.data()}}};
  const std::array<const double*, 3> reference{&e.values.theta, e.values.grad.data(), e.values.hess.data()};
  constexpr std::size_t sizes[3] = {1, 12, 144};
  for (int g = 0; g < 3; ++g) {
    if (!grading.given[g]) continue;
    std::array<double, 144> shifted{};  // reference + (a - b): its distance to reference is ||a - b||
    for (std::size_t k = 0; k < sizes[g]; ++k)
      shifted[k] = reference[g][k] + (groups[g].first[k] - groups[g].second[k]);
    if (!(normwise_error(shifted.data(), reference[g], sizes[g], e.conditioning.scale[g], u) <= o.tolerance[g]))
      return false;
  }
  return true;
}

class Diagnoser {
 public:
  Diagnoser(const std::vector<Expected>& expected, const std::vector<CandidateResult>& results,
            const std::vector<CaseOutcome>& outcomes, const Grading& grading, const Stencil& stencil,
            std::vector<Hypothesis> hypotheses = {})
      : expected_(expected), results_(results), outcomes_(outcomes), grading_(grading), stencil_(stencil),
        hypotheses_(std::move(hypotheses)) {
    if (hypotheses_.empty()) build_hypotheses();  // the theta kit's conventions
  }

  // The hypotheses that explain category `cases` (indices of evaluated cases), simplest first, each with
  // the later ones equivalent to it.
  std::vector<std::pair<const Hypothesis*, std::vector<const Hypothesis*>>> explain(
      const std::vector<std::size_t>& cases) {
    std::vector<const Hypothesis*> lifting;
    std::map<const Hypothesis*, std::vector<std::optional<Outputs>>> applied;
    for (const Hypothesis& h : hypotheses_) {
      if (!any_given(h.changes) || !any_given(h.differs)) continue;
      std::vector<std::optional<Outputs>> per_case;
      bool lifts = true, changes = false;
      for (const std::size_t i : cases) {
        per_case.push_back(h.apply(i));
        if (!per_case.back()) {
          lifts = false;
          break;
        }
        const Outputs& out = *per_case.back();
        Expected e = expected_[i];
        CandidateResult r = results_[i];
        const Outputs as_given = h.forward ? outputs_of(e.values) : outputs_of(r);
        if (h.forward) set(e.values, out);
        else set(r, out);
        if (compare(e, r, grading_).tier == Tier::fail) {
          lifts = false;
          break;
        }
        changes = changes || !within_tolerance(out, as_given, expected_[i], outcomes_[i], grading_);
      }
      if (lifts && changes) {
        lifting.push_back(&h);
        applied[&h] = std::move(per_case);
      }
    }
    // Equivalent: the same residual (candidate minus what it is graded against) on every case.
    std::vector<std::pair<const Hypothesis*, std::vector<const Hypothesis*>>> out;
    for (const Hypothesis* h : lifting) {
      bool merged = false;
      for (auto& [first, others] : out)
        if (equivalent(*first, applied[first], *h, applied[h], cases)) {
          others.push_back(h);
          merged = true;
          break;
        }
      if (!merged) out.push_back({h, {}});
    }
    return out;
  }

  // Whether h, taken as the candidate's convention, makes one of `cases` (evaluated cases of a category
  // that does not fail) fail: then it does not explain the candidate, whatever it lifts elsewhere.
  bool breaks(const Hypothesis& h, const std::vector<std::size_t>& cases) const {
    for (const std::size_t i : cases) {
      const std::optional<Outputs> out = h.apply(i);
      if (!out) return true;
      Expected e = expected_[i];
      CandidateResult r = results_[i];
      if (h.forward) set(e.values, *out);
      else set(r, *out);
      if (compare(e, r, grading_).tier == Tier::fail) return true;
    }
    return false;
  }

 private:
  bool any_given(const std::array<bool, 3>& groups) const {
    for (int g = 0; g < 3; ++g)
      if (groups[g] && grading_.given[g]) return true;
    return false;
  }

  static void set(CertifiedTheta& v, const Outputs& o) {
    v.theta = o.theta;
    v.grad = o.grad;
    v.hess = o.hess;
  }
  static void set(CandidateResult& r, const Outputs& o) {
    r.theta = o.theta;
    r.grad = o.grad;
    r.hess = o.hess;
  }

  // candidate - graded-against, as outputs.
  Outputs residual(const Hypothesis& h, const Outputs& applied, std::size_t i) const {
    const Outputs got = h.forward ? outputs_of(results_[i]) : applied;
    const Outputs want = h.forward ? applied : outputs_of(expected_[i].values);
    Outputs d;
    d.theta = got.theta - want.theta;
    for (int k = 0; k < 12; ++k) d.grad[k] = got.grad[k] - want.grad[k];
    for (int k = 0; k < 144; ++k) d.hess[k] = got.hess[k] - want.hess[k];
    return d;
  }

  bool equivalent(const Hypothesis& a, const std::vector<std::optional<Outputs>>& a_out, const Hypothesis& b,
                  const std::vector<std::optional<Outputs>>& b_out, const std::vector<std::size_t>& cases) const {
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const std::size_t i = cases[k];
      if (!within_tolerance(residual(a, *a_out[k], i), residual(b, *b_out[k], i), expected_[i], outcomes_[i], grading_))
        return false;
    }
    return true;
  }

  // The groups the last hypothesis added can change, and where it differs from the one before it.
  void masks(std::array<bool, 3> changes, std::array<bool, 3> differs = {true, true, true}) {
    hypotheses_.back().changes = changes;
    hypotheses_.back().differs = differs;
  }

  // `predict` maps the certified outputs (and the candidate's theta, where a prediction may go either way)
  // to what a kernel with that convention returns.
  void add_forward(std::string key, std::string explanation, std::string change,
                   std::function<std::optional<Outputs>(const Outputs&)> predict) {
    add_forward(std::move(key), std::move(explanation), std::move(change),
                [predict](const Outputs& e, double) { return predict(e); });
  }
  void add_forward(std::string key, std::string explanation, std::string change,
                   std::function<std::optional<Outputs>(const Outputs&, double)> predict) {
    hypotheses_.push_back(
        {std::move(key), std::move(explanation), std::move(change), true,
         [this, predict](std::size_t i) { return predict(outputs_of(expected_[i].values), results_[i].theta); }});
  }
  // Repairs in the candidate's own order.
  void add_inverse(std::string key, std::string explanation, std::string change,
                   std::function<Outputs(const Outputs&)> repair) {
    hypotheses_.push_back(
        {std::move(key), std::move(explanation), std::move(change), false, [this, repair](std::size_t i) {
           return std::optional<Outputs>(
               to_contract(repair(to_candidate(outputs_of(results_[i]), stencil_)), stencil_));
         }});
  }

  // theta and its derivatives at the permuted hinge z_a = x_{pi(a)}, mapped back (file comment); cached.
  std::optional<Outputs> permuted(std::size_t i, const std::array<int, 4>& perm) {
    const auto key = std::make_pair(i, perm);
    if (const auto it = cache_.find(key); it != cache_.end()) return it->second;
    std::optional<Outputs> result;
    std::array<double, 12> z{};
    const std::array<double, 12>& x = expected_[i].input.x;
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) z[3 * a + c] = x[3 * perm[a] + c];
    try {
      const CertifiedTheta t = oracle::certified_theta_derivatives(z);
      Outputs o;
      o.theta = t.theta;
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 3; ++c) o.grad[3 * perm[b] + c] = t.grad[3 * b + c];
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 3; ++c)
          for (int b = 0; b < 4; ++b)
            for (int d = 0; d < 3; ++d)
              o.hess[12 * (3 * perm[a] + c) + 3 * perm[b] + d] = t.hess[12 * (3 * a + c) + 3 * b + d];
      result = o;
    } catch (const InputError&) {
    } catch (const DomainError&) {
    }
    cache_.emplace(key, result);
    return result;
  }

  void build_hypotheses() {
    const double degrees = 180 / pi;
    const std::string swap12 = [&] {
      Stencil s = stencil_;  // the declared order with the labels x1 and x2 exchanged
      for (int& v : s) v = v == 1 ? 2 : v == 2 ? 1 : v;
      return label_tuple(s, false);
    }();
    add_forward("theta-negated", "theta negated (the same as the stencil " + swap12 + ")",
                std::string(kSignConvention) + "negate theta and its derivatives",
                [](const Outputs& e, double got) { return negated_theta(scaled(e, 1, -1, -1), got); });
    add_forward(
        "theta-only-negated", "theta negated, its derivatives not",
        std::string(kSignConvention) + "negate theta (its gradient and Hessian already have the contract's sign)",
        [](const Outputs& e, double got) { return negated_theta(e, got); });
    masks({true, false, false}, {false, true, true});
    add_forward("degrees", "theta in degrees", "return radians: multiply theta and its derivatives by pi/180",
                [=](const Outputs& e) { return scaled(e, degrees, degrees, degrees); });
    add_forward("theta-degrees", "theta in degrees (its derivatives in radians)", "return theta in radians",
                [=](const Outputs& e) { return scaled(e, degrees, 1, 1); });
    masks({true, false, false}, {false, true, true});
    add_forward("unsigned", "the unsigned angle |theta| (an acos of n . nt)",
                std::string("the contract's theta is signed: ") + kAtan2, [](const Outputs& e) {
                  const double s = e.theta < 0 ? -1 : 1;
                  Outputs o = scaled(e, s, s, s);
                  return o;
                });
    add_forward("pi-minus", "pi - |theta| (an acos of -n . nt: the angle between the triangles, not the bend)",
                std::string("theta is the bend angle, 0 for a flat hinge: ") + kAtan2, [](const Outputs& e) {
                  const double s = e.theta < 0 ? -1 : 1;
                  Outputs o = scaled(e, 1, -s, -s);
                  o.theta = pi - std::fabs(e.theta);
                  return o;
                });
    add_forward("zero-two-pi", "theta in [0, 2 pi)", "return theta in (-pi, pi]: subtract 2 pi from angles above pi",
                [](const Outputs& e) {
                  Outputs o = e;
                  if (o.theta < 0) o.theta += 2 * pi;
                  return o;
                });
    masks({true, false, false});
    add_forward("branch-cut", "-pi on the branch cut",
                "a hinge folded flat onto itself has theta = +pi, never -pi (mind atan2(-0.0, x) for x < 0)",
                [](const Outputs& e) {
                  Outputs o = e;
                  if (on_cut(o.theta)) o.theta = -o.theta;
                  return o;
                });
    masks({true, false, false});
    add_forward("gradient-negated", "the gradient negated (a force)", "return d theta / dx; the force is its negative",
                [](const Outputs& e) { return scaled(e, 1, -1, 1); });
    masks({false, true, false});
    add_forward("derivatives-negated", "the gradient and Hessian negated (a force and its Jacobian)",
                "return the derivatives of theta; the force and its Jacobian are their negatives",
                [](const Outputs& e) { return scaled(e, 1, -1, -1); });
    masks({false, true, true}, {false, false, true});
    add_inverse("hessian-upper-only",
                "a Hessian with only its upper matrix triangle right (the lower one missing or wrong)",
                "fill the whole 12 x 12 Hessian: it is symmetric, H[j][i] = H[i][j]", [](Outputs c) {
                  for (int i = 0; i < 12; ++i)
                    for (int j = 0; j < i; ++j) c.hess[12 * i + j] = c.hess[12 * j + i];
                  return c;
                });
    masks({false, false, true});
    add_inverse("hessian-lower-only",
                "a Hessian with only its lower matrix triangle right (the upper one missing or wrong)",
                "fill the whole 12 x 12 Hessian: it is symmetric, H[i][j] = H[j][i]", [](Outputs c) {
                  for (int i = 0; i < 12; ++i)
                    for (int j = i + 1; j < 12; ++j) c.hess[12 * i + j] = c.hess[12 * j + i];
                  return c;
                });
    masks({false, false, true});
    add_inverse("coordinate-major",
                "coordinate-major variables (x0.x, x1.x, x2.x, x3.x, x0.y, ...) instead of vertex-major",
                "order the gradient and Hessian vertex by vertex: x0.x, x0.y, x0.z, x1.x, ...", [](const Outputs& c) {
                  // The candidate's entry at coordinate-major index 4 c + j is variable 3 j + c.
                  Outputs o = c;
                  const auto vertex_major = [](int k) { return 3 * (k % 4) + k / 4; };
                  for (int k = 0; k < 12; ++k) o.grad[vertex_major(k)] = c.grad[k];
                  for (int k = 0; k < 12; ++k)
                    for (int l = 0; l < 12; ++l) o.hess[12 * vertex_major(k) + vertex_major(l)] = c.hess[12 * k + l];
                  return o;
                });
    masks({false, true, true});
    // The ten order hypotheses: per permutation pi with pi(1) < pi(2) (one of each pair pi, pi o (12)(03)),
    // hinge edge other than {1, 2}; the candidate's true order s' = pi^-1 o s.
    const auto true_order = [&](const std::array<int, 4>& p) {
      Stencil order{};
      for (int j = 0; j < 4; ++j)  // s'(j) = pi^-1(s(j))
        order[j] = static_cast<int>(std::find(p.begin(), p.end(), stencil_[j]) - p.begin());
      return order;
    };
    std::array<int, 4> perm{0, 1, 2, 3};
    do {
      if (perm[1] > perm[2] || (perm[1] == 1 && perm[2] == 2)) continue;
      const Stencil order = true_order(perm);
      // The same prediction: pi o (12)(03); and pi o (12), pi o (03) with theta negated.
      const std::string same = label_tuple(true_order({perm[3], perm[2], perm[1], perm[0]}), false);
      const std::string negated = label_tuple(true_order({perm[0], perm[2], perm[1], perm[3]}), false) + " or " +
                                  label_tuple(true_order({perm[3], perm[1], perm[2], perm[0]}), false);
      const std::string name = label_tuple(order, false);
      add_forward("order:" + name,
                  "the vertex order " + name + " (the same as " + same + "; or " + negated + " with theta negated)",
                  "declare stencil=" + label_tuple(order, true) +
                      " (the kernel's vertex j is that label), or reorder the kernel to the contract's hinge: edge "
                      "x1 -> x2, upper triangle (x0, x1, x2), lower (x3, x2, x1)",
                  std::function<std::optional<Outputs>(const Outputs&)>{});  // apply set below
      hypotheses_.back().apply = [this, perm](std::size_t i) {
        // The order's class includes its orders with theta negated: on the branch cut either sign of pi.
        std::optional<Outputs> o = permuted(i, perm);
        if (o && on_cut(o->theta) && on_cut(-results_[i].theta)) o->theta = -o->theta;
        return o;
      };
    } while (std::next_permutation(perm.begin(), perm.end()));
  }

  const std::vector<Expected>& expected_;
  const std::vector<CandidateResult>& results_;
  const std::vector<CaseOutcome>& outcomes_;
  const Grading& grading_;
  Stencil stencil_;
  std::vector<Hypothesis> hypotheses_;
  std::map<std::pair<std::size_t, std::array<int, 4>>, std::optional<Outputs>> cache_;
};

}  // namespace

std::string stencil_name(const Stencil& s) { return label_tuple(s, false); }

namespace {

// The findings of `diagnoser`'s hypotheses on the failing categories of `outcomes`.
std::vector<Finding> findings_of(Diagnoser& diagnoser, const std::vector<CaseOutcome>& outcomes) {
  std::vector<std::string> order;  // categories in report order
  std::map<std::string, std::vector<std::size_t>> evaluated;
  std::map<std::string, bool> failing;  // an evaluated case at tier fail: what a mismatch must lift
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const CaseOutcome& o = outcomes[i];
    if (!failing.count(o.category)) order.push_back(o.category);
    const bool ok = o.status == CandidateResult::Status::ok;
    failing[o.category] = failing[o.category] || (ok && o.tier == Tier::fail);
    if (ok) evaluated[o.category].push_back(i);
  }
  // Per failing category, its explanations (groups of equivalent hypotheses). Missing and non-finite cases
  // fail whatever the convention: the mismatches are judged on the others, and only where one of those fails.
  using Group = std::pair<const Hypothesis*, std::vector<const Hypothesis*>>;
  std::vector<std::pair<std::string, std::vector<Group>>> explained;
  std::map<std::string, int> lifted;  // per hypothesis, the categories it lifts
  for (const std::string& category : order) {
    if (!failing[category]) continue;
    explained.push_back({category, diagnoser.explain(evaluated[category])});
    for (const auto& [first, others] : explained.back().second) {
      ++lifted[first->key];
      for (const Hypothesis* h : others) ++lifted[h->key];
    }
  }
  // A convention that makes a category fail which does not fail now is not the candidate's.
  std::map<std::string, bool> consistent;
  const auto holds = [&](const Hypothesis* h) {
    const auto [it, inserted] = consistent.try_emplace(h->key, true);
    if (inserted)
      for (const std::string& category : order)
        if (!failing[category] && diagnoser.breaks(*h, evaluated[category])) it->second = false;
    return it->second;
  };
  std::vector<Finding> findings;
  for (const auto& [category, groups] : explained)
    for (const auto& [first, others] : groups) {
      // Among equivalent explanations the one that explains the most categories, then the simplest.
      std::vector<const Hypothesis*> members{first};
      members.insert(members.end(), others.begin(), others.end());
      std::vector<const Hypothesis*> candidates;
      for (const Hypothesis* h : members)
        if (holds(h)) candidates.push_back(h);
      if (candidates.empty()) continue;
      const Hypothesis* chosen =
          *std::max_element(candidates.begin(), candidates.end(),
                            [&](const Hypothesis* a, const Hypothesis* b) { return lifted[a->key] < lifted[b->key]; });
      auto it = std::find_if(findings.begin(), findings.end(), [&](const Finding& f) { return f.key == chosen->key; });
      if (it == findings.end()) {
        Finding f{chosen->key, chosen->explanation, chosen->change, {}, {}};
        std::string also;
        for (const Hypothesis* h : candidates)
          if (h != chosen) also += (also.empty() ? "" : "; ") + h->explanation;
        if (!also.empty()) f.explanation += " (on these cases also: " + also + ")";
        findings.push_back(std::move(f));
        it = findings.end() - 1;
      }
      it->categories.push_back(category);
    }
  for (Finding& f : findings) {
    std::string list;
    for (std::size_t k = 0; k < f.categories.size(); ++k) list += (k ? ", " : "") + f.categories[k];
    f.sentence = list + ": " + f.explanation + ". Change: " + f.change + ".";
  }
  return findings;
}

}  // namespace

std::vector<Finding> diagnose(const std::vector<Expected>& expected, const std::vector<CandidateResult>& results,
                              const std::vector<CaseOutcome>& outcomes, const Grading& grading,
                              const Stencil& stencil) {
  Diagnoser diagnoser(expected, results, outcomes, grading, stencil);
  return findings_of(diagnoser, outcomes);
}

namespace detail {

std::vector<Finding> explain_failures(std::vector<Hypothesis> hypotheses, const std::vector<Expected>& expected,
                                      const std::vector<CandidateResult>& results,
                                      const std::vector<CaseOutcome>& outcomes, const Grading& grading) {
  if (hypotheses.empty()) return {};
  Diagnoser diagnoser(expected, results, outcomes, grading, contract_stencil, std::move(hypotheses));
  return findings_of(diagnoser, outcomes);
}

}  // namespace detail
}  // namespace hinge::conformance
