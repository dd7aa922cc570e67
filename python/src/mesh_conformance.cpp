// hinge._hinge's whole-mesh conformance part, for hinge.conform_mesh (python/hinge/mesh_conformance.py, which
// calls the candidate and converts its arrays; docs/mesh-conformance.md): a MeshProblem holds a mesh, its
// topology and its certified values (oracle::certified_mesh), and grades what the candidate returned on it:
// its energy, gradient and Hessian against the certified ones (conformance::compare_mesh_gradient and
// compare_mesh_hessian; the energy by the rule below), the energy and gradient under the rigid motions of
// conformance/consistency.hpp, the net force and torque (net_load), and the force at rest. Where an output
// fails, it names the vertex pair of the worst 3 x 3 block of the difference and the hinges containing both.
// Every error and tolerance is in units of u = 2^-53, relative to the scale each check states.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "hinge/conformance/consistency.hpp"
#include "hinge/conformance/energy_sets.hpp"
#include "hinge/conformance/grading.hpp"
#include "hinge/conformance/inputs.hpp"
#include "hinge/core/bending_problem.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge/oracle/mesh.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace hinge::python {
namespace {

namespace conf = hinge::conformance;
using oracle::scaled_norm;
using Coordinates = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using Sparse = Eigen::SparseMatrix<double>;

constexpr double u = 0x1p-53;  // the unit of every error and tolerance
constexpr double infinity = std::numeric_limits<double>::infinity();

// The force at rest passes within at_rest_tolerance u sum_h L_h ||H_h||_F (docs/mesh-conformance.md): the
// force of an angle error 16 u (s_X + s_R) = 32 u L_h ||grad theta_h|| on each hinge, as in the contract's
// zero-energy bound.
constexpr double at_rest_tolerance = 32;

// The (n, 3) array `a` as vertices (hinge.conform_mesh has checked shape and finiteness).
std::vector<std::array<double, 3>> to_vertices(const Coordinates& a) {
  if (a.ndim() != 2 || a.shape(1) != 3) throw py::value_error("MeshProblem: vertices must be (n, 3)");
  std::vector<std::array<double, 3>> out(static_cast<std::size_t>(a.shape(0)));
  std::copy_n(a.data(), 3 * out.size(), out.empty() ? nullptr : out[0].data());
  return out;
}

std::vector<double> flat(const Coordinates& a) { return std::vector<double>(a.data(), a.data() + a.size()); }

std::vector<double> flat(const Mesh& m) {
  std::vector<double> out;
  out.reserve(3 * m.vertices.size());
  for (const auto& v : m.vertices) out.insert(out.end(), v.begin(), v.end());
  return out;
}

py::array_t<double> as_array(const std::vector<double>& x) {
  py::array_t<double> out({static_cast<py::ssize_t>(x.size() / 3), py::ssize_t{3}});
  std::copy(x.begin(), x.end(), out.mutable_data());
  return out;
}

// The longest of a hinge's five edge vectors (x1 x2, x0 x1, x0 x2, x3 x1, x3 x2).
double longest_edge(const std::array<double, 12>& x) {
  constexpr int edges[5][2] = {{1, 2}, {0, 1}, {0, 2}, {3, 1}, {3, 2}};
  double longest = 0;
  for (const auto& [a, b] : edges) {
    const double d[3] = {x[3 * b] - x[3 * a], x[3 * b + 1] - x[3 * a + 1], x[3 * b + 2] - x[3 * a + 2]};
    longest = std::max(longest, scaled_norm(d, 3));
  }
  return longest;
}

// The larger of two errors, NaN (an output that cannot be compared) counting as the largest.
double worse(double a, double b) { return std::isnan(a) || a > b ? a : b; }

// One graded check, as hinge.conform_mesh lists it (the mesh's name is added there).
py::dict check(const std::string& name, double error, double tolerance, bool pass, const std::string& detail = "") {
  py::dict d("check"_a = name, "error"_a = error, "tolerance"_a = tolerance, "pass"_a = pass);
  if (!detail.empty()) d["detail"] = detail;
  return d;
}

// A consistency check by the contract's rule: fails where the discrepancy exceeds both 8 times the estimate
// 16 (1 + kappa) u and 2^-20 (both relative to the same scale); error and tolerance in units of u.
py::dict consistency(const std::string& name, double discrepancy, double kappa) {
  const double estimate = 16 * (1 + kappa) * u;
  const double threshold = std::max(8 * estimate, conf::consistency_floor(conf::Dtype::float64));
  return check(name, discrepancy / u, threshold / u, std::isfinite(discrepancy) && discrepancy <= threshold);
}

class MeshProblem {
 public:
  MeshProblem(const Coordinates& vertices, const Indices& faces, const Coordinates& rest, const std::string& energy,
              const py::object& weight, double k, const std::string& hessian) {
    const Energy graded = parsed([&] { return parse_graded_energy(energy, "energy="); });
    const std::optional<Model> model = evaluator_model(graded);
    if (!model)
      throw py::value_error("energy=: the " + energy +
                            " energy is not graded at mesh level yet (conform_mesh grades shells, tan, willmore and "
                            "bridson)");
    if (!py::isinstance<py::str>(weight) || weight.cast<std::string>() != "contract") {
      std::string shown = py::repr(weight);
      throw py::value_error(
          "weight=: conform_mesh grades only weight='contract' (w = 3 |e_bar|^2 / A_bar, the "
          "mesh oracle's); got " +
          shown);
    }
    if (hessian == "projected")
      throw py::value_error(
          "hessian=: the projected Hessian is not graded at mesh level (it has no certified "
          "value); give 'exact' or 'gauss-newton'");
    if (hessian != "exact" && hessian != "gauss-newton")
      throw py::value_error("hessian= must be 'exact' or 'gauss-newton'; got '" + hessian + "'");
    parameters_ = {*model, parsed([&] { return check_k({k, "k="}); }), 0};
    options_.gauss_newton = hessian == "gauss-newton";

    deformed_.vertices = to_vertices(vertices);
    rest_.vertices = to_vertices(rest);
    if (faces.ndim() != 2 || faces.shape(1) != 3) throw py::value_error("MeshProblem: faces must be (m, 3)");
    deformed_.faces.resize(static_cast<std::size_t>(faces.shape(0)));
    for (std::size_t f = 0; f < deformed_.faces.size(); ++f)
      for (std::size_t c = 0; c < 3; ++c) deformed_.faces[f][c] = static_cast<Index>(faces.data()[3 * f + c]);
    rest_.faces = deformed_.faces;

    py::gil_scoped_release release;
    try {
      topology_ = build_topology(deformed_);
      check_bending_mesh(topology_, deformed_, &rest_, {"vertices", "rest", "", false});
      certified_ = oracle::certified_mesh(deformed_, rest_, topology_, parameters_, want_all, options_);
      certified_full_ = certified_.rounded.hessian.selfadjointView<Eigen::Upper>();
      per_hinge();
    } catch (const InputError& e) {
      throw py::value_error(e.what());
    } catch (const DomainError& e) {
      throw py::value_error(e.what());
    }
    const std::vector<double> x = flat(deformed_);
    coordinates_norm_ = scaled_norm(x.data(), x.size());
    gradient_norm_ = scaled_norm(certified_.rounded.gradient.data(), certified_.rounded.gradient.size());
    hessian_norm_ = conf::symmetric_frobenius(certified_.rounded.hessian);
  }

  std::size_t vertex_count() const { return deformed_.vertices.size(); }
  std::size_t hinge_count() const { return topology_.hinges.size(); }
  // The outputs the oracle could not certify within its precision cap (in practice none).
  std::vector<std::string> uncertified() const {
    std::vector<std::string> out;
    for (const auto& v : certified_.uncertified) out.push_back(v.output);
    return out;
  }
  // Whether the force is exactly zero at rest (shells, tan, bridson; not willmore, which has no rest angle).
  bool zero_force_at_rest() const { return parameters_.model != Model::willmore; }

  // The candidate's energy, gradient (3n) and Hessian (triplets of the full 3n x 3n matrix, duplicates
  // summed) against the certified values.
  py::list compare(double energy, const Coordinates& gradient, const Indices& rows, const Indices& cols,
                   const Coordinates& values) const {
    const std::size_t n = 3 * vertex_count();
    const std::vector<double> g = flat(gradient);
    if (g.size() != n || rows.size() != cols.size() || rows.size() != values.size())
      throw py::value_error("MeshProblem.compare: sizes differ");
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(static_cast<std::size_t>(values.size()));
    for (py::ssize_t i = 0; i < values.size(); ++i) {
      const std::int64_t r = rows.data()[i], c = cols.data()[i];
      if (r < 0 || c < 0 || r >= static_cast<std::int64_t>(n) || c >= static_cast<std::int64_t>(n))
        throw py::value_error("MeshProblem.compare: a Hessian index is out of range");
      triplets.emplace_back(static_cast<int>(r), static_cast<int>(c), values.data()[i]);
    }
    py::list out;
    {  // the energy
      const double want = certified_.rounded.energy;
      const double size = std::fabs(want);
      const double error = energy == want ? 0.0 : std::fabs(energy - want) / (size > 0 ? size : 1) / u;
      const double kappa = size > 0 ? energy_contributions_ / size : 1.0;
      const double tolerance = (conf::mesh_base + static_cast<double>(hinge_count()) - 1) * kappa;
      out.append(check("energy", error, tolerance, std::isfinite(error) && error <= tolerance));
    }
    {  // the gradient
      const conf::MeshComparison c = conf::compare_mesh_gradient(certified_, g);
      py::dict d = check("gradient", c.error, c.tolerance, c.pass);
      if (!c.pass) {
        std::vector<double> difference(n);
        for (std::size_t i = 0; i < n; ++i) difference[i] = g[i] - certified_.rounded.gradient[i];
        locate_vertex(d, difference);
      }
      out.append(d);
    }
    {  // the Hessian: both triangles graded (an asymmetric Hessian fails in one of them)
      Sparse candidate(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
      candidate.setFromTriplets(triplets.begin(), triplets.end());
      const Sparse upper = candidate.triangularView<Eigen::Upper>();
      const Sparse transposed = candidate.transpose();
      const Sparse lower = transposed.triangularView<Eigen::Upper>();
      const conf::MeshComparison a = conf::compare_mesh_hessian(certified_, upper);
      const conf::MeshComparison b = conf::compare_mesh_hessian(certified_, lower);
      const bool pass = a.pass && b.pass;
      std::string detail;
      if (!pass && strictly_upper_count(lower) == 0 && strictly_upper_count(upper) > 0)
        detail = "no entry below the diagonal: conform_mesh takes the full symmetric Hessian";
      py::dict d = check("hessian", worse(a.error, b.error), a.tolerance, pass, detail);
      if (!pass) locate_block(d, Sparse(candidate - certified_full_));
      out.append(d);
    }
    return out;
  }

  // The rigid motions of consistency.hpp, their translation in units of the mesh's size (2^floor(log2 D), D
  // the longest side of its bounding box): (name, the moved vertices (n, 3)).
  py::list motions() const {
    py::list out;
    for (const conf::RigidMotion& m : motions_)
      out.append(py::make_tuple(m.name, as_array(conf::apply(m, flat(deformed_)))));
    return out;
  }

  // The candidate's energy and gradient at the vertices (e0, g0) and after motion `index` (e1, g1): the
  // energy unchanged, the gradient turned with the motion.
  py::list check_motion(std::size_t index, double e0, const Coordinates& g0, double e1, const Coordinates& g1) const {
    if (index >= motions_.size()) throw py::value_error("MeshProblem.check_motion: no such motion");
    const conf::RigidMotion& m = motions_[index];
    const std::vector<double> moved = conf::apply(m, flat(deformed_));
    const double size = std::max(coordinates_norm_, scaled_norm(moved.data(), moved.size()));
    py::list out;
    {
      const double scale = energy_scale();
      const double kappa = std::max(energy_kappa(), size * gradient_norm_ / scale);
      out.append(consistency("energy under rigid motion (" + m.name + ")", std::fabs(e1 - e0) / scale, kappa));
    }
    {
      const std::vector<double> turned = conf::apply(m, flat(g0), false), after = flat(g1);
      if (turned.size() != after.size()) throw py::value_error("MeshProblem.check_motion: sizes differ");
      std::vector<double> difference(after.size());
      for (std::size_t i = 0; i < after.size(); ++i) difference[i] = after[i] - turned[i];
      const double scale = gradient_scale();
      const double kappa = std::max(gradient_kappa(), size * hessian_norm_ / scale);
      py::dict d = consistency("gradient turned with the motion (" + m.name + ")",
                               scaled_norm(difference.data(), difference.size()) / scale, kappa);
      if (!d["pass"].cast<bool>()) locate_vertex(d, difference);
      out.append(d);
    }
    return out;
  }

  // The net force and torque (about the centroid) of the candidate's gradient at the vertices: zero. The force
  // relative to ||g||, the torque to rho ||g|| (rho the largest distance of a vertex from the centroid);
  // kappa = sqrt(n) kappa_sum of the gradient (the candidate's errors, within the gradient's tolerance, add up
  // over the n vertices).
  py::list check_net_load(const Coordinates& gradient) const {
    const std::vector<double> g = flat(gradient);
    const conf::NetLoad load = conf::net_load(flat(deformed_), g);
    const double kappa = std::sqrt(static_cast<double>(vertex_count())) * gradient_kappa();
    const double torque_scale = gradient_norm_ > 0 ? radius_ * gradient_norm_ : contract_c_;
    py::list out;
    out.append(consistency("net force", load.force / gradient_scale(), kappa));
    out.append(consistency("net torque", load.torque / (torque_scale > 0 ? torque_scale : 1), kappa));
    return out;
  }

  // The candidate's gradient at rest (fn(rest, faces, rest)): zero within 32 u sum_h L_h ||H_h||_F.
  py::dict check_at_rest(const Coordinates& gradient) const {
    const std::vector<double> g = flat(gradient);
    const double size = scaled_norm(g.data(), g.size());
    const double error = size == 0 ? 0.0 : rest_force_scale_ > 0 ? size / rest_force_scale_ / u : infinity;
    const bool pass = std::isfinite(error) && error <= at_rest_tolerance;
    py::dict d = check("force at rest", error, at_rest_tolerance, pass);
    if (!pass) locate_vertex(d, g);
    return d;
  }

 private:
  // Per hinge, certified on its own two triangles (hinge_mesh): |psi_h| summed (the energy's summation
  // condition number), and at rest L_h ||H_h||_F (the force-at-rest scale); k w_h summed (the scale where an
  // output is zero). Also the mesh's size, the motions scaled to it, its radius about the centroid.
  void per_hinge() {
    const Topology one = build_topology(hinge_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1}));
    for (const Hinge& h : topology_.hinges) {
      const std::array<double, 12> x = hinge_coordinates(deformed_, h), r = hinge_coordinates(rest_, h);
      const Mesh hx = hinge_mesh(x), hr = hinge_mesh(r);
      energy_contributions_ += std::fabs(oracle::certified_mesh(hx, hr, one, parameters_, want_energy).rounded.energy);
      contract_c_ += parameters_.k * conf::named_weight("contract", r);
      longest_edge_ = std::max(longest_edge_, longest_edge(x));
      if (zero_force_at_rest()) {
        const oracle::CertifiedMesh at_rest = oracle::certified_mesh(hr, hr, one, parameters_, want_hessian);
        rest_force_scale_ += longest_edge(r) * conf::symmetric_frobenius(at_rest.rounded.hessian);
      }
    }
    std::array<double, 3> low{infinity, infinity, infinity}, high{-infinity, -infinity, -infinity}, centroid{};
    for (const auto& v : deformed_.vertices)
      for (int c = 0; c < 3; ++c) {
        low[c] = std::min(low[c], v[c]), high[c] = std::max(high[c], v[c]);
        centroid[c] += v[c] / static_cast<double>(vertex_count());
      }
    double side = 0;
    for (int c = 0; c < 3; ++c) side = std::max(side, high[c] - low[c]);
    const double unit = side > 0 && std::isfinite(side) ? std::ldexp(1.0, std::ilogb(side)) : 1.0;
    for (conf::RigidMotion m : conf::rigid_motions()) {
      for (double& t : m.translation) t *= unit;
      motions_.push_back(std::move(m));
    }
    for (const auto& v : deformed_.vertices) {
      const double d[3] = {v[0] - centroid[0], v[1] - centroid[1], v[2] - centroid[2]};
      radius_ = std::max(radius_, scaled_norm(d, 3));
    }
  }

  // Where an output is zero, the scale of the contract's consistency checks: c = sum_h k w_h for the energy
  // and the torque, c / L for the gradient (L the longest edge); 1 if that is zero too (k = 0).
  double energy_scale() const {
    const double e = std::fabs(certified_.rounded.energy);
    return e > 0 ? e : contract_c_ > 0 ? contract_c_ : 1.0;
  }
  double gradient_scale() const {
    return gradient_norm_ > 0 ? gradient_norm_ : contract_c_ > 0 ? contract_c_ / longest_edge_ : 1.0;
  }
  double energy_kappa() const {
    const double e = std::fabs(certified_.rounded.energy);
    return e > 0 ? energy_contributions_ / e : 1.0;
  }
  double gradient_kappa() const { return conf::gradient_kappa_sum(certified_); }

  // The hinges whose stencil holds both vertices, each as its edge (x1, x2).
  py::list hinges_with(Index a, Index b) const {
    py::list out;
    for (const Hinge& h : topology_.hinges)
      if (std::find(h.x.begin(), h.x.end(), a) != h.x.end() && std::find(h.x.begin(), h.x.end(), b) != h.x.end())
        out.append(py::make_tuple(h.x[1], h.x[2]));
    return out;
  }

  // Names the vertex whose 3-vector of `difference` (3n) is largest (a NaN the largest) as the pair (v, v).
  void locate_vertex(py::dict& d, const std::vector<double>& difference) const {
    Index worst = -1;
    double largest = -1;
    for (std::size_t v = 0; 3 * v < difference.size(); ++v) {
      const double norm = scaled_norm(difference.data() + 3 * v, 3);
      const double key = std::isnan(norm) ? infinity : norm;
      if (key > largest) largest = key, worst = static_cast<Index>(v);
    }
    if (worst < 0 || largest == 0) return;
    d["vertices"] = py::make_tuple(worst, worst);
    d["hinges"] = hinges_with(worst, worst);
  }

  // Names the vertex pair (i <= j) of the 3 x 3 block of `difference` (3n x 3n) with the largest Frobenius norm
  // (a NaN the largest).
  void locate_block(py::dict& d, const Sparse& difference) const {
    std::map<std::pair<Index, Index>, double> squares;
    for (Eigen::Index c = 0; c < difference.outerSize(); ++c)
      for (Sparse::InnerIterator it(difference, c); it; ++it) {
        const auto i = static_cast<Index>(it.row() / 3), j = static_cast<Index>(it.col() / 3);
        const double v = it.value();
        squares[{std::min(i, j), std::max(i, j)}] += std::isnan(v) ? infinity : v * v;
      }
    std::pair<Index, Index> worst{-1, -1};
    double largest = 0;
    for (const auto& [pair, sum] : squares)
      if (sum > largest) largest = sum, worst = pair;
    if (worst.first < 0) return;
    d["vertices"] = py::make_tuple(worst.first, worst.second);
    d["hinges"] = hinges_with(worst.first, worst.second);
  }

  static Eigen::Index strictly_upper_count(const Sparse& upper) {
    Eigen::Index count = 0;
    for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
      for (Sparse::InnerIterator it(upper, c); it; ++it) count += it.row() < it.col() && it.value() != 0;
    return count;
  }

  Mesh deformed_, rest_;
  Topology topology_;
  EnergyParameters parameters_;
  oracle::Options options_;
  oracle::CertifiedMesh certified_;
  Sparse certified_full_;
  std::vector<conf::RigidMotion> motions_;
  double energy_contributions_ = 0, contract_c_ = 0, rest_force_scale_ = 0, longest_edge_ = 0, radius_ = 0;
  double coordinates_norm_ = 0, gradient_norm_ = 0, hessian_norm_ = 0;
};

// The project's conformance meshes (conformance::meshes(), each rest flat), and each again with its rest and
// deformed shapes exchanged, so that curved rest shapes are graded: (name, vertices, faces, rest).
py::list conformance_meshes() {
  py::list out;
  auto add = [&out](const std::string& name, const Mesh& deformed, const Mesh& rest) {
    py::array_t<std::int64_t> faces({static_cast<py::ssize_t>(deformed.faces.size()), py::ssize_t{3}});
    for (std::size_t f = 0; f < deformed.faces.size(); ++f)
      for (std::size_t c = 0; c < 3; ++c) faces.mutable_data()[3 * f + c] = deformed.faces[f][c];
    out.append(py::make_tuple(name, as_array(flat(deformed)), faces, as_array(flat(rest))));
  };
  const std::vector<conf::MeshCase> meshes = conf::meshes();
  for (const conf::MeshCase& m : meshes) add(m.name, m.deformed, m.rest);
  for (const conf::MeshCase& m : meshes) {
    std::string name = m.name;
    name += "-curved-rest";
    add(name, m.rest, m.deformed);
  }
  return out;
}

}  // namespace

void bind_mesh_conformance(py::module_& m) {
  py::class_<MeshProblem>(m, "MeshProblem",
                          "A mesh with its certified bending energy, gradient and Hessian, grading a candidate's "
                          "(hinge.conform_mesh builds it)")
      .def(py::init<const Coordinates&, const Indices&, const Coordinates&, const std::string&, const py::object&,
                    double, const std::string&>(),
           "vertices"_a, "faces"_a, "rest"_a, "energy"_a, "weight"_a, "k"_a, "hessian"_a)
      .def_property_readonly("vertex_count", &MeshProblem::vertex_count)
      .def_property_readonly("hinge_count", &MeshProblem::hinge_count)
      .def_property_readonly("uncertified", &MeshProblem::uncertified)
      .def_property_readonly("zero_force_at_rest", &MeshProblem::zero_force_at_rest)
      .def("compare", &MeshProblem::compare, "energy"_a, "gradient"_a, "rows"_a, "cols"_a, "values"_a)
      .def("motions", &MeshProblem::motions)
      .def("check_motion", &MeshProblem::check_motion, "index"_a, "e0"_a, "g0"_a, "e1"_a, "g1"_a)
      .def("check_net_load", &MeshProblem::check_net_load, "gradient"_a)
      .def("check_at_rest", &MeshProblem::check_at_rest, "gradient"_a);
  m.def("mesh_conformance_meshes", &conformance_meshes);
}

}  // namespace hinge::python
