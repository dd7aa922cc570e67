// Running a scene (hinge/sim/simulation.hpp).
#include "hinge/sim/simulation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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
      : scene_(scene), options_(options), topology_(build_topology(scene.mesh)),
        sparsity_(topology_, couplings(scene)) {
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
    summary_.solver.linear_solver = solver_->name();
    force_scale_ = force_scale(scene.solve.mode == Mode::dynamic);
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
    if (!per_step_.empty()) {
      std::vector<int> sorted = per_step_;
      std::sort(sorted.begin(), sorted.end());
      const std::size_t m = sorted.size();
      summary_.solver.newton_median = m % 2 ? sorted[m / 2] : 0.5 * (sorted[m / 2 - 1] + sorted[m / 2]);
      summary_.solver.newton_max = sorted.back();
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
    x_ = start + step_limit(start, dx) * dx;
    if (std::isinf(energy_at(x_, &inertia))) x_ = start;  // x_hat folds a hinge flat (tan): start from x_n
    newton(&inertia);
    v_ = (x_ - start) / scene_.solve.dt;
  }

  struct Inertia {
    Eigen::VectorXd target;  // x_hat
    Eigen::VectorXd weight;  // M / dt^2
  };

  // The potential Newton minimizes at x: the effects' parts and, for a time step, the inertial part.
  Evaluation& evaluate(const Eigen::VectorXd& x, unsigned request, const Inertia* inertia,
                       Treatment treatment = Treatment::scene) {
    ev_.request = request;
    ev_.treatment = treatment;
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

  // The largest fraction of the step dx from x that every effect admits (the sphere: 0.8 of the way to its
  // surface), in (0, 1].
  double step_limit(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const {
    double alpha = 1;
    for (const auto& e : effects_) alpha = std::min(alpha, e->max_step(x, dx));
    return alpha;
  }

  // The largest force residual on a free vertex: max_v |g_v| of the potential's gradient.
  double residual(const Eigen::VectorXd& gradient) const {
    double m = 0;
    for (Eigen::Index v = 0; v < gradient.size() / 3; ++v)
      if (reduction_->is_free(3 * v)) m = std::max(m, gradient.segment<3>(3 * v).norm());
    return m;
  }

  // The rungs of the fallback chain (summary.json's "rungs").
  enum class Rung { newton, projected, shifted, gradient };

  // Newton from x_, a trust region on its newton and projected rungs (docs/simulator.md, "Newton"); throws
  // Failure.
  void newton(const Inertia* inertia) {
    const double step_tolerance = scene_.solve.newton_tolerance * longest_edge_;
    const double force_tolerance = scene_.solve.residual_tolerance * force_scale_;
    const int step = inertia ? summary_.steps + 1 : 0;
    Eigen::VectorXd b, d, dx;
    bool last_step_small = false;  // the previous iteration's step would have let Newton stop
    int stalled = 0;               // iterations in a row whose tiny step left the residual where it was
    double last_residual = INFINITY;
    shift_ = 0;   // the shift is found afresh in every step
    radius_ = 0;  // and the trust region's radius
    int iterations = 0;

    for (int iteration = 1;; ++iteration) {
      Evaluation* evaluated = nullptr;
      try {
        evaluated = &evaluate(x_, want_all, inertia, Treatment::scene);
      } catch (const std::exception& e) {  // not expected: every accepted state had a finite potential
        throw Failure{std::string("the potential cannot be evaluated at the current state: ") + e.what()};
      }
      Evaluation& ev = *evaluated;
      if (!std::isfinite(ev.energy) || !ev.gradient.allFinite())
        throw Failure{"the potential or its gradient is not finite at the current state"};
      const double r = residual(ev.gradient);
      if (iteration > 1 && last_step_small && r <= force_tolerance) break;  // converged where the step led
      if (iteration > scene_.solve.max_newton)
        throw Failure{"Newton did not converge in " + std::to_string(scene_.solve.max_newton) + " iterations" +
                      (inertia ? " at step " + std::to_string(step) : std::string())};
      ++summary_.newton_iterations, ++iterations;
      const double energy = ev.energy;
      const Eigen::VectorXd gradient = ev.gradient;
      reduction_->reduce_vector(gradient, b);
      b = -b;
      dumping_ = wants_dump(step, iteration);  // keep the matrix factored for this iteration's dump
      const Rung rung = descent(ev, inertia, b, d);
      reduction_->expand_vector(d, dx);
      count(rung);
      if (dumping_) dump(step, iteration, inertia, gradient);
      if (options_.on_progress && !inertia) options_.on_progress(iteration, scene_.solve.max_newton);
      const bool newton_rung = rung == Rung::newton || rung == Rung::projected;
      const double full = largest_displacement(dx);
      last_step_small = !newton_rung || full <= step_tolerance;
      // A residual that no longer falls while Newton's steps are below newton_tolerance: the rounding floor of
      // the scene's forces (or a saddle Newton creeps towards); say so rather than iterate to max_newton.
      stalled =
          (newton_rung && full <= step_tolerance && r > force_tolerance && r >= 0.5 * last_residual) ? stalled + 1 : 0;
      last_residual = r;
      if (stalled >= 3) {
        char why[320];
        std::snprintf(why, sizeof why,
                      "the force residual stalls at %.3g F (residual_tolerance %.3g) while Newton's steps are %.3g L, "
                      "below newton_tolerance: the rounding floor of this scene's forces (raise "
                      "solve.residual_tolerance) or a saddle of the potential",
                      r / force_scale_, scene_.solve.residual_tolerance, full / longest_edge_);
        throw Failure{std::string(why) + (inertia ? " (step " + std::to_string(step) + ")" : std::string())};
      }
      IterationReport report{step, iteration, rung_name(rung), r / force_scale_, energy, full / longest_edge_};
      if (last_step_small && r <= force_tolerance) {  // converged: take the (tiny) step as it is
        report.alpha = step_limit(x_, dx);
        x_ += report.alpha * dx;
        if (options_.on_iteration) options_.on_iteration(report);
        break;
      }
      const Attempt where{inertia, step, iteration, energy};
      if (newton_rung) {
        last_step_small = trust_region(where, b, d, report) && last_step_small;
      } else {
        line_search(where, gradient, dx, report);
      }
      if (options_.on_iteration) options_.on_iteration(report);
      if (!x_.allFinite()) throw Failure{"a non-finite coordinate"};
    }
    per_step_.push_back(iterations);
  }

  // F of the contract's stop rule: max_v (m_v |g| + |f_load,v|), or where that is 0 max_v m_v L / dt^2 (a
  // time step) or Y h L (a static solve; k / L for a scene whose bending has k and no Young's modulus).
  double force_scale(bool dynamic) const {
    const Eigen::Index n = context_.mass.size() / 3;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    if (scene_.gravity)
      f = Eigen::Vector3d(scene_.gravity->g.data()).norm() * context_.mass(Eigen::seq(0, Eigen::last, 3));
    if (scene_.load)
      for (Index v : scene_.load->vertices) f[v] += Eigen::Vector3d(scene_.load->force.data()).norm();
    double scale = f.maxCoeff();
    if (scale > 0) return scale;
    if (dynamic) return context_.mass.maxCoeff() * longest_edge_ / (scene_.solve.dt * scene_.solve.dt);
    scale = scene_.material.young * scene_.material.thickness * longest_edge_;
    if (!(scale > 0) && scene_.bending) scale = scene_.bending->k / longest_edge_;
    return scale;
  }

  static const char* rung_name(Rung rung) {
    return rung == Rung::newton      ? "newton"
           : rung == Rung::projected ? "projected"
           : rung == Rung::shifted   ? "shifted"
                                     : "gradient";
  }

  void count(Rung rung) {
    auto& s = summary_.solver;
    (rung == Rung::newton      ? s.newton
     : rung == Rung::projected ? s.projected
     : rung == Rung::shifted   ? s.shifted_rung
                               : s.gradient)++;
  }

  // Factors A (the reduced matrix) and solves A d = b; false if A is not positive definite or d is not a
  // descent direction (b = -gradient: b . d > 0).
  // Its time is time_s.linear_solve.
  bool factor_and_solve(const Eigen::VectorXd& b, Eigen::VectorXd& d, bool shifted) {
    ++summary_.solver.factorizations;
    if (shifted) ++summary_.solver.shifted;
    const auto t = Clock::now();
    const bool factored = solver_->factorize(reduction_->matrix());
    if (factored) d = solver_->solve(b);
    linear_time_ += seconds_since(t);
    return factored && d.allFinite() && b.dot(d) > 0;
  }

  // The iteration's direction d (free coordinates) from the first rung of the fallback chain that gives a
  // positive definite matrix: the scene's treatment as it is; every element's Hessian projected (the scene's
  // Hessian kept as model_, the projected matrix the trust region's preconditioner); a shift tau D (D = M /
  // dt^2 in a time step, the mean diagonal entry times I in a static solve; tau from 1e-3 growing tenfold to
  // 1e6, starting a tenth below the step's last successful shift); the gradient step d = D^-1 b.
  Rung descent(Evaluation& ev, const Inertia* inertia, const Eigen::VectorXd& b, Eigen::VectorXd& d) {
    auto& A = reduction_->matrix();
    model_is_factored_ = true;
    if (b.size() == 0 || b.isZero(0.0)) {  // nothing free, or no force: the step is zero
      d.setZero(b.size());
      return Rung::newton;
    }
    reduction_->reduce_matrix(ev.hessian);
    if (factor_and_solve(b, d, false)) return keep_factored(Rung::newton);
    model_ = A;  // the scene's Hessian, not positive definite
    model_is_factored_ = false;
    evaluate(x_, want_hessian, inertia, Treatment::projected);
    reduction_->reduce_matrix(ev_.hessian);
    if (factor_and_solve(b, d, false)) return keep_factored(Rung::projected);
    Eigen::VectorXd scale;
    if (inertia) {
      reduction_->reduce_vector(inertia->weight, scale);
    } else {
      const double mean = A.diagonal().cwiseAbs().mean();
      scale = Eigen::VectorXd::Constant(A.rows(), mean > 0 ? mean : 1.0);
    }
    const Eigen::VectorXd diagonal = A.diagonal();
    for (double tau = std::max(1e-3, shift_ / 10); tau <= 1e6; tau *= 10) {
      for (Eigen::Index k = 0; k < A.rows(); ++k) A.coeffRef(k, k) = diagonal[k] + tau * scale[k];
      if (factor_and_solve(b, d, true)) {
        shift_ = tau;
        return keep_factored(Rung::shifted);
      }
    }
    d = b.cwiseQuotient(scale);
    if (dumping_) factored_ = Eigen::SparseMatrix<double>(scale.asDiagonal()).triangularView<Eigen::Upper>();
    return Rung::gradient;
  }

  // Where a step is tried: the step's inertia, its number, the Newton iteration, the potential at x_.
  struct Attempt {
    const Inertia* inertia;
    int step, iteration;
    double energy;
    std::string where() const {
      return "Newton iteration " + std::to_string(iteration) +
             (inertia ? " of step " + std::to_string(step) : std::string());
    }
  };

  // The rounding of the potential's evaluation at a state whose potential is `energy`: decreases below it
  // are not told apart from zero.
  static double allowance(double energy) { return 1e-13 * std::abs(energy); }

  // The newton and projected rungs' step: a trust region on the quadratic model of the potential whose
  // Hessian is the scene's (model_; on the newton rung the matrix factored, P), the step z from Steihaug's
  // truncated conjugate gradients preconditioned by P, the region measured in P's norm |z|_P = sqrt(z^T P z).
  // On the newton rung the first iterate is Newton's step. On the projected rung P >= model_ but where
  // elements were projected, so a few iterations solve the model where it is convex, and a direction of
  // negative curvature of the scene's Hessian is followed to the boundary (near a buckling saddle a projected
  // step alone creeps). rho, the potential's decrease over the model's, sets the radius: a step with rho <=
  // 1e-4 is retried inside a quarter of it (counted in "halvings"), below 1/4 the next region is a quarter of
  // the step; a step on the boundary with rho > 3/4 is tried again in a region twice as wide, and kept while
  // the potential falls further (a radius cut too far grows back within the iteration, not over many).
  // Each step is shortened by the effects' step limits. The radius starts every time step at the length of
  // its first Newton step. Returns whether the step taken is the whole Newton step (the stop rule's
  // condition); d = P^-1 b.
  bool trust_region(const Attempt& at, const Eigen::VectorXd& b, const Eigen::VectorXd& d, IterationReport& report) {
    const auto& P = reduction_->matrix();
    const auto& H = model_is_factored_ ? P : model_;
    Eigen::VectorXd z, dx, taken;
    double taken_energy = at.energy;
    bool have = false, whole = false;
    const double tiny = allowance(at.energy);
    if (!(radius_ > 0)) radius_ = std::sqrt(b.dot(d));  // |P^-1 b|_P
    for (int attempt = 0; attempt < 100; ++attempt) {
      const bool interior = steihaug(H, b, d, z);
      reduction_->expand_vector(z, dx);
      const double alpha = step_limit(x_, dx);
      z *= alpha, dx *= alpha;
      const Eigen::VectorXd Hz = H.selfadjointView<Eigen::Upper>() * z;
      const double predicted = b.dot(z) - 0.5 * z.dot(Hz);
      Eigen::VectorXd trial = x_ + dx;
      const double e = energy_at(trial, at.inertia), actual = at.energy - e;
      const bool accept = predicted <= tiny ? actual >= -tiny : actual > 1e-4 * predicted;
      const double rho = predicted <= tiny ? (accept ? 1 : -1) : actual / predicted;
      const double zPz = model_is_factored_ ? z.dot(Hz) : z.dot(P.selfadjointView<Eigen::Upper>() * z);
      const double norm = std::sqrt(std::max(0.0, zPz));
      const bool widen = rho > 0.75 && !interior && alpha == 1;  // the model held to the boundary
      // A step was taken: a wider region's step replaces it while the potential falls further, by more than its
      // rounding (a tie decided by the last digits would send two nearly equal runs down different paths).
      if (have) {
        if (!(accept && e < taken_energy - tiny)) {
          radius_ /= 2;
          break;
        }
      } else if (!accept) {
        radius_ = 0.25 * norm;
        ++summary_.solver.halvings;
        if (!(radius_ > 0)) break;
        continue;
      } else if (rho < 0.25) {
        radius_ = 0.25 * norm;
      }
      taken = std::move(trial), taken_energy = e, have = true;
      whole = interior && alpha == 1;
      report.alpha = alpha, report.boundary = !interior;
      if (!widen) break;
      radius_ *= 2;
    }
    if (!have) throw Failure{"the trust region found no decrease of the potential (" + at.where() + ")"};
    if (report.alpha < 1) ++summary_.solver.limited;
    x_ = std::move(taken);
    return whole;
  }

  // Steihaug's truncated conjugate gradients for min_z m(z) = -b^T z + z^T H z / 2 within |z|_P <= radius_,
  // preconditioned by the factored P; d = P^-1 b, the first preconditioned residual. Returns whether it
  // stopped inside the region (the residual's P^-1 norm 1e-8 times its start), not at its boundary along a
  // direction of negative curvature or a step that would leave it. The P-norms by the recurrences of Conn,
  // Gould and Toint (Trust-Region Methods, 2000, sec. 7.5.1).
  bool steihaug(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& b, const Eigen::VectorXd& d,
                Eigen::VectorXd& z) {
    const auto t = Clock::now();  // the solves with P: linear solve time
    z.setZero(b.size());
    Eigen::VectorXd r = b, y = d, p = d, Hp;
    double ry = r.dot(y);
    const double ry0 = ry, radius2 = radius_ * radius_;
    double zPz = 0, zPp = 0, pPp = ry;
    bool interior = false;
    for (int j = 0; j < 100; ++j) {
      Hp = H.selfadjointView<Eigen::Upper>() * p;
      const double kappa = p.dot(Hp), a = ry / kappa;
      // To the boundary along p; beyond a relative slack of 1e-9, since the radius starts at the first step's
      // length, which rounding would put on either side.
      if (!(kappa > 0) || zPz + 2 * a * zPp + a * a * pPp > radius2 * (1 + 1e-9)) {
        const double tau = (-zPp + std::sqrt(std::max(0.0, zPp * zPp + pPp * (radius2 - zPz)))) / pPp;
        z += tau * p;
        break;
      }
      z += a * p;
      zPz += 2 * a * zPp + a * a * pPp;
      r -= a * Hp;
      if (j > 0 || !model_is_factored_) y = solver_->solve(r);
      else y.setZero(r.size());  // on the newton rung the first iterate is the solution
      const double ry_next = r.dot(y);
      if (!(ry_next > 1e-16 * ry0)) {
        interior = true;
        break;
      }
      const double beta = ry_next / ry;
      ry = ry_next;
      zPp = beta * (zPp + a * pPp);
      pPp = ry + beta * beta * pPp;
      p = y + beta * p;
    }
    linear_time_ += seconds_since(t);
    return interior;
  }

  // Backtracking along the shifted or gradient rung's step dx: halved until the potential falls by
  // Armijo's sufficient decrease (1e-4 of the slope's promise), after the effects' step limits.
  void line_search(const Attempt& at, const Eigen::VectorXd& gradient, const Eigen::VectorXd& dx,
                   IterationReport& report) {
    double alpha = step_limit(x_, dx);
    if (alpha < 1) ++summary_.solver.limited;
    const double slope = gradient.dot(dx);  // < 0: a descent direction
    for (int halvings = 0; halvings < 60; ++halvings, alpha /= 2) {
      Eigen::VectorXd trial = x_ + alpha * dx;
      if (energy_at(trial, at.inertia) <= at.energy + 1e-4 * alpha * slope + allowance(at.energy)) {
        x_ = std::move(trial);
        report.alpha = alpha;
        return;
      }
      ++summary_.solver.halvings;
    }
    throw Failure{"the line search found no decrease of the potential (" + at.where() + ")"};
  }

  Rung keep_factored(Rung rung) {
    if (dumping_) factored_ = reduction_->matrix();
    return rung;
  }

  bool wants_dump(int step, int iteration) const {
    return options_.on_dump &&
           std::find(options_.dump.begin(), options_.dump.end(), std::pair(step, iteration)) != options_.dump.end();
  }

  // --dump-system: the true Hessian (every effect exact, with the inertia), the matrix factored, the
  // gradient, the state; not counted in time_s.
  void dump(int step, int iteration, const Inertia* inertia, const Eigen::VectorXd& gradient) {
    const auto t = Clock::now();
    SystemDump out;
    out.step = step, out.iteration = iteration;
    const std::vector<double> kept = ev_.hessian;
    Eigen::SparseMatrix<double> factored = reduction_->matrix();  // the trust region's norm: the run goes on with it
    evaluate(x_, want_hessian, inertia, Treatment::exact);
    reduction_->reduce_matrix(ev_.hessian);
    out.hessian = reduction_->matrix();
    reduction_->matrix() = std::move(factored);
    ev_.hessian = kept;
    out.factored = factored_;
    reduction_->reduce_vector(gradient, out.gradient);
    const Mesh state = state_mesh();
    out.state = &state;
    options_.on_dump(out);
    output_time_ += seconds_since(t);
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
  double force_scale_ = 1;  // F of the stop rule
  double shift_ = 0, longest_edge_ = 0, output_time_ = 0, linear_time_ = 0;
  double radius_ = 0;                  // the trust region's radius in P's norm, reset every step
  Eigen::SparseMatrix<double> model_;  // the scene's Hessian on the projected rung (the factored one's otherwise)
  bool model_is_factored_ = true;
  std::vector<int> per_step_;  // Newton iterations of each step
  bool dumping_ = false;       // this iteration is dumped: keep a copy of the matrix factored
  Eigen::SparseMatrix<double> factored_;
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
