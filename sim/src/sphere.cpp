// Sphere: a static obstacle no vertex enters. A barrier of the vertex's distance d = |x - c| - r to the
// surface (Li et al.'s IPC barrier, C2, zero beyond d_hat, infinite at contact):
//   kappa b(d),  b(d) = -(d - d_hat)^2 ln(d / d_hat) for 0 < d < d_hat,
// and a step limit (max_step) that stops every Newton step short of the surface, so the barrier is never
// crossed. d_hat = r / 100; kappa puts a force of ten times the heaviest vertex's weight at d = d_hat / 2
// (docs/simulator.md). The barrier's Hessian is kappa (b'' n n^T + b' (I - n n^T) / |x - c|): b'' > 0 and
// b' < 0 on (0, d_hat), so the second part is negative semidefinite; it is kept but on the fallback chain's
// projected rung (projects(), effect.hpp), where kappa b'' n n^T, exactly the projection of the 3 x 3, is.
#include <cmath>

#include "effects_internal.hpp"
#include "hinge/core/errors.hpp"

namespace hinge::sim::detail {
namespace {

class SphereEffect final : public Effect {
 public:
  SphereEffect(const Context& c, const Sphere& s)
      : center_(s.center[0], s.center[1], s.center[2]), radius_(s.radius), d_hat_(s.radius / 100),
        slots_(c.topology->vertex_count), file_(c.scene->file), treatment_(c.scene->solve.hessian) {
    double weight = 0, accel = 9.81;
    if (c.scene->gravity) accel = std::max(accel, Eigen::Vector3d(c.scene->gravity->g.data()).norm());
    for (Eigen::Index d = 0; d < c.mass.size(); ++d) weight = std::max(weight, c.mass[d]);
    weight *= accel;
    if (c.scene->load) weight = std::max(weight, Eigen::Vector3d(c.scene->load->force.data()).norm());
    // -b'(d_hat / 2) = d_hat (1/2 + ln 2)
    kappa_ = 10 * weight / (d_hat_ * (0.5 + std::log(2.0)));
    for (Index v = 0; v < static_cast<Index>(slots_.size()); ++v) {
      const Index vs[1] = {v};
      slots_[static_cast<std::size_t>(v)] = c.sparsity->element_slots(vs);
    }
  }
  std::string_view name() const override { return "sphere"; }

  void check_initial(const Eigen::VectorXd& x) const override {
    for (Eigen::Index v = 0; v < x.size() / 3; ++v)
      if (!((x.segment<3>(3 * v) - center_).norm() > radius_ + d_hat_ / 100))
        throw InputError(file_ + ": effects.sphere: vertex " + std::to_string(v) +
                         " starts inside the sphere or within r / 10^4 of its surface");
  }

  void add(const Eigen::VectorXd& x, Evaluation& out) override {
    for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
      const Eigen::Vector3d p = x.segment<3>(3 * v) - center_;
      const double norm = p.norm(), d = norm - radius_;
      if (d >= d_hat_) continue;
      if (!(d > 0)) throw DomainError("a vertex reached the sphere");  // never accepted (max_step)
      const double g = d - d_hat_, l = std::log(d / d_hat_);
      const double b = -g * g * l, b1 = -2 * g * l - g * g / d, b2 = -2 * l - 4 * g / d + g * g / (d * d);
      const Eigen::Vector3d n = p / norm;
      if (out.request & 1u) out.energy += kappa_ * b;
      if (out.request & 2u) out.gradient.segment<3>(3 * v) += kappa_ * b1 * n;
      if (out.request & 4u) {
        Eigen::Matrix3d h = kappa_ * b2 * n * n.transpose();
        if (!projects(out.treatment, treatment_, false))
          h += kappa_ * b1 / norm * (Eigen::Matrix3d::Identity() - n * n.transpose());
        scatter(std::span<const double>(h.data(), 9), slots_[static_cast<std::size_t>(v)], out.hessian);
      }
    }
  }

  double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const override {
    double alpha = 1;
    for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
      const Eigen::Vector3d p = x.segment<3>(3 * v) - center_, q = dx.segment<3>(3 * v);
      const double a = q.squaredNorm(), b = p.dot(q), c = p.squaredNorm() - radius_ * radius_;
      if (!(b < 0) || a == 0) continue;  // moving away from the centre, or not moving
      const double disc = b * b - a * c;
      if (disc < 0) continue;                           // the line misses the sphere
      const double first = c / (-b + std::sqrt(disc));  // the nearer root of a t^2 + 2 b t + c
      alpha = std::min(alpha, 0.8 * first);
    }
    return alpha;
  }

 private:
  Eigen::Vector3d center_;
  double radius_, d_hat_, kappa_ = 0;
  std::vector<std::vector<Slot>> slots_;
  std::string file_;
  HessianTreatment treatment_;
};

}  // namespace

std::unique_ptr<Effect> make_sphere(const Context& context, const Sphere& sphere) {
  return std::make_unique<SphereEffect>(context, sphere);
}

}  // namespace hinge::sim::detail
