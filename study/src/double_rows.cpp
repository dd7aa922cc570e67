// The rows in double alone: the faithful mode, the certified oracle, and implementations from outside
// (study_internal.hpp). Measured and timed as every row (rows.hpp, timing.hpp).
#include <algorithm>
#include <memory>

#include "hinge/fast/faithful.hpp"
#include "rows.hpp"
#include "study_internal.hpp"

namespace hinge::study::detail {
namespace {

const ScalarType& double_type() {
  static const ScalarType d = parse_scalar_type("double");
  return d;
}

Outputs<double> outputs(const oracle::CertifiedTheta& c) {
  Outputs<double> o;
  o.theta = c.theta;
  for (int k = 0; k < 12; ++k) o.grad[k] = c.grad[k];
  for (int r = 0; r < 12; ++r)
    for (int k = 0; k < 12; ++k) o.hess(r, k) = c.hess[12 * r + k];
  return o;
}

Clock::time_point after(Clock::time_point t, double seconds) {
  return t + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// A row in double named `method`, not measured yet.
Measured double_row(const std::string& method) {
  Measured m;
  m.row.method = method;
  m.row.scalar = double_type();
  return m;
}

}  // namespace

Measured measure_faithful(const Prepared& p, double budget, bool quick) {
  Measured m = double_row("faithful");
  Row& row = m.row;
  const auto start = Clock::now();
  measure_errors<double>(row, row.scalar, p, after(start, budget / 2), [&](std::size_t i) {
    const fast::HingeDerivatives<double> d = fast::faithful_hinge_derivatives(p.hinges[i].x);
    return Outputs<double>{d.theta, d.grad, d.hess};
  });
  m.timer = row_timer(
      row, p, budget / 2, quick, 3,
      [](int g, const std::array<double, 12>& x, Slots& out, std::size_t i) {
        const fast::HingeDerivatives<double> d = fast::faithful_hinge_derivatives(x, g == 2);
        out.theta[i] = d.theta;
        if (g >= 1) std::copy(d.grad.begin(), d.grad.end(), out.grad.begin() + static_cast<std::ptrdiff_t>(12 * i));
        if (g == 2)
          std::copy(d.hess.data(), d.hess.data() + 144, out.hess.begin() + static_cast<std::ptrdiff_t>(144 * i));
      },
      [] {});
  row.seconds = seconds_since(start);
  return m;
}

Measured measure_oracle(const Prepared& p, double budget, bool quick) {
  Measured m = double_row("oracle");
  Row& row = m.row;
  const auto start = Clock::now();
  std::map<std::string, std::pair<std::size_t, std::size_t>> escalated;  // per category: beyond the fast path, all
  measure_errors<double>(row, row.scalar, p, after(start, budget / 2), [&](std::size_t i) {
    const oracle::CertifiedTheta c = oracle::certified_theta_derivatives(p.hinges[i].x);  // the fast path on
    auto& [beyond, all] = escalated[p.hinges[i].category];
    ++all;
    if (c.path != oracle::Path::fast) ++beyond;
    return outputs(c);
  });
  for (const auto& [category, counts] : escalated)
    row.escalation[category] = static_cast<double>(counts.first) / static_cast<double>(counts.second);
  m.timer = row_timer(
      row, p, budget / 2, quick, 1,  // its one call gives all three groups
      [](int, const std::array<double, 12>& x, Slots& out, std::size_t i) {
        const oracle::CertifiedTheta c = oracle::certified_theta_derivatives(x);
        out.theta[i] = c.theta;
        std::copy(c.grad.begin(), c.grad.end(), out.grad.begin() + static_cast<std::ptrdiff_t>(12 * i));
        std::copy(c.hess.begin(), c.hess.end(), out.hess.begin() + static_cast<std::ptrdiff_t>(144 * i));
      },
      [] {});
  row.seconds = seconds_since(start);
  return m;
}

Measured measure_outside(const Outside& o, const Prepared& p, double budget, bool quick) {
  Measured m = double_row(o.label);
  Row& row = m.row;
  row.outside = true;
  const auto start = Clock::now();
  std::vector<std::array<double, 12>> xs;
  for (const std::size_t i : p.order) xs.push_back(p.hinges[i].x);
  const std::vector<io::EvalOutput> results = o.evaluate(xs);
  std::map<std::string, std::array<std::vector<double>, 3>> errors;
  for (std::size_t k = 0; k < p.order.size() && k < results.size(); ++k) {
    const std::size_t i = p.order[k];
    const io::EvalOutput& r = results[k];
    ++row.hinges;
    using Status = io::EvalOutput::Status;
    if (r.status == Status::error || r.status == Status::missing) {
      ++row.failed;
      if (row.error.empty() && (r.error.rfind("crashed", 0) == 0 || r.error.rfind("timed out", 0) == 0))
        row.error = r.error + " on hinge " + p.hinges[i].id;
      continue;
    }
    if (r.status == Status::nonfinite) {
      ++row.nonfinite;
      continue;
    }
    record_errors(row, p, i, RoundedTheta{r.theta, r.grad, r.hess}, errors[p.hinges[i].category]);
  }
  for (auto& [category, e] : errors) row.error_u[category] = statistics(e);
  row.seconds = seconds_since(start);

  // A round: one batch request (the candidate's pass and fast's, in its process); the three groups are one call.
  struct State {
    Rounds rounds;
    std::string error;
    double spent = 0, row_spent = 0;
    int count = 0;
  };
  auto state = std::make_shared<State>();
  const RoundPolicy policy = round_policy(quick);
  const auto hinges = std::make_shared<const std::vector<std::array<double, 12>>>(p.timing);
  RowTimer t;
  t.round = [state, hinges, time = o.time](int) {
    const auto round_start = Clock::now();
    const OutsideTiming r = time(*hinges, 1);
    state->spent += seconds_since(round_start);
    ++state->count;
    if (!r.error.empty()) state->error = r.error;
    for (const auto& [mine, fast] : r.rounds) {
      state->rounds.add(2, mine, fast);
      state->row_spent += 1e-9 * mine * static_cast<double>(hinges->size());
    }
  };
  t.done = [state, policy, budget] {
    return !state->error.empty() || (state->count >= policy.min_rounds && state->row_spent >= policy.min_seconds) ||
           (state->count >= 3 && state->spent >= budget);
  };
  t.finish = [state](Row& r) {
    if (!state->error.empty()) {
      r.error += (r.error.empty() ? "" : "; ") + std::string("timing: ") + state->error;
      return;
    }
    state->rounds.summarize(r, 1);
  };
  m.timer = t;
  return m;
}

}  // namespace hinge::study::detail
