// Running a scene (hinge/sim/simulation.hpp).
#include "hinge/sim/simulation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "hinge/core/errors.hpp"
#include "hinge/core/results.hpp"
#include "hinge/sim/effect.hpp"
#include "hinge/sim/linear_solver.hpp"
#include "hinge/sim/system.hpp"

namespace hinge::sim {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Failure {
  std::string reason;
};

class Run {
 public:
  Run(const Scene& scene, const RunOptions& options)
      : scene_(scene), options_(options), topology_(build_topology(scene.mesh)), sparsity_(topology_) {
    const std::size_t n = scene.mesh.vertices.size();
    context_.scene = &scene, context_.topology = &topology_, context_.sparsity = &sparsity_;
    context_.threads = options.threads;
    context_.dt = scene.solve.mode == Mode::dynamic ? scene.solve.dt : 0;
    context_.mass = lumped_mass(scene);
    for (const auto& f : scene.rest.faces)
      for (int i = 0; i < 3; ++i) {
        const auto& a = scene.rest.vertices[static_cast<std::size_t>(f[i])];
        const auto& b = scene.rest.vertices[static_cast<std::size_t>(f[(i + 1) % 3])];
        longest_edge_ = std::max(longest_edge_, std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]));
      }
    for (std::size_t v = 0; v < n; ++v)
      if (!(context_.mass[static_cast<Eigen::Index>(3 * v)] > 0))
        throw InputError(scene.file + ": mesh: vertex " + std::to_string(v) +
                         " belongs to no face of non-zero area (no mass)");
    effects_ = make_effects(context_);
    times_.assign(effects_.size(), 0.0);
    for (const auto& e : effects_) summary_.effects.emplace_back(e->name());
    if (scene.pins) pinned_ = scene.pins->vertices;
    reduction_ = std::make_unique<Reduction>(sparsity_, pinned_);
    solver_ = make_sparse_solver(scene.solve.linear_solver);
    solver_->analyze(reduction_->matrix());
    x_.resize(static_cast<Eigen::Index>(3 * n));
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t c = 0; c < 3; ++c) x_[static_cast<Eigen::Index>(3 * v + c)] = scene.mesh.vertices[v][c];
    v_ = Eigen::VectorXd::Zero(x_.size());
    for (std::size_t v = 0; v < n; ++v)
      if (reduction_->is_free(static_cast<Eigen::Index>(3 * v)))
        for (std::size_t c = 0; c < 3; ++c) v_[static_cast<Eigen::Index>(3 * v + c)] = scene.velocity[c];
    for (const auto& e : effects_) e->check_initial(x_);
    last_good_ = x_;
    summary_.scene = scene.name;
    summary_.vertices = n;
  }

  Summary run(Mesh& final_state, Clock::time_point start) {
    try {
      if (scene_.solve.mode == Mode::static_equilibrium) {
        newton(nullptr);
      } else {
        frame(0);
        for (int s = 1; s <= scene_.solve.steps; ++s) {
          step();
          summary_.steps = s;
          if (s % scene_.output_every == 0) frame(s / scene_.output_every);
          if (options_.on_progress) options_.on_progress(s, scene_.solve.steps);
        }
      }
    } catch (const Failure& f) {
      fail(f.reason);
    } catch (const std::exception& e) {  // an effect that cannot go on (a degenerate hinge, ...)
      fail(e.what());
    }
    final_state = state_mesh();
    for (std::size_t i = 0; i < effects_.size(); ++i)
      if (effects_[i]->has_energy()) {
        const auto t = Clock::now();
        double e = std::numeric_limits<double>::quiet_NaN();
        try {
          e = effects_[i]->energy(x_);
        } catch (const std::exception&) {
        }
        times_[i] += seconds_since(t);
        summary_.energy.emplace_back(effects_[i]->name(), e);
      }
    summary_.time_total = seconds_since(start) - output_time_;
    summary_.time_linear_solve = linear_time_;
    for (std::size_t i = 0; i < effects_.size(); ++i) {
      summary_.time_effects.emplace_back(effects_[i]->name(), times_[i]);
      if (effects_[i]->name() == "bending" && summary_.time_total > 0)
        summary_.bending_share = times_[i] / summary_.time_total;
    }
    return summary_;
  }

 private:
  // The run stops: the state goes back to the last accepted one (the start of the failed step).
  void fail(const std::string& reason) {
    summary_.ok = false;
    summary_.reason = reason;
    x_ = last_good_;
  }

  Mesh state_mesh() const {
    Mesh m = scene_.mesh;
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
      for (std::size_t c = 0; c < 3; ++c) m.vertices[v][c] = x_[static_cast<Eigen::Index>(3 * v + c)];
    return m;
  }

  void frame(int index) {
    if (!options_.on_frame) return;
    if (!x_.allFinite()) throw Failure{"a non-finite coordinate"};
    const auto t = Clock::now();
    options_.on_frame(index, state_mesh());
    output_time_ += seconds_since(t);
  }

  // One backward Euler step.
  void step() {
    for (std::size_t i = 0; i < effects_.size(); ++i) {
      const auto t = Clock::now();
      effects_[i]->begin_step(x_, v_);
      times_[i] += seconds_since(t);
    }
    const Eigen::VectorXd start = x_;
    last_good_ = x_;
    Inertia inertia{start + scene_.solve.dt * v_, context_.mass / (scene_.solve.dt * scene_.solve.dt)};
    // The initial guess: towards x_hat as far as the effects admit (the sphere); pinned coordinates stay.
    Eigen::VectorXd dx = inertia.target - start;
    for (Eigen::Index d = 0; d < x_.size(); ++d)
      if (!reduction_->is_free(d)) dx[d] = 0;
    double alpha = 1;
    for (const auto& e : effects_) alpha = std::min(alpha, e->max_step(start, dx));
    x_ = start + alpha * dx;
    if (std::isinf(energy_at(x_, &inertia))) x_ = start;  // x_hat folds a hinge flat (tan): start from x_n
    newton(&inertia);
    v_ = (x_ - start) / scene_.solve.dt;
  }

  struct Inertia {
    Eigen::VectorXd target;  // x_hat
    Eigen::VectorXd weight;  // M / dt^2
  };

  // The potential Newton minimizes at x: the effects' parts and, for a time step, the inertial part.
  Evaluation& evaluate(const Eigen::VectorXd& x, unsigned request, const Inertia* inertia) {
    ev_.request = request;
    ev_.energy = 0;
    if (request & 2u) ev_.gradient.setZero(x.size());
    if (request & 4u) ev_.hessian.assign(static_cast<std::size_t>(sparsity_.nonzeros()), 0.0);
    for (std::size_t i = 0; i < effects_.size(); ++i) {
      const auto t = Clock::now();
      effects_[i]->add(x, ev_);
      times_[i] += seconds_since(t);
    }
    if (inertia) {
      const Eigen::VectorXd d = x - inertia->target;
      if (request & 1u) ev_.energy += 0.5 * d.dot(inertia->weight.cwiseProduct(d));
      if (request & 2u) ev_.gradient += inertia->weight.cwiseProduct(d);
      if (request & 4u)
        for (Eigen::Index k = 0; k < x.size(); ++k)
          ev_.hessian[static_cast<std::size_t>(sparsity_.slot(k, k))] += inertia->weight[k];
    }
    return ev_;
  }

  double energy_at(const Eigen::VectorXd& x, const Inertia* inertia) {
    try {
      const double e = evaluate(x, want_energy, inertia).energy;
      return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
    } catch (const DomainError&) {  // tan at theta = pi, a vertex on the sphere
      return std::numeric_limits<double>::infinity();
    } catch (const InputError&) {  // a triangle of zero area
      return std::numeric_limits<double>::infinity();
    }
  }

  double largest_displacement(const Eigen::VectorXd& dx) const {
    double m = 0;
    for (Eigen::Index v = 0; v < dx.size() / 3; ++v) m = std::max(m, dx.segment<3>(3 * v).norm());
    return m;
  }

  // Newton with line search from x_; throws Failure.
  void newton(const Inertia* inertia) {
    const double tolerance = scene_.solve.newton_tolerance * longest_edge_;
    Eigen::VectorXd b, d, dx, trial;
    for (int iteration = 1; iteration <= scene_.solve.max_newton; ++iteration) {
      ++summary_.newton_iterations;
      Evaluation* evaluated = nullptr;
      try {
        evaluated = &evaluate(x_, want_all, inertia);
      } catch (const std::exception& e) {  // not expected: every accepted state had a finite potential
        throw Failure{std::string("the potential cannot be evaluated at the current state: ") + e.what()};
      }
      Evaluation& ev = *evaluated;
      if (!std::isfinite(ev.energy) || !ev.gradient.allFinite())
        throw Failure{"the potential or its gradient is not finite at the current state"};
      const double energy = ev.energy;
      const Eigen::VectorXd gradient = ev.gradient;
      const auto t = Clock::now();
      reduction_->reduce_matrix(ev.hessian);
      reduction_->reduce_vector(gradient, b);
      b = -b;
      solve_descent(b, d);
      reduction_->expand_vector(d, dx);
      linear_time_ += seconds_since(t);
      if (options_.on_progress && !inertia) options_.on_progress(iteration, scene_.solve.max_newton);
      double alpha = 1;
      for (const auto& e : effects_) alpha = std::min(alpha, e->max_step(x_, dx));
      const double full = largest_displacement(dx);
      if (full < tolerance) {  // converged: take the (tiny) step without a line search
        x_ += alpha * dx;
        return;
      }
      const double slope = gradient.dot(dx);              // < 0: a descent direction
      const double allowance = 1e-13 * std::abs(energy);  // rounding of the energy's evaluation
      bool accepted = false;
      for (int halvings = 0; halvings < 60; ++halvings, alpha /= 2) {
        trial = x_ + alpha * dx;
        if (energy_at(trial, inertia) <= energy + 1e-4 * alpha * slope + allowance) {
          accepted = true;
          break;
        }
      }
      if (!accepted)
        throw Failure{"the line search found no decrease of the potential (Newton iteration " +
                      std::to_string(iteration) + ")"};
      x_ = trial;
      if (!x_.allFinite()) throw Failure{"a non-finite coordinate"};
    }
    throw Failure{
        "Newton did not converge in " + std::to_string(scene_.solve.max_newton) + " iterations" +
        (scene_.solve.mode == Mode::dynamic ? " at step " + std::to_string(summary_.steps + 1) : std::string())};
  }

  // Solves H d = b (b = -gradient) for a descent direction: if the factorization fails or d is not a
  // descent direction (the exact treatment's indefinite Hessian), H + tau I with tau growing tenfold from
  // 1e-8 times the largest diagonal entry; the next iteration starts from a quarter of the shift that
  // worked (docs/simulator.md).
  void solve_descent(const Eigen::VectorXd& b, Eigen::VectorXd& d) {
    auto& A = reduction_->matrix();
    if (b.size() == 0 || b.isZero(0.0)) {  // nothing free, or no force: the step is zero
      d.setZero(b.size());
      return;
    }
    Eigen::VectorXd diagonal = A.diagonal();
    const double scale = diagonal.cwiseAbs().maxCoeff();
    if (!(scale > 0))
      throw Failure{"the Hessian of the free coordinates is zero on its diagonal (an unconstrained scene?)"};
    double tau = last_shift_ / 4;  // the last iteration's shift, lowered: one factorization, usually
    if (tau < 1e-8 * scale) tau = 0;
    for (int attempt = 0; attempt < 40; ++attempt) {
      if (tau > 0)
        for (Eigen::Index k = 0; k < A.rows(); ++k) A.coeffRef(k, k) = diagonal[k] + tau;
      if (solver_->factorize(A)) {
        d = solver_->solve(b);
        if (d.allFinite() && b.dot(d) > 0) {
          last_shift_ = tau;
          return;
        }
      }
      tau = tau == 0 ? 1e-8 * scale : tau * 10;
    }
    throw Failure{"no descent direction: the shifted Hessian could not be factored"};
  }

  const Scene& scene_;
  RunOptions options_;
  Topology topology_;
  Sparsity sparsity_;
  Context context_;
  std::vector<std::unique_ptr<Effect>> effects_;
  std::vector<double> times_;
  std::vector<Index> pinned_;
  std::unique_ptr<Reduction> reduction_;
  std::unique_ptr<SparseSolver> solver_;
  Eigen::VectorXd x_, v_, last_good_;
  Evaluation ev_;
  Summary summary_;
  double last_shift_ = 0, longest_edge_ = 0, output_time_ = 0, linear_time_ = 0;
};

}  // namespace

Eigen::VectorXd lumped_mass(const Scene& scene) {
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(3 * scene.rest.vertices.size()));
  for (const auto& f : scene.rest.faces) {
    auto X = [&](int i) { return Eigen::Vector3d(scene.rest.vertices[static_cast<std::size_t>(f[i])].data()); };
    const double area = (X(1) - X(0)).cross(X(2) - X(0)).norm() / 2;
    for (int i = 0; i < 3; ++i)
      mass.segment<3>(3 * f[i]).array() += scene.material.density * scene.material.thickness * area / 3;
  }
  return mass;
}

Summary simulate(const Scene& scene, const RunOptions& options, Mesh& final_state) {
  const auto start = Clock::now();  // the setup (topology, structure, the effects' rest state) counts
  Run run(scene, options);
  return run.run(final_state, start);
}

}  // namespace hinge::sim
