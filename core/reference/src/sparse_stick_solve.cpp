#include "planarbench/reference/sparse_stick_solve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <tuple>

#include "planarbench/errors.hpp"

namespace pb {

void SparseStickSolve::solve(const PlanarModel& model, const Eigen::VectorXd& q,
                             const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot_free,
                             const std::vector<StickRow>& rows, std::vector<double>& force_n) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  force_n.resize(rows.size());
  if (n == 0) return;
  const Eigen::VectorXd& mass_diag = model.mass_diagonal();
  jacobian_.resize(rows.size());
  entries_.resize(rows.size());
  rhs_.resize(n);
  rows_of_coord_.resize(static_cast<std::size_t>(model.coordinates()));
  for (auto& r : rows_of_coord_) r.clear();
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto ju = static_cast<std::size_t>(j);
    const StickRow& r = rows[ju];
    // J^T of the row: t on b at p_b, -t on a at p_a (StickSolve::jacobian_transpose)
    int m = 0;
    for (const auto& [body, point, sign] :
         {std::tuple{r.body_b, r.point_b_m, 1.0}, std::tuple{r.body_a, r.point_a_m, -1.0}}) {
      int idx[3];
      double val[3];
      const int count = model.point_force_entries(body, q, point, sign * r.tangent, idx, val);
      for (int e = 0; e < count; ++e) jacobian_[ju][static_cast<std::size_t>(m++)] = Entry{idx[e], val[e]};
    }
    entries_[ju] = m;
    double ju_dot = 0.0;
    for (int e = 0; e < m; ++e) {
      const Entry& en = jacobian_[ju][static_cast<std::size_t>(e)];
      ju_dot += en.value * u_dot_free[en.coord];
      rows_of_coord_[static_cast<std::size_t>(en.coord)].emplace_back(static_cast<int>(j), en.value);
    }
    const Vec2 c = model.point_centripetal_acceleration(r.body_b, q, u, r.point_b_m) -
                   model.point_centripetal_acceleration(r.body_a, q, u, r.point_a_m);
    rhs_[j] = -(ju_dot + r.tangent.dot(c) + kStickRate_per_s * r.slip_rate_mps);
  }
  // A_jk = sum over shared coordinates c of J_jc J_kc / M_c (lower triangle
  // and diagonal; the rows through a coordinate are few)
  triplets_.clear();
  for (std::size_t c = 0; c < rows_of_coord_.size(); ++c) {
    const auto& through = rows_of_coord_[c];
    const double inv_mass = 1.0 / mass_diag[static_cast<Eigen::Index>(c)];
    for (std::size_t x = 0; x < through.size(); ++x) {
      for (std::size_t y = 0; y <= x; ++y) {
        const auto& [j, vj] = through[x];
        const auto& [k, vk] = through[y];
        triplets_.emplace_back(std::max(j, k), std::min(j, k), vj * vk * inv_mass);
      }
    }
  }
  a_.resize(n, n);
  // duplicates (rows sharing several coordinates) are summed, in triplet order
  a_.setFromTriplets(triplets_.begin(), triplets_.end());
  // the symbolic analysis depends on which rows couple: the rows' bodies
  bool same = pattern_.size() == rows.size();
  for (std::size_t j = 0; same && j < rows.size(); ++j) {
    same = pattern_[j] == std::pair{rows[j].body_a, rows[j].body_b};
  }
  if (!same) {
    pattern_.resize(rows.size());
    for (std::size_t j = 0; j < rows.size(); ++j) pattern_[j] = {rows[j].body_a, rows[j].body_b};
    ldlt_.analyzePattern(a_.selfadjointView<Eigen::Lower>());
  }
  ldlt_.factorize(a_.selfadjointView<Eigen::Lower>());
  if (ldlt_.info() != Eigen::Success) {
    throw EngineError(fmt::format("reference: the stick solve of {} sticking pairs is singular", n));
  }
  f_ = ldlt_.solve(rhs_);
  for (Eigen::Index j = 0; j < n; ++j) force_n[static_cast<std::size_t>(j)] = f_[j];
}

}  // namespace pb
