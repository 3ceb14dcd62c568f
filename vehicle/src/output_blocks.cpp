#include "output_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace ferro::vehicle::detail {
namespace {

std::shared_ptr<OutputBlocks> partition(std::vector<char> is_output) {
  auto b = std::make_shared<OutputBlocks>();
  b->slot.resize(is_output.size());
  for (std::size_t i = 0; i < is_output.size(); ++i) {
    auto& list = is_output[i] != 0 ? b->output : b->dynamic;
    b->slot[i] = static_cast<Eigen::Index>(list.size());
    list.push_back(static_cast<Eigen::Index>(i));
  }
  b->is_output = std::move(is_output);
  return b;
}

std::size_t at(Eigen::Index i) { return static_cast<std::size_t>(i); }

/// A's non-zeros in dynamic slots: the pattern's dynamic rows of each dynamic column, and the
/// diagonal.
void set_dynamic_pattern(OutputBlocks& b, const std::vector<std::vector<int>>& pattern) {
  b.dynamic_pattern.assign(b.dynamic.size(), {});
  for (std::size_t c = 0; c < b.dynamic.size(); ++c) {
    auto& rows = b.dynamic_pattern[c];
    rows.push_back(static_cast<Eigen::Index>(c));
    for (const int i : pattern[at(b.dynamic[c])]) {
      if (b.is_output[static_cast<std::size_t>(i)] == 0) rows.push_back(b.slot[static_cast<std::size_t>(i)]);
    }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  }
}

}  // namespace

bool pivots_ok(const Eigen::PartialPivLU<Eigen::MatrixXd>& lu) {
  if (lu.rows() == 0) return true;
  const double min_pivot = lu.matrixLU().diagonal().cwiseAbs().minCoeff();
  return min_pivot > 0.0 && std::isfinite(min_pivot);
}

std::shared_ptr<const OutputBlocks> OutputBlocks::make(
    const OdeSystem& system, const std::vector<std::vector<int>>& pattern, bool sparse) {
  const auto outputs = system.output_states();
  if (outputs.empty()) return nullptr;
  std::vector<char> is_output(system.size(), 0);
  for (const std::size_t i : outputs) is_output.at(i) = 1;
  // Block-triangular only if no output column reaches a row of the other states.
  if (pattern.size() == system.size()) {
    for (const std::size_t j : outputs) {
      for (const int i : pattern[j]) {
        if (is_output[static_cast<std::size_t>(i)] == 0) return nullptr;
      }
    }
  }
  auto b = partition(std::move(is_output));
  if (sparse && pattern.size() == system.size()) set_dynamic_pattern(*b, pattern);
  return b;
}

std::shared_ptr<const OutputBlocks> OutputBlocks::all_dynamic(
    std::size_t n, const std::vector<std::vector<int>>& pattern) {
  auto b = partition(std::vector<char>(n, 0));
  if (pattern.size() == n) set_dynamic_pattern(*b, pattern);
  return b;
}

OutputBlockMatrix::OutputBlockMatrix(std::shared_ptr<const OutputBlocks> b) : blocks(std::move(b)) {
  const auto nd = static_cast<Eigen::Index>(blocks->dynamic.size());
  a = Eigen::MatrixXd::Zero(nd, nd);
}

void OutputBlockMatrix::set_zero() {
  a.setZero();
  c.clear();
  d.clear();
}

void OutputBlockMatrix::set(std::size_t i, std::size_t j, double value) {
  const OutputBlocks& b = *blocks;
  const Eigen::Index row = b.slot[i], col = b.slot[j];
  if (b.is_output[j] != 0) {
    if (b.is_output[i] != 0) d.push_back({row, col, value});
  } else if (b.is_output[i] == 0) {
    a(row, col) = value;
  } else {
    c.push_back({row, col, value});
  }
}

void OutputBlockMatrix::order_by_column() {
  std::stable_sort(c.begin(), c.end(),
                   [](const BlockEntry& x, const BlockEntry& y) { return x.col < y.col; });
}

void OutputBlockMatrix::scale_add_identity(double g) {
  a *= g;
  a.diagonal().array() += 1.0;
  for (auto& e : c) e.value *= g;
  for (auto& e : d) e.value = g * e.value + (e.row == e.col ? 1.0 : 0.0);
}

bool OutputBlockLu::compute(const OutputBlockMatrix& m) {
  const auto& pattern = m.blocks->dynamic_pattern;
  if (pattern.empty()) {
    dynamic_.compute(m.a);
    if (!pivots_ok(dynamic_)) return false;
  } else {
    const auto nd = static_cast<Eigen::Index>(pattern.size());
    if (sparse_ == nullptr) {
      std::vector<Eigen::Triplet<double, int>> entries;
      for (Eigen::Index c = 0; c < nd; ++c) {
        for (const Eigen::Index r : pattern[at(c)])
          entries.emplace_back(static_cast<int>(r), static_cast<int>(c), 1.0);
      }
      sparse_matrix_.resize(nd, nd);
      sparse_matrix_.setFromTriplets(entries.begin(), entries.end());
      sparse_matrix_.makeCompressed();
      sparse_ = std::make_unique<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>();
    }
    // The values of A at its non-zeros (compressed storage: rows increasing per column).
    double* values = sparse_matrix_.valuePtr();
    const int* inner = sparse_matrix_.innerIndexPtr();
    const int* outer = sparse_matrix_.outerIndexPtr();
    for (Eigen::Index c = 0; c < nd; ++c) {
      for (int k = outer[c]; k < outer[c + 1]; ++k) values[k] = m.a(inner[k], c);
    }
    if (!sparse_analysed_) {
      sparse_->analyzePattern(sparse_matrix_);
      sparse_analysed_ = true;
    }
    sparse_->factorize(sparse_matrix_);
    sparse_ok_ = sparse_->info() == Eigen::Success;
    if (!sparse_ok_) return false;
  }
  // The groups of output slots D's entries connect (union-find), in slot order.
  const std::size_t no = m.blocks->output.size();
  std::vector<Eigen::Index> parent(no);
  for (std::size_t i = 0; i < no; ++i) parent[i] = static_cast<Eigen::Index>(i);
  const auto root = [&](Eigen::Index i) {
    while (parent[at(i)] != i) i = parent[at(i)];
    return i;
  };
  for (const auto& e : m.d) parent[at(root(e.row))] = root(e.col);
  std::vector<Eigen::Index> group_of(no, -1), index_in(no, 0);
  groups_.clear();
  for (std::size_t i = 0; i < no; ++i) {
    const Eigen::Index r = root(static_cast<Eigen::Index>(i));
    if (group_of[at(r)] < 0) {
      group_of[at(r)] = static_cast<Eigen::Index>(groups_.size());
      groups_.emplace_back();
    }
    auto& g = groups_[at(group_of[at(r)])];
    index_in[i] = static_cast<Eigen::Index>(g.slots.size());
    g.slots.push_back(static_cast<Eigen::Index>(i));
  }
  std::vector<Eigen::MatrixXd> blocks;
  for (const auto& g : groups_) {
    const auto k = static_cast<Eigen::Index>(g.slots.size());
    blocks.emplace_back(Eigen::MatrixXd::Zero(k, k));
  }
  for (const auto& e : m.d) {
    blocks[at(group_of[at(root(e.row))])](index_in[at(e.row)], index_in[at(e.col)]) += e.value;
  }
  for (std::size_t gi = 0; gi < groups_.size(); ++gi) {
    groups_[gi].lu.compute(blocks[gi]);
    if (!pivots_ok(groups_[gi].lu)) return false;
  }
  return true;
}

void OutputBlockLu::solve(const OutputBlockMatrix& m, const double* b, double* x) const {
  solve_dynamic(m, b, x);
  solve_outputs(m, b, x);
}

void OutputBlockLu::solve_dynamic(const OutputBlockMatrix& m, const double* b, double* x) const {
  const OutputBlocks& st = *m.blocks;
  bd_.resize(static_cast<Eigen::Index>(st.dynamic.size()));
  for (std::size_t i = 0; i < st.dynamic.size(); ++i) bd_[static_cast<Eigen::Index>(i)] = b[st.dynamic[i]];
  if (st.dynamic_pattern.empty()) {
    xd_.noalias() = dynamic_.solve(bd_);
  } else if (sparse_ok_) {
    xd_ = sparse_->solve(bd_);
  } else {  // a singular matrix: a non-finite solution
    xd_.setConstant(bd_.size(), std::numeric_limits<double>::quiet_NaN());
  }
  for (std::size_t i = 0; i < st.dynamic.size(); ++i) x[st.dynamic[i]] = xd_[static_cast<Eigen::Index>(i)];
}

void OutputBlockLu::solve_outputs(const OutputBlockMatrix& m, const double* b, double* x) const {
  const OutputBlocks& st = *m.blocks;
  if (st.output.empty()) return;
  // b_o - C x_d, the entries subtracted one by one in their order (columns increasing).
  bo_.resize(static_cast<Eigen::Index>(st.output.size()));
  for (std::size_t i = 0; i < st.output.size(); ++i) bo_[static_cast<Eigen::Index>(i)] = b[st.output[i]];
  for (const auto& e : m.c) bo_[e.row] -= e.value * xd_[e.col];
  for (const auto& g : groups_) {
    bg_.resize(static_cast<Eigen::Index>(g.slots.size()));
    for (std::size_t i = 0; i < g.slots.size(); ++i) bg_[static_cast<Eigen::Index>(i)] = bo_[g.slots[i]];
    xg_.noalias() = g.lu.solve(bg_);
    for (std::size_t i = 0; i < g.slots.size(); ++i) x[st.output[at(g.slots[i])]] = xg_[static_cast<Eigen::Index>(i)];
  }
}

}  // namespace ferro::vehicle::detail
