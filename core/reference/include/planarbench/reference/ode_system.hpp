// A first-order ODE y' = f(y) as the integrators see it (autonomous: the
// cases have no time-dependent forcing).
#pragma once

#include <Eigen/Core>

namespace pb {

class OdeSystem {
 public:
  OdeSystem() = default;
  virtual ~OdeSystem() = default;
  OdeSystem(const OdeSystem&) = delete;
  OdeSystem& operator=(const OdeSystem&) = delete;

  // dy = f(y); dy has the size of y. Must not allocate once dy is sized.
  virtual void derivative(const Eigen::VectorXd& y, Eigen::VectorXd& dy) = 0;
};

}  // namespace pb
