#include "mujoco_pair_state.hpp"

#include <algorithm>
#include <cmath>

#include "mujoco_frame.hpp"
#include "mujoco_sparse_jacobian.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::mujoco {

namespace {

// v = J qvel of a point of a body, m/s (MuJoCo frame); zero for the world.
// Sparse: the body's own DOFs, ascending (the dense sum's other terms are
// exact zeros: the same bits)
void point_velocity(const mjModel* m, const mjData* d, int body, const double p[3],
                    std::vector<double>& jac, Scratch& s, double v[3]) {
  v[0] = v[1] = v[2] = 0.0;
  if (body <= 0) return;
  if (s.sparse) {
    s.body_dofs.clear();
    append_body_dofs(m, body, s.body_dofs);
    const std::size_t w = s.body_dofs.size();
    point_jacobian(m, d, body, p, s.body_dofs, s.body_jac.data());
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t c = 0; c < w; ++c) {
        v[r] += s.body_jac[r * w + c] * d->qvel[s.body_dofs[c]];
      }
    }
    return;
  }
  mj_jac(m, d, jac.data(), nullptr, p, body);
  const auto nv = static_cast<std::size_t>(m->nv);
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t k = 0; k < nv; ++k) v[r] += jac[r * nv + k] * d->qvel[k];
  }
}

// the largest number of DOFs of one body (a free planar body: 3)
std::size_t most_body_dofs(const mjModel* m) {
  int most = 0;
  for (int b = 0; b < m->nbody; ++b) most = std::max(most, m->body_dofnum[b]);
  return static_cast<std::size_t>(most);
}

}  // namespace

Scratch::Scratch(const mjModel* m)
    : jac_a(static_cast<std::size_t>(3 * m->nv)),
      jac_b(static_cast<std::size_t>(3 * m->nv)),
      row(static_cast<std::size_t>(m->nv)),
      minv_row(static_cast<std::size_t>(m->nv)),
      sparse(bodies_hang_from_world(m)),
      pjac_a(6 * most_body_dofs(m)),
      pjac_b(6 * most_body_dofs(m)),
      body_jac(3 * most_body_dofs(m)) {
  dofs.reserve(2 * most_body_dofs(m));
  body_dofs.reserve(most_body_dofs(m));
}

double approach_speed_mps(const mjModel* m, const mjData* d, int body_a, int body_b,
                          const double p[3], const double n[3], Scratch& s) {
  double va[3];
  double vb[3];
  point_velocity(m, d, body_a, p, s.jac_a, s, va);
  point_velocity(m, d, body_b, p, s.jac_b, s, vb);
  return (va[0] - vb[0]) * n[0] + (va[1] - vb[1]) * n[1] + (va[2] - vb[2]) * n[2];
}

void normal_row(const mjModel* m, mjData* d, int body_a, int body_b, const double p[3],
                const double n[3], Scratch& s, double* row) {
  const int nv = m->nv;
  std::fill(s.jac_a.begin(), s.jac_a.end(), 0.0);
  std::fill(s.jac_b.begin(), s.jac_b.end(), 0.0);
  if (body_a > 0) mj_jac(m, d, s.jac_a.data(), nullptr, p, body_a);
  if (body_b > 0) mj_jac(m, d, s.jac_b.data(), nullptr, p, body_b);
  for (int k = 0; k < nv; ++k) {
    double r = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t at = i * static_cast<std::size_t>(nv) + static_cast<std::size_t>(k);
      r += n[i] * (s.jac_b[at] - s.jac_a[at]);
    }
    row[k] = r;
  }
}

void normal_row_on_dofs(const mjModel* m, const mjData* d, int body_a, int body_b,
                        const double p[3], const double n[3], Scratch& s, double* row) {
  const std::size_t w = s.dofs.size();
  std::fill(s.pjac_a.begin(), s.pjac_a.begin() + static_cast<std::ptrdiff_t>(3 * w), 0.0);
  std::fill(s.pjac_b.begin(), s.pjac_b.begin() + static_cast<std::ptrdiff_t>(3 * w), 0.0);
  if (body_a > 0) point_jacobian(m, d, body_a, p, s.dofs, s.pjac_a.data());
  if (body_b > 0) point_jacobian(m, d, body_b, p, s.dofs, s.pjac_b.data());
  // normal_row's sum, term by term
  for (std::size_t c = 0; c < w; ++c) {
    double r = 0.0;
    for (std::size_t i = 0; i < 3; ++i) r += n[i] * (s.pjac_b[i * w + c] - s.pjac_a[i * w + c]);
    row[c] = r;
  }
}

double effective_mass_kg(const mjModel* m, mjData* d, int body_a, int body_b, const double p[3],
                         const double n[3], Scratch& s) {
  const int nv = m->nv;
  normal_row(m, d, body_a, body_b, p, n, s, s.row.data());
  mj_solveM(m, d, s.minv_row.data(), s.row.data(), 1);
  double w = 0.0;  // inverse effective mass, 1/kg
  for (int k = 0; k < nv; ++k) {
    w += s.row[static_cast<std::size_t>(k)] * s.minv_row[static_cast<std::size_t>(k)];
  }
  return 1.0 / w;
}

void observe_pairs(const mjModel* m, const mjData* d, const ModelLayout& layout,
                   const ContactBuckets& buckets, bool with_force, Scratch& scratch,
                   std::vector<PairObservation>& out, std::span<const double> forces) {
  out.clear();
  for (std::size_t bucket = 0; bucket < buckets.pairs().size(); ++bucket) {
    const int k = buckets.pairs()[bucket];
    const auto list = buckets.contacts(bucket);
    PairObservation o;
    o.pair = k;
    for (const int i : list) {
      const mjContact& con = d->contact[i];
      // a contact fused into another (a vertex two pieces share) is not a contact
      if (con.exclude == 2) continue;
      ++o.contacts;
      if (con.dist < 0.0) ++o.pressed;
      if (with_force && con.efc_address >= 0) {
        mjtNum f[6];
        if (forces.empty()) {
          mj_contactForce(m, d, i, f);
        } else {
          for (std::size_t j = 0; j < 6; ++j) f[j] = forces[6 * static_cast<std::size_t>(i) + j];
        }
        o.force_n += f[0];  // contact frame: f[0] is the normal force, >= 0
        // the force on geom2 (the frame's rows: normal from geom1 to geom2,
        // then the two tangents), onto the case's body_b
        double world[3];
        for (int j = 0; j < 3; ++j) {
          world[j] = f[0] * con.frame[j] + f[1] * con.frame[3 + j] + f[2] * con.frame[6 + j];
        }
        const double on_b = layout.on_body_a(con.geom1, k) ? 1.0 : -1.0;
        o.force_on_b_n += on_b * from_mj(world);
      }
      if (o.reported && -con.dist <= o.penetration_m) continue;
      o.reported = true;
      o.deepest = i;
      o.penetration_m = -con.dist;
    }
    if (o.reported) {
      const PairLayout& p = layout.pairs[static_cast<std::size_t>(k)];
      const mjContact& con = d->contact[o.deepest];
      // frame[0..2] is the normal from geom1 to geom2; the case wants a -> b.
      // The out-of-plane component (MPR noise, ~1e-8) is dropped.
      const double sign = layout.on_body_a(con.geom1, k) ? 1.0 : -1.0;
      Vec2 n = sign * from_mj(con.frame);
      n.normalize();
      o.normal_ab = n;
      if (with_force) o.tangential_force_n = o.force_on_b_n.dot(pb::contact_tangent(n));
      o.point_m = from_mj(con.pos);
      if (o.pressed > 1) {
        // SPEC §1, one force per pair: several contacts pressed in act at their
        // depth-weighted centroid
        double w = 0.0;              // m
        Vec2 moment = Vec2::Zero();  // m^2
        for (const int i : list) {
          const mjContact& c = d->contact[i];
          if (c.dist >= 0.0 || c.exclude == 2) continue;
          w -= c.dist;
          moment -= c.dist * from_mj(c.pos);
        }
        if (w > 0.0) o.point_m = moment / w;
      }
      const auto n3 = to_mj(n);
      const auto p3 = to_mj(o.point_m);
      o.approach_speed_mps =
          approach_speed_mps(m, d, p.mj_body_a, p.mj_body_b, p3.data(), n3.data(), scratch);
    }
    out.push_back(o);
  }
}

void observe_pairs(const mjModel* m, const mjData* d, const ModelLayout& layout, bool with_force,
                   Scratch& scratch, std::vector<PairObservation>& out,
                   std::span<const double> forces) {
  scratch.buckets.build(d, layout);
  observe_pairs(m, d, layout, scratch.buckets, with_force, scratch, scratch.touched, forces);
  out.assign(layout.pairs.size(), PairObservation{});
  for (const PairObservation& o : scratch.touched) out[static_cast<std::size_t>(o.pair)] = o;
}

}  // namespace pb::internal::mujoco
