// The consistency checks of the energy conformance (hinge/conformance/consistency.hpp; the contract,
// CONVENTIONS.md "Conformance of bending energies (contract version 3)", bullet "Consistency checks").
//
// Error model of every estimate: a candidate's output f at coordinates x is taken to be within
// 16 (1 + kappa_f) u |f| of the exact one (the contract's 16 (1 + kappa) u), with kappa_f = ||J_f|| ||x|| / ||f||
// the output's condition number with respect to relative perturbations of the coordinates (J_f its Jacobian:
// for the energy, the Richardson differences of the candidate's own energy; for the gradient, those of its own
// gradient; for the Hessian, central differences of its own Hessian). ||x|| is the absolute size of the
// coordinates, not L: what a coordinate's rounding (and a translation's) perturbs is relative to |x_i|. These
// Jacobians are the candidate's own derivatives measured independently of the outputs they judge, so a wrong
// gradient cannot loosen the estimate of its own check.
#include "hinge/conformance/consistency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace hinge::conformance {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr int levels = 3;  // steps h, 2h, 4h: two Richardson levels R(h), R(2h)

// The difference checks' steps, as the exponent of h / 2^floor(log2 L). Richardson-extrapolated central
// differences R(h) = (4 D(h) - D(2h)) / 3 leave a truncation error h^4 |E^(5)| / 30 (|R(h) - R(2h)| is 15 times
// it); the rounding of the candidate's energy adds about u |E| / h. With |E^(5)| ~ C |E'| / L^4 the two balance
// at (h / L)^5 ~ u / C, and C reaches 2^8 and more on well-shaped hinges (tan near pi). Measured on the 60
// well-shaped cases of the test (shells, tan, willmore, bridson; worst estimate relative to ||g|| or ||H||):
//   float64 (u = 2^-53): 2^-10: 6e-8 (truncation), 2^-11: 4e-9, 2^-12: 3e-10 (truncation ~ rounding), so 2^-12;
//   float32 (u = 2^-24): 2^-5: 7e-2 (truncation), 2^-6: 4e-3, 2^-7: 7e-4 (rounding, 8 times it above the floor
//   2^-8 on a fifth of the checks), so 2^-6: only steep energies (tan near pi) have thresholds above the floor.
constexpr int float64_step_exponent = -12;
constexpr int float32_step_exponent = -6;

double round_to(Dtype d, double v) { return d == Dtype::float32 ? static_cast<double>(static_cast<float>(v)) : v; }

// The spacing of the dtype's numbers in the binade of m > 0.
double ulp_of(Dtype d, double m) {
  const int digits = d == Dtype::float32 ? 24 : 53;
  const int min_exponent = d == Dtype::float32 ? -126 : -1022;
  return std::ldexp(1.0, std::max(std::ilogb(m), min_exponent) - (digits - 1));
}

double norm(const double* v, std::size_t n) {
  double s = 0;
  for (std::size_t i = 0; i < n; ++i) s += v[i] * v[i];
  return std::sqrt(s);
}
template <std::size_t N>
double norm(const std::array<double, N>& v) {
  return norm(v.data(), N);
}

// L: the longest of the five edge vectors x1 - x0, x2 - x0, x2 - x1, x3 - x1, x3 - x2.
double longest_edge(const std::array<double, 12>& x) {
  static constexpr int edges[5][2] = {{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}};
  double longest = 0;
  for (const auto& [a, b] : edges) {
    const double d[3] = {x[3 * b] - x[3 * a], x[3 * b + 1] - x[3 * a + 1], x[3 * b + 2] - x[3 * a + 2]};
    longest = std::max(longest, norm(d, 3));
  }
  return longest;
}

std::string coordinate_name(int j) {
  std::string s = "x";
  s += static_cast<char>('0' + j / 3);
  s += '.';
  s += static_cast<char>('x' + j % 3);
  return s;
}

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

// Where the probes of a case are (consistency.hpp, ConsistencyPlan).
std::size_t difference_probe(std::size_t first, int j, int level, bool plus) {
  return first + 1 + static_cast<std::size_t>(6 * j + 2 * level + (plus ? 0 : 1));
}
std::size_t motion_probe(std::size_t first, std::size_t m) { return first + 1 + 12 * levels * 2 + m; }

std::string probe_name(const ConsistencyPlan& plan, std::size_t case_index, std::size_t p) {
  const std::size_t offset = p - plan.first[case_index];
  if (offset == 0) return "the base point";
  if (offset > 12 * levels * 2) return rigid_motions()[offset - 1 - 12 * levels * 2].name;
  const int k = static_cast<int>(offset - 1), j = k / 6, level = (k % 6) / 2;
  std::string s = coordinate_name(j);
  s += k % 2 == 0 ? " + " : " - ";
  s += level == 0 ? "h" : level == 1 ? "2h" : "4h";
  return s;
}

// The normalizer of an output: its norm, or `fallback` (c, in the output's units) where that norm is zero to
// within the output's own rounding, `noise` = 16 u ||J|| ||x|| (the error model's error of an exactly zero
// output: at the rest angle a candidate's force is a few u ||J|| ||x||, not 0, and relative to it the difference
// schemes' absolute error would be 10^5 and more, a check without teeth).
double normalizer(double output_norm, double noise, double fallback) {
  return output_norm > noise ? output_norm : fallback;
}

// Discrepancy and estimate relative to `scale` (0 when the difference is; infinite when the scale is not
// positive: nothing silent).
double relative(double difference, double scale) {
  if (difference == 0) return 0;
  return scale > 0 && std::isfinite(scale) ? difference / scale : infinity;
}

struct Checker {
  const ConsistencyPlan& plan;
  const std::vector<EnergyOutputs>& outputs;
  const ConsistencyOptions& options;
  double u, floor;

  // Whether probe p has every output the options say is given, finite.
  bool usable(std::size_t p) const {
    const EnergyOutputs& o = outputs[p];
    if (!o.ok) return false;
    if (options.energy_given && !std::isfinite(o.energy)) return false;
    if (options.grad_given)
      for (double g : o.grad)
        if (!std::isfinite(g)) return false;
    if (options.hess_given)
      for (double h : o.hess)
        if (!std::isfinite(h)) return false;
    return true;
  }

  ConsistencyCheck finish(ConsistencyCheck c) const {
    c.threshold = std::max(8 * c.estimate, floor);  // the contract's: 8 times the estimate, at least the floor
    c.pass = c.discrepancy <= c.threshold;          // false for NaN and infinity
    return c;
  }
  ConsistencyCheck not_evaluated(std::string check, const std::string& id, const std::string& probe) const {
    ConsistencyCheck c;
    c.check = std::move(check);
    c.case_id = id;
    c.discrepancy = infinity;  // fails: a check not evaluated is not passed
    c.threshold = floor;
    c.pass = false;
    c.detail = "not evaluated: the candidate's outputs at " + probe + " are not ok";
    return c;
  }
};

// Richardson-extrapolated central differences of one output (n values per probe) in each of the 12
// coordinates: columns R(h)[j] and R(2h)[j], n values each, column-major.
struct Differences {
  bool ok = false;
  std::string missing;        // the first probe not usable
  std::vector<double> at_h;   // R(h): 12 columns of n
  std::vector<double> at_2h;  // R(2h)
  double largest_output = 0;  // max over the probes of the output's norm (the rounding term's |E|)
};

template <class Value>
Differences differences(const Checker& k, std::size_t case_index, std::size_t n, Value value) {
  Differences d;
  const std::size_t first = k.plan.first[case_index];
  for (int j = 0; j < 12; ++j)
    for (int level = 0; level < levels; ++level)
      for (bool plus : {true, false}) {
        const std::size_t p = difference_probe(first, j, level, plus);
        if (!k.usable(p)) {
          d.missing = probe_name(k.plan, case_index, p);
          return d;
        }
      }
  d.at_h.assign(12 * n, 0);
  d.at_2h.assign(12 * n, 0);
  std::vector<double> D(levels * n);
  for (int j = 0; j < 12; ++j) {
    for (int level = 0; level < levels; ++level) {
      const std::size_t plus = difference_probe(first, j, level, true),
                        minus = difference_probe(first, j, level, false);
      const double width = k.plan.actual_step[plus] - k.plan.actual_step[minus];  // a + b (minus stores -b)
      const double* fp = value(k.outputs[plus]);
      const double* fm = value(k.outputs[minus]);
      d.largest_output = std::max({d.largest_output, norm(fp, n), norm(fm, n)});
      for (std::size_t i = 0; i < n; ++i) D[level * n + i] = (fp[i] - fm[i]) / width;
    }
    for (std::size_t i = 0; i < n; ++i) {
      d.at_h[j * n + i] = (4 * D[i] - D[n + i]) / 3;
      d.at_2h[j * n + i] = (4 * D[n + i] - D[2 * n + i]) / 3;
    }
  }
  d.ok = true;
  return d;
}

}  // namespace

int step_exponent(Dtype dtype) { return dtype == Dtype::float32 ? float32_step_exponent : float64_step_exponent; }

// The contract's floor, the same relative 2^-20 / 2^-8 as the tier `approximate`'s bound (grading.hpp): below
// it a formula is right and only its accuracy is in question, which the oracle grades, not these checks.
double consistency_floor(Dtype dtype) { return dtype == Dtype::float32 ? 0x1p-8 : 0x1p-20; }

const std::vector<RigidMotion>& rigid_motions() {
  // The general rotation: the unit quaternion (1, 2, 3, 4) / sqrt(30), entries n / 30 rounded to double.
  static const std::vector<RigidMotion> motions{
      {"translation", {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0.75, -1.25, 2.5}},
      {"quarter turn about x", {1, 0, 0, 0, 0, -1, 0, 1, 0}, {0, 0, 0}},
      {"quarter turn about y", {0, 0, 1, 0, 1, 0, -1, 0, 0}, {0, 0, 0}},
      {"quarter turn about z", {0, -1, 0, 1, 0, 0, 0, 0, 1}, {0, 0, 0}},
      {"general rotation",
       {-20.0 / 30, 4.0 / 30, 22.0 / 30, 20.0 / 30, -10.0 / 30, 20.0 / 30, 10.0 / 30, 28.0 / 30, 4.0 / 30},
       {0, 0, 0}},
  };
  return motions;
}

std::vector<double> apply(const RigidMotion& m, std::span<const double> x, bool translate) {
  if (x.size() % 3 != 0) throw std::invalid_argument("apply: the coordinates are not a multiple of 3");
  std::vector<double> y(x.size());
  for (std::size_t v = 0; v < x.size() / 3; ++v)
    for (int r = 0; r < 3; ++r) {
      const double* q = &m.rotation[3 * r];
      // Quarter turns: two of the three products are exact zeros, the third +-x exactly, so the sum is exact.
      y[3 * v + r] = q[0] * x[3 * v] + q[1] * x[3 * v + 1] + q[2] * x[3 * v + 2] + (translate ? m.translation[r] : 0);
    }
  return y;
}

NetLoad net_load(std::span<const double> x, std::span<const double> g) {
  if (x.size() != g.size() || x.size() % 3 != 0)
    throw std::invalid_argument("net_load: x and g must hold the same number 3n of values");
  const std::size_t n = x.size() / 3;
  double centroid[3] = {0, 0, 0}, force[3] = {0, 0, 0}, torque[3] = {0, 0, 0};
  for (std::size_t v = 0; v < n; ++v)
    for (int c = 0; c < 3; ++c) centroid[c] += x[3 * v + c];
  for (double& c : centroid) c /= static_cast<double>(n == 0 ? 1 : n);
  for (std::size_t v = 0; v < n; ++v) {
    const double r[3] = {x[3 * v] - centroid[0], x[3 * v + 1] - centroid[1], x[3 * v + 2] - centroid[2]};
    const double* f = &g[3 * v];
    for (int c = 0; c < 3; ++c) force[c] += f[c];
    torque[0] += r[1] * f[2] - r[2] * f[1];
    torque[1] += r[2] * f[0] - r[0] * f[2];
    torque[2] += r[0] * f[1] - r[1] * f[0];
  }
  return {norm(force, 3), norm(torque, 3)};
}

ConsistencyPlan consistency_plan(const std::vector<EnergyCase>& base, Dtype dtype) {
  ConsistencyPlan plan;
  plan.base = base;
  plan.dtype = dtype;
  const std::size_t probes = base.size() * probes_per_case;
  plan.x.reserve(probes);
  plan.rest.reserve(probes);
  plan.actual_step.reserve(probes);
  for (const EnergyCase& c : base) {
    double largest = 0;
    for (int i = 0; i < 12; ++i) {
      if (!std::isfinite(c.x[i]) || !std::isfinite(c.rest[i]))
        throw std::invalid_argument("consistency_plan: a coordinate of " + c.id + " is not finite");
      largest = std::max(largest, std::fabs(c.x[i]));
    }
    const double L = longest_edge(c.x);
    if (!(L > 0)) throw std::invalid_argument("consistency_plan: the hinge " + c.id + " has no extent");
    const double unit = std::ldexp(1.0, std::ilogb(L));  // 2^floor(log2 L): scaling by it is exact
    double h = std::ldexp(unit, step_exponent(dtype));
    // The grid: multiples of the dtype's spacing one binade above every probe's magnitude (|x_i| + 4h), so
    // that the base point and every x +- 2^k h are exact in the dtype; h is at least that spacing.
    double grid = ulp_of(dtype, 2 * (largest + 4 * h));
    while (h < grid) {  // only far from the origin (|x| > 2^(p - 12) L): then the steps grow to the grid
      h = grid;
      grid = ulp_of(dtype, 2 * (largest + 4 * h));
    }
    std::array<double, 12> x0{}, r0{};
    for (int i = 0; i < 12; ++i) x0[i] = std::nearbyint(c.x[i] / grid) * grid;  // exact: scaled by a power of two
    if (c.rest == c.x) {
      r0 = x0;  // at rest stays at rest
    } else {
      for (int i = 0; i < 12; ++i) r0[i] = round_to(dtype, c.rest[i]);
    }
    plan.first.push_back(plan.x.size());
    plan.length.push_back(L);
    plan.step.push_back(h);
    plan.x.push_back(x0);
    plan.rest.push_back(r0);
    plan.actual_step.push_back(0);
    for (int j = 0; j < 12; ++j)
      for (int level = 0; level < levels; ++level)
        for (double sign : {1.0, -1.0}) {
          const double s = sign * std::ldexp(h, level);
          std::array<double, 12> xp = x0;
          xp[j] = round_to(dtype, x0[j] + s);
          const double actual = xp[j] - x0[j];  // exact: two nearby numbers of the dtype, subtracted in double
          if (actual != s) throw std::logic_error("consistency_plan: a difference probe is not exact");
          plan.x.push_back(xp);
          plan.rest.push_back(r0);
          plan.actual_step.push_back(actual);
        }
    std::array<double, 3> t{};
    for (const RigidMotion& m : rigid_motions()) {
      RigidMotion scaled = m;
      for (int r = 0; r < 3; ++r) scaled.translation[r] = m.translation[r] * unit;
      if (m.name == "translation") t = scaled.translation;
      const std::vector<double> y = conformance::apply(scaled, x0);
      std::array<double, 12> xm{};
      for (int i = 0; i < 12; ++i) xm[i] = round_to(dtype, y[i]);  // the translation and general rotation round
      plan.x.push_back(xm);
      plan.rest.push_back(r0);  // R stays
      plan.actual_step.push_back(0);
    }
    plan.translation.push_back(t);
  }
  return plan;
}

std::vector<ConsistencyCheck> consistency_checks(const ConsistencyPlan& plan, const std::vector<EnergyOutputs>& outputs,
                                                 const std::vector<double>& c, const ConsistencyOptions& options) {
  if (outputs.size() != plan.x.size())
    throw std::invalid_argument("consistency_checks: one output per probe of the plan is needed");
  if (c.size() != plan.base.size()) throw std::invalid_argument("consistency_checks: one c per base case is needed");
  if (options.dtype != plan.dtype)
    throw std::invalid_argument("consistency_checks: the options' dtype is not the plan's (its probes and its u)");
  const Checker k{plan, outputs, options, unit_roundoff(options.dtype), consistency_floor(options.dtype)};
  const auto& motions = rigid_motions();
  std::vector<ConsistencyCheck> checks;
  for (std::size_t i = 0; i < plan.base.size(); ++i) {
    const std::string& id = plan.base[i].id;
    const std::size_t first = plan.first[i];
    const double L = plan.length[i], h = plan.step[i];
    const std::array<double, 12>& x0 = plan.x[first];
    const double x_norm = norm(x0);
    const double c_energy = c[i], c_grad = c[i] / L, c_hess = c[i] / (L * L);  // where an output's norm is zero
    const bool base_ok = k.usable(first);
    const EnergyOutputs& o = outputs[first];
    const double g_norm = norm(o.grad), H_norm = norm(o.hess);
    const std::string base_name = "the base point";

    // The candidate's own derivatives, measured: its energy's gradient and its gradient's Jacobian.
    Differences dE, dG;
    if (options.energy_given) dE = differences(k, i, 1, [](const EnergyOutputs& e) { return &e.energy; });
    if (options.grad_given) dG = differences(k, i, 12, [](const EnergyOutputs& e) { return e.grad.data(); });
    const double gradE_norm = dE.ok ? norm(dE.at_h.data(), 12) : 0;
    const double jacobian_norm = dG.ok ? norm(dG.at_h.data(), 144) : 0;
    // ... and its Hessian's derivatives T, central differences at step h (the Hessian's conditioning).
    std::string third_missing = base_ok ? "" : base_name;
    double third = 0;
    if (options.hess_given) {
      for (int j = 0; j < 12 && third_missing.empty(); ++j) {
        const std::size_t plus = difference_probe(first, j, 0, true), minus = difference_probe(first, j, 0, false);
        if (!k.usable(plus) || !k.usable(minus)) {
          third_missing = probe_name(plan, i, k.usable(plus) ? minus : plus);
          break;
        }
        const double width = plan.actual_step[plus] - plan.actual_step[minus];
        for (int e = 0; e < 144; ++e) {
          const double t = (outputs[plus].hess[e] - outputs[minus].hess[e]) / width;
          third += t * t;
        }
      }
      third = std::sqrt(third);
    }
    // The energy's own rounding: a relative change 16 u of the coordinates moves it by up to
    // ||grad E|| (16 u ||x||) + ||H|| (16 u ||x||)^2 / 2 (the second term where grad E vanishes: at rest).
    const double moved = 16 * k.u * x_norm;
    const double E_noise = gradE_norm * moved + H_norm * moved * moved / 2;
    const double E_scale = normalizer(std::fabs(o.energy), E_noise, c_energy);
    const double g_scale = normalizer(g_norm, 16 * k.u * jacobian_norm * x_norm, c_grad);
    const double H_scale = normalizer(H_norm, third_missing.empty() ? 16 * k.u * third * x_norm : 0, c_hess);

    // The gradient against Richardson differences of the energy. Estimate: |R(h) - R(2h)| (15 times R(h)'s
    // truncation error) plus rounding: R(h) = (4 D(h) - D(2h)) / 3 carries (4 + 1/2) / 3 = 1.5 times the
    // energy's error over h per coordinate, sqrt(12) normwise, the energy's error u (|E| + ||grad E|| ||x||).
    if (options.energy_given && options.grad_given) {
      const std::string name = "gradient against differences of the energy";
      if (!base_ok) {
        checks.push_back(k.not_evaluated(name, id, base_name));
      } else if (!dE.ok) {
        checks.push_back(k.not_evaluated(name, id, dE.missing));
      } else {
        double diff = 0, trunc = 0, worst = -1;
        int worst_j = 0;
        for (int j = 0; j < 12; ++j) {
          const double e = o.grad[j] - dE.at_h[j];
          diff += e * e;
          trunc += (dE.at_h[j] - dE.at_2h[j]) * (dE.at_h[j] - dE.at_2h[j]);
          if (std::fabs(e) > worst) worst = std::fabs(e), worst_j = j;
        }
        const double rounding = 1.5 * std::sqrt(12.0) * k.u * (dE.largest_output + gradE_norm * x_norm) / h;
        ConsistencyCheck r;
        r.check = name;
        r.case_id = id;
        r.discrepancy = relative(std::sqrt(diff), g_scale);
        r.estimate = relative(std::sqrt(trunc) + rounding, g_scale);
        r.detail = "worst coordinate " + coordinate_name(worst_j) + ": gradient " + number(o.grad[worst_j]) +
                   ", differences " + number(dE.at_h[worst_j]) + "; h = " + number(h);
        checks.push_back(k.finish(r));
      }
    }

    // The exact Hessian against Richardson differences of the gradient: column j of H against R(h) of the
    // gradient in coordinate j; the same estimate, 144 entries (normwise factor 12), the gradient's error
    // u (||g|| + ||J_g|| ||x||).
    if (options.grad_given && options.hess_given && options.hessian_exact) {
      const std::string name = "Hessian against differences of the gradient";
      if (!base_ok) {
        checks.push_back(k.not_evaluated(name, id, base_name));
      } else if (!dG.ok) {
        checks.push_back(k.not_evaluated(name, id, dG.missing));
      } else {
        double diff = 0, trunc = 0, worst = -1;
        int worst_row = 0, worst_col = 0;
        for (int col = 0; col < 12; ++col)
          for (int row = 0; row < 12; ++row) {
            if (options.diagonal_blocks && row / 3 != col / 3) continue;  // blocks="diagonal": the rest not given
            const double d = dG.at_h[12 * col + row];
            const double e = o.hess[12 * row + col] - d;
            diff += e * e;
            trunc += (d - dG.at_2h[12 * col + row]) * (d - dG.at_2h[12 * col + row]);
            if (std::fabs(e) > worst) worst = std::fabs(e), worst_row = row, worst_col = col;
          }
        const double rounding = 1.5 * 12 * k.u * (dG.largest_output + jacobian_norm * x_norm) / h;
        ConsistencyCheck r;
        r.check = name;
        r.case_id = id;
        r.discrepancy = relative(std::sqrt(diff), H_scale);
        r.estimate = relative(std::sqrt(trunc) + rounding, H_scale);
        r.detail = "worst entry (" + coordinate_name(worst_row) + ", " + coordinate_name(worst_col) + "): Hessian " +
                   number(o.hess[12 * worst_row + worst_col]) + ", differences " +
                   number(dG.at_h[12 * worst_col + worst_row]) + "; h = " + number(h);
        checks.push_back(k.finish(r));
      }
    }

    // The Hessian's symmetry, ||H - H^T||_F relative to ||H||_F. Estimate 16 (1 + kappa_H) u, kappa_H =
    // ||T|| ||x|| / ||H||, T the central differences (step h) of the candidate's own Hessian: H_ij and H_ji are
    // two computations of one number, each within the error model.
    if (options.hess_given) {
      const std::string name = "Hessian symmetry";
      if (!third_missing.empty()) {
        checks.push_back(k.not_evaluated(name, id, third_missing));
      } else {
        double asym = 0, worst = -1;
        int worst_row = 0, worst_col = 0;
        for (int row = 0; row < 12; ++row)
          for (int col = 0; col < 12; ++col) {
            const double e = o.hess[12 * row + col] - o.hess[12 * col + row];
            asym += e * e;
            if (std::fabs(e) > worst) worst = std::fabs(e), worst_row = row, worst_col = col;
          }
        ConsistencyCheck r;
        r.check = name;
        r.case_id = id;
        r.discrepancy = relative(std::sqrt(asym), H_scale);
        r.estimate = relative(16 * k.u * (H_norm + third * x_norm), H_scale);
        r.detail = "worst pair (" + coordinate_name(worst_row) + ", " + coordinate_name(worst_col) +
                   "): " + number(o.hess[12 * worst_row + worst_col]) + " and " +
                   number(o.hess[12 * worst_col + worst_row]);
        checks.push_back(k.finish(r));
      }
    }

    // Rigid motions of X (R stays). The quarter turns are exact; the translation rounds each coordinate of
    // the moved X (relative u |x_i|) and the general rotation's entries are rounded (Q orthogonal to a few
    // u): both are perturbations of the coordinates of relative size u, which the estimate 16 (1 + kappa) u
    // covers with kappa taken over the larger of ||X|| and ||QX + t||. For the energy kappa_E =
    // ||grad E|| ||x|| / |E|, for the gradient kappa_g = ||J_g|| ||x|| / ||g|| (the measured derivatives).
    for (std::size_t m = 0; m < motions.size(); ++m) {
      if (!options.energy_given) break;
      const std::string name = "energy under rigid motion (" + motions[m].name + ")";
      const std::size_t p = motion_probe(first, m);
      if (!base_ok) {
        checks.push_back(k.not_evaluated(name, id, base_name));
      } else if (!k.usable(p)) {
        checks.push_back(k.not_evaluated(name, id, motions[m].name));
      } else if (!dE.ok) {
        checks.push_back(k.not_evaluated(name, id, dE.missing));
      } else {
        const double size = std::max(x_norm, norm(plan.x[p])), shift = 16 * k.u * size;
        ConsistencyCheck r;
        r.check = name;
        r.case_id = id;
        r.discrepancy = relative(std::fabs(outputs[p].energy - o.energy), E_scale);
        r.estimate =
            relative(16 * k.u * std::fabs(o.energy) + gradE_norm * shift + H_norm * shift * shift / 2, E_scale);
        r.detail = "energy " + number(o.energy) + ", moved " + number(outputs[p].energy);
        checks.push_back(k.finish(r));
      }
    }
    for (std::size_t m = 0; m < motions.size(); ++m) {
      if (!options.grad_given) break;
      const std::string name = "gradient turned with the motion (" + motions[m].name + ")";
      const std::size_t p = motion_probe(first, m);
      if (!base_ok) {
        checks.push_back(k.not_evaluated(name, id, base_name));
      } else if (!k.usable(p)) {
        checks.push_back(k.not_evaluated(name, id, motions[m].name));
      } else if (!dG.ok) {
        checks.push_back(k.not_evaluated(name, id, dG.missing));
      } else {
        const std::vector<double> turned = conformance::apply(motions[m], o.grad, false);
        double diff = 0;
        for (int j = 0; j < 12; ++j) diff += (outputs[p].grad[j] - turned[j]) * (outputs[p].grad[j] - turned[j]);
        const double size = std::max(x_norm, norm(plan.x[p]));
        ConsistencyCheck r;
        r.check = name;
        r.case_id = id;
        r.discrepancy = relative(std::sqrt(diff), g_scale);
        r.estimate = relative(16 * k.u * (g_norm + jacobian_norm * size), g_scale);
        r.detail = "||g(QX + t) - Q g(X)|| = " + number(std::sqrt(diff)) + ", ||g|| = " + number(g_norm);
        checks.push_back(k.finish(r));
      }
    }

    // Zero net force and torque: the exact gradient of a rigid-invariant energy has both zero. The candidate's
    // gradient errors (16 (1 + kappa_g) u ||g||) add up to at most twice that in the force over four vertices,
    // and in the torque, measured relative to L ||g|| (|x_v - centroid| <= L), likewise; the estimate's 16 covers
    // the sums' own rounding.
    if (options.grad_given) {
      const NetLoad load = base_ok ? net_load(x0, o.grad) : NetLoad{};
      for (const char* name : {"net force", "net torque"}) {
        if (!base_ok) {
          checks.push_back(k.not_evaluated(name, id, base_name));
        } else if (!dG.ok) {
          checks.push_back(k.not_evaluated(name, id, dG.missing));
        } else {
          const bool force = std::string(name) == "net force";
          const double scale = force ? 1 : L;
          ConsistencyCheck r;
          r.check = name;
          r.case_id = id;
          r.discrepancy = relative(force ? load.force : load.torque, scale * g_scale);
          r.estimate = relative(16 * k.u * (g_norm + jacobian_norm * x_norm) * scale, scale * g_scale);
          r.detail = force ? "||sum_v g_v|| = " + number(load.force)
                           : "||sum_v (x_v - centroid) x g_v|| = " + number(load.torque);
          r.detail += ", ||g|| = " + number(g_norm);
          checks.push_back(k.finish(r));
        }
      }
    }
  }
  return checks;
}

}  // namespace hinge::conformance
