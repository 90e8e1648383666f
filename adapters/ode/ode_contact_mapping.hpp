// How a case's contact law becomes an ODE soft contact (pure arithmetic, no
// ODE calls): the linear spring-damper a law is expressed as, its ERP/CFM at
// a step, the effective mass along a contact normal, and the auto step.
#pragma once

#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/contact_law_response.hpp"

namespace pb::internal::ode {

// ---- ERP/CFM of a linear spring-damper -----------------------------------

// ODE manual, "Soft constraint and constraint force mixing": a contact with
//   ERP = h k / (h k + c'),  CFM = 1 / (h k + c')
// solves J v' = (ERP/h) depth - CFM lambda, i.e. lambda = k (depth - h u) + c' (-u)
// with u = J v' the separation speed at the end of the step: the spring acts
// on the end-of-step penetration (backward Euler), which damps like an extra
// h k. The textbook choice c' = c therefore behaves like c + h k; the corrected
// choice c' = c - h k gives lambda = k depth + c (-u), spring at the start of
// the step and damper at its end, which keeps the intended damping. c' must
// stay >= 0 (ERP <= 1): with c < h k the correction is clamped at c' = 0 and
// the contact still damps like h k instead of c.
struct SoftContact {
  double erp = 0.0;                         // -
  double cfm = 0.0;                         // m/(N s)
  double damping_used_ns_per_m = 0.0;       // c' fed to the formulas, N s/m
  double numerical_damping_ns_per_m = 0.0;  // h k, N s/m
  bool corrected = false;                   // the corrected mapping was asked for
  bool correction_valid = true;             // c >= h k (always true for textbook)
  std::string note;                         // what was done and why
};
[[nodiscard]] SoftContact soft_contact(double stiffness_n_per_m, double damping_ns_per_m,
                                       double step_s, bool corrected);

// The numbers of soft_contact without its note, for every contact of every
// step (no allocation): ERP, CFM and whether the corrected mapping held.
struct SoftRow {
  double erp = 0.0;              // -
  double cfm = 0.0;              // m/(N s)
  bool correction_valid = true;  // c >= h k (always true for textbook)
};
[[nodiscard]] SoftRow soft_row(double stiffness_n_per_m, double damping_ns_per_m, double step_s,
                               bool corrected);

// ---- one pair's law over its contacts (native mode) -------------------------

// SPEC §1, one force per pair: ODE's soft contact rows are springs and
// dampers in force units, each on its own depth d_i and normal speed u_i
// (lambda_i = k_i d_i - c_i u_i with the corrected mapping). Giving contact i
//   k_i = k delta / sum_j d_j,   c_i = c d_i / sum_j d_j
// (delta = max_j d_j, the pair's penetration) makes the springs sum to
// k delta for any depths and the dampers to c (a mean of the u_i weighted by
// depth); both resultants act at the depth-weighted centroid of the contacts
// (k_i d_i and c_i are proportional to d_i). One contact: the law itself;
// a uniform penetration: k / N and c / N each. (Spreading c like k, c delta /
// sum d_j, would damp by delta / mean depth too much: 1.5 times for the
// parabolic depths of a curved outline pressed into a line.)
struct SpreadLaw {
  double stiffness_n_per_m = 0.0;  // k_i, N/m
  double damping_ns_per_m = 0.0;   // c_i, N s/m
};
[[nodiscard]] SpreadLaw spread_law(double stiffness_n_per_m, double damping_ns_per_m,
                                   double deepest_m, double depth_m, double depth_sum_m);

// A pair with friction: the same spread law, with every contact row of the
// pair given the same CFM. dWorldStep bounds each friction row by mu times
// its own contact's normal lambda, and a soft normal row's lambda follows its
// CFM: rows whose CFM differs (c_i = c d_i / sum d_j differs wherever the
// depths do, a face tilted by friction's own moment) share the load unlike
// their bounds, and the face slid at +11.3 % of g (sin - mu cos) on a 0.2 m
// square (2 kg, K 2e5, c 1100, 25 deg, mu 0.42; +0.36 % on the 0.4 m slab;
// ode.stepper=quick: exact). Here each of the n pressed rows takes the
// implicit damping c / n (one CFM for all), and the rest of its share,
// c_i - c / n (positive on the deeper contacts, negative on the shallower;
// summing to 0), is applied explicitly each step as a force -(c_i - c / n) u_i
// along the normal at the contact (u_i its separation speed at the step's
// start): the damping resultant c and its moment (the face's rocking damper)
// are the spread law's, its force up to one step's change of u_i.
struct FaceRow {
  double stiffness_n_per_m = 0.0;          // k_i, N/m (as spread_law)
  double implicit_damping_ns_per_m = 0.0;  // c / n, N s/m: into ERP / CFM
  double explicit_damping_ns_per_m = 0.0;  // c_i - c / n, N s/m: a force each step
};
[[nodiscard]] FaceRow face_row(double stiffness_n_per_m, double damping_ns_per_m,
                               double deepest_m, double depth_m, double depth_sum_m,
                               int pressed_contacts);

// ---- a law as a linear spring-damper ---------------------------------------

struct LinearLaw {
  double stiffness_n_per_m = 0.0;     // N/m
  double damping_ns_per_m = 0.0;      // N s/m
  bool exact = false;                 // the law is this spring-damper (plain Kelvin-Voigt)
  CollisionResponse law_response;     // the case's law in one collision (m_eff, v)
  CollisionResponse linear_response;  // the linear law in the same collision
  double mass_kg = 0.0;               // m_eff used
  double approach_speed_mps = 0.0;    // v used
  std::string how;                    // how the equivalent was found
};

// Plain Kelvin-Voigt is itself (exact). Any other law (Lankarani-Nikravesh,
// Hertz, Kelvin-Voigt with a damping ramp) becomes the spring-damper whose
// clamped collision has the same force duration and restitution as the law's
// own collision of mass m_eff at approach speed v (simulate_collision, then
// linear_equivalent). A purely elastic law (restitution 1) gets
// k = m (pi / T)^2, c = 0. v <= 0 (a contact that starts at rest) uses a
// nominal 1 m/s, stated in `how`.
[[nodiscard]] LinearLaw linear_law(const ContactLaw& law, double mass_kg,
                                   double approach_speed_mps);

// ---- effective mass ---------------------------------------------------------

// 1 / (J M^-1 J^T) along `normal` at `point` for the pair's two bodies, where
// J maps the bodies' velocities to the relative normal velocity. Per body:
// fixed -> 0; free -> 1/m + (r x n)^2 / I (r from the centre); one revolute
// joint to ground -> (r_p x n)^2 / I_p with r_p from the pivot and
// I_p = I + m |centre - pivot|^2 (parallel-axis theorem); two or more
// revolute joints -> 0 (immobile). centres_m: the bodies' current centres
// (index = Case::bodies index). Infinity when neither body can move.
[[nodiscard]] double effective_mass_kg(const Case& c, const ContactPair& pair,
                                       const std::vector<Vec2>& centres_m, const Vec2& point_m,
                                       const Vec2& normal);

// ---- step -------------------------------------------------------------------

// Steps per dt: the smallest n >= 1 such that h = dt / n resolves every pair's
// force phase with at least contact_steps steps and, when `need_hk_le_c`,
// gives h k <= c for every pair with c > 0 (the corrected mapping is valid).
struct StepNeed {
  double stiffness_n_per_m = 0.0;  // N/m
  double damping_ns_per_m = 0.0;   // N s/m
  double force_duration_s = 0.0;   // s, <= 0: unknown, not used
};
[[nodiscard]] int auto_substeps(double dt_s, const std::vector<StepNeed>& needs, int contact_steps,
                                bool need_hk_le_c);

}  // namespace pb::internal::ode
