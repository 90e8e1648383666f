#include "planarbench/contact_set_mass.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pb {

namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// adds one body's J M^-1 J^T to A; `sign` is -1 for body a (its normal is -n)
void add_body(const PlanarInertia& body, std::span<const Vec2> points,
              std::span<const Vec2> normals, ContactSetMatrix& a) {
  if (body.fixed) return;
  const auto n = static_cast<Eigen::Index>(points.size());
  const Vec2 origin = body.pinned ? body.pivot_m : body.centre_m;
  const double rot_inertia =  // kg m^2, about the centre, or about the pivot (parallel axes)
      body.pinned ? body.inertia_kgm2 + body.mass_kg * (body.centre_m - body.pivot_m).squaredNorm()
                  : body.inertia_kgm2;
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    const double li = cross(points[ui] - origin, normals[ui]);  // m
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto uj = static_cast<std::size_t>(j);
      const double lj = cross(points[uj] - origin, normals[uj]);
      double v = li * lj / rot_inertia;
      if (!body.pinned) v += normals[ui].dot(normals[uj]) / body.mass_kg;
      a(i, j) += v;
    }
  }
}

}  // namespace

ContactSetMatrix contact_inverse_mass(const PlanarInertia& a, const PlanarInertia& b,
                                      std::span<const Vec2> points_m,
                                      std::span<const Vec2> normals) {
  if (points_m.size() != normals.size() ||
      points_m.size() > static_cast<std::size_t>(kMaxContactSetPoints)) {
    throw std::invalid_argument("contact_inverse_mass: points and normals differ or exceed " +
                                std::to_string(kMaxContactSetPoints));
  }
  const auto n = static_cast<Eigen::Index>(points_m.size());
  ContactSetMatrix m = ContactSetMatrix::Zero(n, n);
  // a's points move against the normal: (-n_i).(-n_j) = n_i.n_j, the same terms
  add_body(a, points_m, normals, m);
  add_body(b, points_m, normals, m);
  return m;
}

double point_effective_mass_kg(const PlanarInertia& a, const PlanarInertia& b,
                               const Vec2& point_m, const Vec2& normal) {
  const ContactSetMatrix m = contact_inverse_mass(a, b, std::span<const Vec2>(&point_m, 1),
                                                  std::span<const Vec2>(&normal, 1));
  return m(0, 0) > 0.0 ? 1.0 / m(0, 0) : std::numeric_limits<double>::infinity();
}

ContactSetScale contact_set_scale(const ContactSetMatrix& inverse_mass,
                                  std::span<const double> depths_m) {
  ContactSetScale out;
  const auto n = inverse_mass.rows();
  if (n == 0 || static_cast<std::size_t>(n) != depths_m.size()) return out;
  // w = A^+ 1, the least-norm forces that accelerate every point alike; for
  // one point A^+ = 1 / a (0 for a = 0), what the decomposition gives, without it
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxContactSetPoints, 1>;
  Vector w(n);
  if (n == 1) {
    const double a = inverse_mass(0, 0);
    w[0] = a != 0.0 ? 1.0 / a : 0.0;
  } else {
    const Eigen::CompleteOrthogonalDecomposition<ContactSetMatrix> cod(inverse_mass);
    w = cod.solve(Vector::Ones(n));
  }
  out.mass_kg = w.sum();
  double wr = 0.0;      // N s^2, w^T r
  double deepest = 0.0;  // m
  for (Eigen::Index i = 0; i < n; ++i) {
    wr += w[i] * depths_m[static_cast<std::size_t>(i)];
    deepest = std::max(deepest, depths_m[static_cast<std::size_t>(i)]);
  }
  if (!(out.mass_kg > 0.0) || !std::isfinite(out.mass_kg)) return out;
  out.weighted_depth_m = wr / out.mass_kg;
  if (out.weighted_depth_m > 0.0) out.scale = deepest / out.weighted_depth_m;
  return out;
}

}  // namespace pb
