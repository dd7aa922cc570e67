// Bending: E = sum_i psi_i(theta_i) (eq. (1)) with the contract's energies, its gradient (eq. (2)) and
// Hessian (eq. (3)), through hinge::fast or any method and scalar type of `hinge eval`.
//   exact         the assembled Hessian: hinge::fast's Algorithm 2 in double (threaded, the same bits for
//                 any thread count), or hinge::methods::MeshEvaluator for another method or scalar type
//   projected     per hinge psi'' grad theta grad theta^T + psi' Hess theta (eq. (3)) projected to positive
//                 semidefinite (its 12 x 12 eigenvalues below zero set to zero), then assembled
//   gauss-newton  per hinge max(psi'', 0) grad theta grad theta^T only (as ARCSim)
// With damping's "bending" part, the energy is the paper's viscoelastic one (section 5): one theta per
// hinge, the elastic and viscous parts only in psi' and psi''; phi_hat from the state at the start of
// each step.
#include <chrono>
#include <cmath>
#include <map>

#include "effects_internal.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/fast/assemble.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/methods/methods.hpp"

namespace hinge::sim::detail {
namespace {

using Mat12 = Eigen::Matrix<double, 12, 12>;

class BendingEffect final : public Effect {
 public:
  BendingEffect(const Context& c, const Bending& b, const Damping* damping)
      : topology_(*c.topology), sparsity_(*c.sparsity), treatment_(c.scene->solve.hessian), method_(b.method),
        scalar_(b.scalar), direct_(b.method == methods::Method::fast && b.scalar.kind == ScalarType::Kind::kind_double),
        threads_(c.threads), assembler_(topology_), rest_(c.scene->rest), mesh_(c.scene->mesh), file_(c.scene->file) {
    parameters_.model = b.energy;
    parameters_.k = b.k;                    // given, or eq. (11) from the material: the scene reader decided
    if (damping && damping->bending > 0) {  // section 5: the viscoelastic model
      parameters_.model = Model::viscoelastic;
      parameters_.k_d_over_dt = damping->bending * parameters_.k / c.dt;
    }
    try {
      coefficients_ = assembler_.rest_state(rest_, parameters_, c.threads);  // Algorithm 1
    } catch (const std::exception& e) {
      throw InputError(file_ + ": effects.bending: the rest shape: " + e.what());
    }
    // The paper's eq. (10), |theta_bar| < pi, enforced at initialization as section 5 says: at theta_bar = pi
    // (two rest triangles overlapping) every energy but tan's jumps across the branch cut, so Newton could
    // not descend from the rest state itself.
    for (std::size_t i = 0; i < coefficients_.size(); ++i)
      if (!(std::abs(coefficients_[i].theta_bar) < M_PI)) {
        const auto& x = topology_.hinges[i].x;
        throw InputError(file_ + ": effects.bending: the rest shape: the hinge on the edge of vertices " +
                         std::to_string(x[1]) + " and " + std::to_string(x[2]) +
                         " (0-based) is folded flat (theta_bar = pi: its two triangles overlap); eq. (10) needs "
                         "|theta_bar| < pi");
      }
  }

  std::string_view name() const override { return "bending"; }
  bool has_energy() const override { return true; }

  double energy(const Eigen::VectorXd& x) override {  // the elastic part alone
    set_mesh(x);
    const Model elastic = parameters_.model == Model::viscoelastic ? Model::tan : parameters_.model;
    if (direct_) {
      assembler_.evaluate(mesh_, coefficients_, elastic, want_energy, threads_, result_);
      return result_.energy;
    }
    double e = 0;
    for (std::size_t i = 0; i < topology_.hinges.size(); ++i) e += hinge_psi(i, elastic, false).value;
    return e;
  }

  void begin_step(const Eigen::VectorXd& x, const Eigen::VectorXd&) override {
    if (parameters_.model != Model::viscoelastic) return;
    set_mesh(x);
    assembler_.set_previous_state(coefficients_, mesh_, threads_);  // phi_hat per hinge
  }

  void add(const Eigen::VectorXd& x, Evaluation& out) override {
    set_mesh(x);
    // The evaluation's treatment (effect.hpp): the true Hessian, every hinge's projected, or the scene's.
    const HessianTreatment mode = out.treatment == Treatment::exact       ? HessianTreatment::exact
                                  : out.treatment == Treatment::projected ? HessianTreatment::projected
                                                                          : treatment_;
    if (mode == HessianTreatment::exact) add_assembled(out);
    else add_per_hinge(out, mode == HessianTreatment::gauss_newton);
  }

 private:
  void set_mesh(const Eigen::VectorXd& x) {
    for (std::size_t v = 0; v < mesh_.vertices.size(); ++v)
      for (std::size_t c = 0; c < 3; ++c) mesh_.vertices[v][c] = x[static_cast<Eigen::Index>(3 * v + c)];
  }

  // The exact Hessian, assembled by hinge::fast (Algorithm 2) or by MeshEvaluator.
  void add_assembled(Evaluation& out) {
    const unsigned request = out.request;
    if (direct_) {
      assembler_.evaluate(mesh_, coefficients_, parameters_.model, request, threads_, result_);
      add_result(out, result_.energy, result_.gradient.data(), result_.hessian);
      return;
    }
    auto it = evaluators_.find(request);
    if (it == evaluators_.end()) {
      methods::MeshInput input;
      input.deformed = &mesh_, input.rest = &rest_, input.topology = &topology_;
      input.parameters = parameters_, input.request = request, input.threads = threads_;
      it = evaluators_.emplace(request, std::make_unique<methods::MeshEvaluator>(method_, scalar_, input)).first;
    }
    it->second->evaluate();
    const RoundedMesh r = it->second->take_result();
    add_result(out, r.energy, r.gradient.data(), r.hessian);
  }

  void add_result(Evaluation& out, double energy, const double* gradient, const Eigen::SparseMatrix<double>& h) {
    if (out.request & 1u) out.energy += energy;
    if (out.request & 2u) out.gradient += Eigen::Map<const Eigen::VectorXd>(gradient, out.gradient.size());
    if (!(out.request & 4u)) return;
    if (map_.size() != static_cast<std::size_t>(h.nonZeros())) {  // the evaluator's structure, mapped once
      map_.clear();
      for (Eigen::Index col = 0; col < h.outerSize(); ++col)
        for (Eigen::SparseMatrix<double>::InnerIterator e(h, col); e; ++e) {
          const Slot s = sparsity_.slot(e.row(), col);
          if (s < 0) throw std::logic_error("sim: the bending Hessian has an entry outside the structure");
          map_.push_back(s);
        }
    }
    const double* values = h.valuePtr();
    for (std::size_t k = 0; k < map_.size(); ++k) out.hessian[static_cast<std::size_t>(map_[k])] += values[k];
  }

  // theta and its derivatives for hinge i at the current mesh, by the scene's method.
  Psi<double> hinge_psi(std::size_t i, Model model, bool want_hessian) {
    const auto x = hinge_coordinates(mesh_, topology_.hinges[i]);
    if (direct_) {
      d_ = fast::hinge_derivatives<double>(x, want_hessian);
    } else {
      const RoundedTheta r = methods::evaluate_hinge(method_, scalar_, x);
      d_.theta = r.theta;
      d_.on_branch_cut = r.theta == M_PI;
      d_.tan_half_theta = d_.on_branch_cut ? INFINITY : std::tan(r.theta / 2);
      d_.grad = Eigen::Map<const Eigen::Matrix<double, 12, 1>>(r.grad.data());
      d_.hess = Eigen::Map<const Eigen::Matrix<double, 12, 12, Eigen::RowMajor>>(r.hess.data());
    }
    return psi(model, coefficients_[i], BendAngle<double>{d_.theta, d_.tan_half_theta, d_.on_branch_cut});
  }

  // projected and gauss-newton: hinge by hinge.
  void add_per_hinge(Evaluation& out, bool gauss_newton) {
    const bool hessian = out.request & 4u;
    if (hessian && hinge_slots_.empty()) {  // the slots of each hinge's 12 x 12, found once
      hinge_slots_.reserve(topology_.hinges.size());
      for (const auto& h : topology_.hinges) hinge_slots_.push_back(sparsity_.element_slots(h.x));
    }
    for (std::size_t i = 0; i < topology_.hinges.size(); ++i) {
      const Psi<double> p = hinge_psi(i, parameters_.model, hessian && !gauss_newton);
      if (out.request & 1u) out.energy += p.value;
      const auto& x = topology_.hinges[i].x;
      if (out.request & 2u)
        for (int v = 0; v < 4; ++v)
          out.gradient.segment<3>(3 * x[static_cast<std::size_t>(v)]) += p.d1 * d_.grad.segment<3>(3 * v);
      if (!hessian) continue;
      Mat12 h = std::max(p.d2, gauss_newton ? 0.0 : -INFINITY) * d_.grad * d_.grad.transpose();  // eq. (3)
      if (!gauss_newton) {
        h += p.d1 * d_.hess;
        project_to_psd<12>(h);
      }
      scatter(std::span<const double>(h.data(), 144), hinge_slots_[i], out.hessian);
    }
  }

  const Topology& topology_;
  const Sparsity& sparsity_;
  HessianTreatment treatment_;
  methods::Method method_;
  ScalarType scalar_;
  bool direct_;  // fast in double: hinge::fast's own entry points, no rounding step
  int threads_;
  EnergyParameters parameters_;
  fast::Assembler<double> assembler_;
  std::vector<HingeCoefficients<double>> coefficients_;
  MeshDerivatives<double> result_;
  std::map<unsigned, std::unique_ptr<methods::MeshEvaluator>> evaluators_;
  std::vector<Slot> map_;
  std::vector<std::vector<Slot>> hinge_slots_;
  fast::HingeDerivatives<double> d_;
  Mesh rest_, mesh_;
  std::string file_;
};

}  // namespace

std::unique_ptr<Effect> make_bending(const Context& context, const Bending& bending, const Damping* damping) {
  return std::make_unique<BendingEffect>(context, bending, damping);
}

}  // namespace hinge::sim::detail
