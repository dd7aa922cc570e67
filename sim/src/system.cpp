// The structure of Newton's linear systems (hinge/sim/system.hpp).
#include "hinge/sim/system.hpp"

#include <algorithm>
#include <stdexcept>

namespace hinge::sim {

Sparsity::Sparsity(const Topology& topology, Couplings couplings) {
  const Eigen::Index n = static_cast<Eigen::Index>(topology.vertex_count);
  if (!couplings.vertex_blocks && !couplings.faces && !couplings.hinges) {  // a diagonal matrix
    structure_.resize(3 * n, 3 * n);
    structure_.reserve(Eigen::VectorXi::Ones(3 * n));
    for (Eigen::Index d = 0; d < 3 * n; ++d) structure_.insert(d, d) = 0.0;
    structure_.makeCompressed();
    return;
  }
  std::vector<std::pair<Index, Index>> pairs;  // vertex pairs u <= v
  pairs.reserve(n + 6 * topology.faces.size() + topology.hinges.size());
  for (Index v = 0; v < n; ++v) pairs.emplace_back(v, v);
  if (couplings.faces)
    for (const auto& f : topology.faces)
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) pairs.emplace_back(std::min(f[i], f[j]), std::max(f[i], f[j]));
  if (couplings.hinges)
    for (const auto& h : topology.hinges) pairs.emplace_back(std::min(h.x[0], h.x[3]), std::max(h.x[0], h.x[3]));
  std::sort(pairs.begin(), pairs.end(),
            [](auto a, auto b) { return std::pair(a.second, a.first) < std::pair(b.second, b.first); });
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  // Per column c = 3 v + cv, the rows 3 u + cu of every pair (u, v) with u <= v, row <= col.
  std::vector<std::vector<Index>> below(static_cast<std::size_t>(n));  // vertices u <= v paired with v
  for (auto [u, v] : pairs) below[static_cast<std::size_t>(v)].push_back(u);
  structure_.resize(3 * n, 3 * n);
  std::vector<Eigen::Index> counts(static_cast<std::size_t>(3 * n));
  for (Index v = 0; v < n; ++v)
    for (int cv = 0; cv < 3; ++cv) {
      Eigen::Index count = 0;
      for (Index u : below[static_cast<std::size_t>(v)]) count += (u == v) ? cv + 1 : 3;
      counts[static_cast<std::size_t>(3 * v + cv)] = count;
    }
  structure_.reserve(counts);
  for (Index v = 0; v < n; ++v)
    for (int cv = 0; cv < 3; ++cv)
      for (Index u : below[static_cast<std::size_t>(v)])  // sorted ascending: rows come in order
        for (int cu = 0; cu < (u == v ? cv + 1 : 3); ++cu) structure_.insert(3 * u + cu, 3 * v + cv) = 0.0;
  structure_.makeCompressed();
}

Slot Sparsity::slot(Eigen::Index row, Eigen::Index col) const {
  const auto* outer = structure_.outerIndexPtr();
  const auto* inner = structure_.innerIndexPtr();
  const auto* first = inner + outer[col];
  const auto* last = inner + outer[col + 1];
  const auto* it = std::lower_bound(first, last, static_cast<int>(row));
  return (it != last && *it == row) ? static_cast<Slot>(it - inner) : -1;
}

std::vector<Slot> Sparsity::element_slots(std::span<const Index> vertices) const {
  const std::size_t m = 3 * vertices.size();
  std::vector<Slot> slots(m * m, -1);
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t i = 0; i < m; ++i) {
      const Eigen::Index row = 3 * Eigen::Index{vertices[i / 3]} + static_cast<Eigen::Index>(i % 3);
      const Eigen::Index col = 3 * Eigen::Index{vertices[j / 3]} + static_cast<Eigen::Index>(j % 3);
      if (row > col) continue;
      // An element visiting a vertex twice would add its entries twice to the diagonal block; none does.
      const Slot s = slot(row, col);
      if (s < 0) throw std::logic_error("sim::Sparsity: an element's entry is outside the structure");
      slots[i + m * j] = s;
    }
  return slots;
}

void scatter(std::span<const double> local, std::span<const Slot> slots, std::span<double> values) {
  for (std::size_t k = 0; k < slots.size(); ++k)
    if (slots[k] >= 0) values[static_cast<std::size_t>(slots[k])] += local[k];
}

Reduction::Reduction(const Sparsity& sparsity, std::span<const Index> pinned_vertices) {
  const Eigen::Index size = sparsity.size();
  index_.assign(static_cast<std::size_t>(size), 0);
  for (Index v : pinned_vertices)
    for (int c = 0; c < 3; ++c) index_[static_cast<std::size_t>(3 * v + c)] = -1;
  for (Eigen::Index d = 0; d < size; ++d)
    if (index_[static_cast<std::size_t>(d)] >= 0) {
      index_[static_cast<std::size_t>(d)] = static_cast<Eigen::Index>(free_.size());
      free_.push_back(d);
    }
  const auto& s = sparsity.structure();
  identity_ = pinned_vertices.empty();
  if (identity_) {
    reduced_ = s;
    return;
  }
  target_.assign(static_cast<std::size_t>(s.nonZeros()), -1);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index col = 0; col < size; ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(s, col); it; ++it)
      if (is_free(it.row()) && is_free(col))
        entries.emplace_back(index_[static_cast<std::size_t>(it.row())], index_[static_cast<std::size_t>(col)], 0.0);
  const Eigen::Index m = free_count();
  reduced_.resize(m, m);
  reduced_.setFromTriplets(entries.begin(), entries.end());
  reduced_.makeCompressed();
  // Slots in the reduced matrix: column by column the order is kept, so walk both.
  for (Eigen::Index col = 0; col < size; ++col) {
    if (!is_free(col)) continue;
    const Eigen::Index rcol = index_[static_cast<std::size_t>(col)];
    Eigen::Index k = reduced_.outerIndexPtr()[rcol];
    for (Eigen::Index p = s.outerIndexPtr()[col]; p < s.outerIndexPtr()[col + 1]; ++p)
      if (is_free(s.innerIndexPtr()[p])) target_[static_cast<std::size_t>(p)] = k++;
  }
}

void Reduction::reduce_matrix(std::span<const double> values) {
  double* out = reduced_.valuePtr();
  if (identity_) {
    std::copy(values.begin(), values.end(), out);
    return;
  }
  for (std::size_t p = 0; p < target_.size(); ++p)
    if (target_[p] >= 0) out[target_[p]] = values[p];
}

void Reduction::reduce_vector(const Eigen::VectorXd& full, Eigen::VectorXd& free) const {
  if (identity_) {
    free = full;
    return;
  }
  free.resize(free_count());
  for (Eigen::Index i = 0; i < free_count(); ++i) free[i] = full[free_[static_cast<std::size_t>(i)]];
}

void Reduction::expand_vector(const Eigen::VectorXd& free, Eigen::VectorXd& full) const {
  if (identity_) {
    full = free;
    return;
  }
  full.setZero(static_cast<Eigen::Index>(index_.size()));
  for (Eigen::Index i = 0; i < free_count(); ++i) full[free_[static_cast<std::size_t>(i)]] = free[i];
}

}  // namespace hinge::sim
