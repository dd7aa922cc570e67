// Stretching: the StVK membrane of the contract, per triangle h A (mu E:E + lambda/2 tr(E)^2), E = (F^T F -
// I) / 2 the Green strain of the constant-strain triangle, F = D_s D_m^-1 (3 x 2) with D_s = [x1 - x0,
// x2 - x0] and D_m the rest edges in the rest triangle's own plane; plane stress lambda = Y nu / (1 - nu^2),
// mu = Y / (2 (1 + nu)). Gradient h A P D_m^-T with P = F S, S = 2 mu E + lambda tr(E) I; the Hessian by
// differentiating P along each of the six directions of D_s. StVK's Hessian is indefinite under
// compression: it is used as it is (the scene's "hessian" governs bending alone: each triangle projected
// makes Newton converge only linearly where the cloth compresses, docs/simulator.md), and each triangle's
// 9 x 9 is projected to positive semidefinite on the fallback chain's projected rung (projects(), effect.hpp).
#include <Eigen/Geometry>
#include <cmath>

#include "effects_internal.hpp"
#include "hinge/core/errors.hpp"

namespace hinge::sim::detail {
namespace {

using Mat32 = Eigen::Matrix<double, 3, 2>;
using Mat9 = Eigen::Matrix<double, 9, 9>;

struct Triangle {
  std::array<Index, 3> v;
  Eigen::Matrix2d dm_inv;
  double area;
};

class StretchingEffect final : public Effect {
 public:
  explicit StretchingEffect(const Context& c) : treatment_(c.scene->solve.hessian) {
    const Material& m = c.scene->material;
    mu_ = m.young / (2 * (1 + m.poisson));
    lambda_ = m.young * m.poisson / (1 - m.poisson * m.poisson);
    h_ = m.thickness;
    const Mesh& rest = c.scene->rest;
    for (std::size_t f = 0; f < rest.faces.size(); ++f) {
      const auto& face = rest.faces[f];
      auto X = [&](int i) { return Eigen::Vector3d(rest.vertices[static_cast<std::size_t>(face[i])].data()); };
      const Eigen::Vector3d e1 = X(1) - X(0), e2 = X(2) - X(0);
      const double l = e1.norm(), a = e2.dot(e1) / l, b = e1.cross(e2).norm() / l;
      if (!(b > 0) || !std::isfinite(a))
        throw InputError(c.scene->file + ": effects.stretching: rest face " + std::to_string(f) + " has zero area");
      Eigen::Matrix2d dm;
      dm << l, a, 0, b;
      triangles_.push_back({face, dm.inverse(), l * b / 2});
      slots_.push_back(c.sparsity->element_slots(face));
    }
  }
  std::string_view name() const override { return "stretching"; }
  bool has_energy() const override { return true; }
  double energy(const Eigen::VectorXd& x) override {
    Evaluation e;
    e.request = 1;
    add(x, e);
    return e.energy;
  }

  void add(const Eigen::VectorXd& x, Evaluation& out) override {
    const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const Triangle& tri = triangles_[t];
      const Eigen::Vector3d x0 = x.segment<3>(3 * tri.v[0]);
      Mat32 ds;
      ds << x.segment<3>(3 * tri.v[1]) - x0, x.segment<3>(3 * tri.v[2]) - x0;
      const Mat32 F = ds * tri.dm_inv;
      const Eigen::Matrix2d E = (F.transpose() * F - I) / 2;
      const double trE = E.trace(), w = h_ * tri.area;
      if (out.request & 1u) out.energy += w * (mu_ * E.squaredNorm() + lambda_ / 2 * trE * trE);
      if (!(out.request & 6u)) continue;
      const Eigen::Matrix2d S = 2 * mu_ * E + lambda_ * trE * I;
      if (out.request & 2u) {
        const Mat32 G = w * F * S * tri.dm_inv.transpose();
        out.gradient.segment<3>(3 * tri.v[1]) += G.col(0);
        out.gradient.segment<3>(3 * tri.v[2]) += G.col(1);
        out.gradient.segment<3>(3 * tri.v[0]) -= G.col(0) + G.col(1);
      }
      if (!(out.request & 4u)) continue;
      Eigen::Matrix<double, 6, 6> h6;  // d G / d D_s, entry 3 c + r of D_s
      for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 3; ++r) {
          Mat32 dF = Mat32::Zero();
          dF.row(r) = tri.dm_inv.row(c);
          const Eigen::Matrix2d dE = (dF.transpose() * F + F.transpose() * dF) / 2;
          const Eigen::Matrix2d dS = 2 * mu_ * dE + lambda_ * dE.trace() * I;
          const Mat32 dG = w * (dF * S + F * dS) * tri.dm_inv.transpose();
          h6.col(3 * c + r) = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(dG.data());
        }
      // D_s = [x1 - x0, x2 - x0]: the 9 x 9 on (x0, x1, x2).
      const auto H11 = h6.block<3, 3>(0, 0), H12 = h6.block<3, 3>(0, 3), H21 = h6.block<3, 3>(3, 0),
                 H22 = h6.block<3, 3>(3, 3);
      Mat9 h9;
      h9.block<3, 3>(3, 3) = H11, h9.block<3, 3>(3, 6) = H12, h9.block<3, 3>(6, 3) = H21, h9.block<3, 3>(6, 6) = H22;
      h9.block<3, 3>(0, 3) = -(H11 + H21), h9.block<3, 3>(0, 6) = -(H12 + H22);
      h9.block<3, 3>(3, 0) = -(H11 + H12), h9.block<3, 3>(6, 0) = -(H21 + H22);
      h9.block<3, 3>(0, 0) = H11 + H12 + H21 + H22;
      if (projects(out.treatment, treatment_, false)) project_to_psd<9>(h9);
      scatter(std::span<const double>(h9.data(), 81), slots_[t], out.hessian);
    }
  }

 private:
  HessianTreatment treatment_;
  double mu_ = 0, lambda_ = 0, h_ = 0;
  std::vector<Triangle> triangles_;
  std::vector<std::vector<Slot>> slots_;
};

}  // namespace

std::unique_ptr<Effect> make_stretching(const Context& context) { return std::make_unique<StretchingEffect>(context); }

}  // namespace hinge::sim::detail
