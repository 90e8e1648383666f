// The stick solve of StickSolve (coulomb_friction.hpp) for scenes: the same
// forces, A f = rhs with A = J M^-1 J^T over the sticking rows, assembled and
// factorised sparsely. A row couples only to the rows that share one of its
// two bodies, so a pyramid's thousands of stuck rows make a sparse A
// (a few entries a row) where the dense solve would hold rows^2 entries and
// factorise them in rows^3 / 3 operations at every derivative. Eigen's
// SimplicialLDLT with its approximate minimum degree ordering; the symbolic
// analysis is kept while the rows' bodies stay the same. Deterministic: the
// same rows give the same operations in the same order.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <utility>
#include <vector>

#include "planarbench/reference/coulomb_friction.hpp"
#include "planarbench/reference/planar_model.hpp"

namespace pb {

class SparseStickSolve {
 public:
  // the tangential force (N, on b along t) of each row given u_dot_free
  void solve(const PlanarModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& u,
             const Eigen::VectorXd& u_dot_free, const std::vector<StickRow>& rows,
             std::vector<double>& force_n);

 private:
  struct Entry {
    int coord = -1;
    double value = 0.0;
  };
  // J of each row: at most 3 coordinates of each of its two bodies
  std::vector<std::array<Entry, 6>> jacobian_;
  std::vector<int> entries_;  // per row, how many of its 6 are used
  std::vector<std::vector<std::pair<int, double>>> rows_of_coord_;  // (row, J value) per coordinate
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> a_;
  Eigen::VectorXd rhs_, f_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  std::vector<std::pair<int, int>> pattern_;  // the rows' bodies at the last analysis
};

}  // namespace pb
