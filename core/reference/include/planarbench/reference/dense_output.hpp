// Continuous output of one accepted step, for output times between steps,
// for event location and for the peaks of an episode.
//   dopri5: the 4th-order continuous extension of Dormand-Prince 5(4)
//           (Shampine 1986; Hairer, Norsett, Wanner, Solving ODEs I, 2nd ed.,
//           §II.6, the CONTD5 form of dopri5.f):
//           y(t0 + th h) = c0 + th (c1 + (1-th) (c2 + th (c3 + (1-th) c4)))
//   hermite: cubic Hermite interpolation of y and f = y' at both ends, order 4
//           in h (used with classic RK4).
#pragma once

#include <Eigen/Core>

namespace pb {

struct DenseSegment {
  enum class Kind { dopri5, hermite };
  Kind kind = Kind::hermite;
  double t0_s = 0.0;  // s, start of the step
  double h_s = 0.0;   // s, its length
  // dopri5: c0..c4 as above; hermite: c0 = y0, c1 = y1, c2 = f0, c3 = f1
  Eigen::VectorXd c0, c1, c2, c3, c4;

  [[nodiscard]] double t1_s() const { return t0_s + h_s; }
  // y at time t_s in [t0, t0 + h]; no allocation once y is sized
  void evaluate(double t_s, Eigen::VectorXd& y) const;
  // Hermite form from the ends of a step
  void set_hermite(double t0_s, double h_s, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                   const Eigen::VectorXd& f0, const Eigen::VectorXd& f1);
};

}  // namespace pb
