// What a case contact pair looks like in MuJoCo's current data: the deepest
// of its contacts (distance, normal, point), the approach speed there and
// MuJoCo's normal force; and the effective mass along a contact normal.
#pragma once

#include <limits>

#include <mujoco/mujoco.h>

#include <span>
#include <vector>

#include "mujoco_contact_buckets.hpp"
#include "mujoco_model.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

struct PairObservation {
  int pair = -1;                    // the run's pair index (ModelLayout::pairs)
  bool reported = false;            // MuJoCo's collider gave at least one contact
  int deepest = -1;                 // index of the deepest contact in mjData::contact
  double penetration_m = 0.0;       // m, -dist of the deepest contact (< 0: apart, within margin)
  Vec2 normal_ab = Vec2::Zero();    // unit, case frame, from body_a to body_b (deepest contact)
  // m, case frame: MuJoCo's contact position (the midpoint between the
  // geoms); with several contacts pressed in, their depth-weighted centroid
  Vec2 point_m = Vec2::Zero();
  double approach_speed_mps = 0.0;  // m/s, (v_a - v_b) . n_ab at the point, > 0 approaching
  double force_n = 0.0;  // N, MuJoCo's normal force summed over the pair's active contacts
  // N, the whole contact force on body_b summed over them (case frame), and
  // its part along t = n rotated by +90 deg (NaN without forces); issue 32
  Vec2 force_on_b_n = Vec2::Zero();
  double tangential_force_n = std::numeric_limits<double>::quiet_NaN();
  int contacts = 0;      // contacts MuJoCo reported for the pair
  int pressed = 0;       // of them, with dist < 0 (in the constraint)
};

// buffers sized for one model, allocated once (the sampling loop allocates nothing)
struct Scratch {
  explicit Scratch(const mjModel* m);
  std::vector<double> jac_a;     // 3 x nv, translational Jacobian of body a's point
  std::vector<double> jac_b;     // 3 x nv
  std::vector<double> row;       // nv, normal Jacobian n^T (J_b - J_a)
  std::vector<double> minv_row;  // nv, M^-1 row^T
  // rows on the pair's DOFs only (mujoco_sparse_jacobian.hpp), when every
  // moving body hangs from the world body (the models this adapter writes)
  bool sparse = false;
  std::vector<int> dofs;         // the DOFs of the two bodies, ascending
  std::vector<double> pjac_a;    // 3 x dofs
  std::vector<double> pjac_b;    // 3 x dofs
  std::vector<int> body_dofs;    // one body's DOFs (point velocities)
  std::vector<double> body_jac;  // 3 x body_dofs
  // the dense observe_pairs' buckets and compact observations
  ContactBuckets buckets;
  std::vector<PairObservation> touched;
};

// Reads d->contact (valid after mj_collision at the current qpos) and d->qvel:
// one observation per pair with contacts, in buckets.pairs() order (built on
// d). Forces only when with_force: mj_contactForce (needs the constraint
// solve), or, when `forces` is not empty, its 6 numbers per contact of
// d->contact (mj_contactForce's, computed by another MuJoCo on the same
// contacts).
void observe_pairs(const mjModel* m, const mjData* d, const ModelLayout& layout,
                   const ContactBuckets& buckets, bool with_force, Scratch& scratch,
                   std::vector<PairObservation>& out, std::span<const double> forces = {});

// The same, one observation per pair of `layout` (index = pair; not
// reported where no contact): for runs of declared pairs only (the probe,
// the injector).
void observe_pairs(const mjModel* m, const mjData* d, const ModelLayout& layout, bool with_force,
                   Scratch& scratch, std::vector<PairObservation>& out,
                   std::span<const double> forces = {});

// (v_a - v_b) . n at world point p (MuJoCo frame), from the bodies'
// translational Jacobians (position stage) and qvel; world body 0 is at rest
[[nodiscard]] double approach_speed_mps(const mjModel* m, const mjData* d, int mj_body_a,
                                        int mj_body_b, const double p[3], const double n[3],
                                        Scratch& scratch);

// m_eff = 1 / (J M^-1 J^T) along n at p, J = n^T (J_b(p) - J_a(p)) (ENGINES.md:
// what a direct solref is per unit of); needs qLD (mj_factorM, position stage)
[[nodiscard]] double effective_mass_kg(const mjModel* m, mjData* d, int mj_body_a, int mj_body_b,
                                       const double p[3], const double n[3], Scratch& scratch);

// n^T (J_b(p) - J_a(p)), the row of one contact along its normal n (MuJoCo
// frame), into `row` (nv entries)
void normal_row(const mjModel* m, mjData* d, int mj_body_a, int mj_body_b, const double p[3],
                const double n[3], Scratch& scratch, double* row);

// the same row on scratch.dofs only (pair_dofs of the two bodies, set by the
// caller; scratch.sparse): dofs.size() entries, each the dense row's
void normal_row_on_dofs(const mjModel* m, const mjData* d, int mj_body_a, int mj_body_b,
                        const double p[3], const double n[3], Scratch& scratch, double* row);

}  // namespace pb::internal::mujoco
