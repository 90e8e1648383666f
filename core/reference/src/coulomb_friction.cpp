#include "planarbench/reference/coulomb_friction.hpp"

#include <cstddef>

namespace pb {

StickSolve::StickSolve(int coordinates, int max_rows)
    : g_(Eigen::VectorXd::Zero(coordinates)),
      jt_(Eigen::MatrixXd::Zero(coordinates, max_rows)),
      a_(Eigen::MatrixXd::Identity(max_rows, max_rows)),
      rhs_(Eigen::VectorXd::Zero(max_rows)),
      f_(Eigen::VectorXd::Zero(max_rows)),
      ldlt_(max_rows) {}

void StickSolve::jacobian_transpose(const PlanarModel& model, const Eigen::VectorXd& q,
                                    const StickRow& row, Eigen::VectorXd& g) {
  g.setZero(model.coordinates());
  model.add_point_force(row.body_b, q, row.point_b_m, row.tangent, g);
  model.add_point_force(row.body_a, q, row.point_a_m, -row.tangent, g);
}

void StickSolve::solve(const PlanarModel& model, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot_free,
                       const std::vector<StickRow>& rows, std::vector<double>& force_n) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  force_n.resize(rows.size());
  if (n == 0) return;
  const Eigen::VectorXd& mass_diag = model.mass_diagonal();
  for (Eigen::Index j = 0; j < n; ++j) {
    const StickRow& r = rows[static_cast<std::size_t>(j)];
    jacobian_transpose(model, q, r, g_);
    jt_.col(j) = g_;
    // the relative tangential acceleration without the stick forces:
    // J u_dot_free plus the points' centripetal parts
    const Vec2 c = model.point_centripetal_acceleration(r.body_b, q, u, r.point_b_m) -
                   model.point_centripetal_acceleration(r.body_a, q, u, r.point_a_m);
    rhs_[j] = -(g_.dot(u_dot_free) + r.tangent.dot(c) + kStickRate_per_s * r.slip_rate_mps);
  }
  if (n == 1) {
    // one sticking pair: f = -(a + beta v) / (J M^-1 J^T)
    const double a = jt_.col(0).cwiseQuotient(mass_diag).dot(jt_.col(0));
    force_n[0] = rhs_[0] / a;
    return;
  }
  // A = J M^-1 J^T over the rows; identity past them so that the
  // factorisation keeps its size (no allocation)
  a_.setIdentity();
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index k = 0; k <= j; ++k) {
      const double v = jt_.col(j).cwiseQuotient(mass_diag).dot(jt_.col(k));
      a_(j, k) = v;
      a_(k, j) = v;
    }
  }
  for (Eigen::Index j = n; j < rhs_.size(); ++j) rhs_[j] = 0.0;
  ldlt_.compute(a_);
  f_ = ldlt_.solve(rhs_);
  for (Eigen::Index j = 0; j < n; ++j) force_n[static_cast<std::size_t>(j)] = f_[j];
}

}  // namespace pb
