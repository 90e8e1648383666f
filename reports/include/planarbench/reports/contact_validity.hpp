// Per-step physical validity of a run's contacts (issue 32), the violations
// by which Le Lidec et al. ("Contact models in robotics: a comparative
// analysis", T-RO 2024, arXiv 2304.06372) judge contact solvers step by step,
// computed from the stored contacts columns (force_n, penetration,
// tangential_force_n, slip_mps) by the same code for every engine, any case
// and any number of pairs. Per pair of a run (Coulomb mu from the case):
//   cone                 max(0, |F_t| - mu F_n) / (mu F_n), samples with
//                        F_n > 0 of a pair with friction;
//   frictionless_tangent |F_t| / F_n, samples with F_n > 0 of a pair without;
//   dissipation          1 + sign(v_t) F_t / (mu F_n) while sliding
//                        (|v_t| > kSlidingSpeed_mps): 0 when the friction
//                        dissipates at the maximum rate (F_t = -mu F_n sign v),
//                        2 when it drives the slip;
//   power_deficit_j      int (F_t v_t + mu F_n |v_t|) dt over the sliding
//                        samples: the energy the friction fell short of the
//                        maximum dissipation by, J (trapezoid between
//                        consecutive samples at most 1.5 output intervals apart);
//   stick_creep_mps      |v_t| while the load is strictly inside the cone
//                        (|F_t| <= (1 - kInsideCone) mu F_n): 0 for a true
//                        stick, a soft model's creep otherwise;
//   force_at_distance_n  F_n of samples whose gap is open (penetration <
//                        -kOpenGap_m): no law of a case acts at a distance;
//   law_residual         |F_n - F_law(delta, delta_dot)| / the pair's peak F_n,
//                        samples in contact (delta > 0 or F_n > 0) of a pair
//                        of smooth bodies (no polygon: a face's force is the
//                        sum over its points while the row holds the deepest
//                        one, so the law of one point does not give it), the
//                        rate delta_dot = -n . (v_b(p_b) - v_a(p_a)) from the
//                        run's body states at the row's time (contact_slip.hpp)
//                        and Lankarani-Nikravesh's approach speed from the
//                        run's episode holding the row: the residual of an
//                        engine that claims the case's law (the reference);
//   complementarity_w    F_n max(0, -delta_dot): the power of a normal force
//                        on a separating contact after the step, W; 0 for a
//                        rigid contact at the velocity level (Box2D), its
//                        restitution the exception (v+ = -e v- by design).
// Each series gives its max, 99th percentile (nearest rank) and the fraction
// of its samples above a stated floor; rows whose tangential columns are NaN
// (a file written before them, an engine that does not give them) count as
// not recorded and enter no series.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/run_result.hpp"

namespace pb {

// m/s: a contact slides above this slip speed; below it a stick's creep is
// read (MuJoCo's soft friction creeps at 5.3e-7 m/s on block_hold, a true
// stick below 2e-10 m/s; a slide reaches 0.1-3 m/s in the shipped cases)
inline constexpr double kSlidingSpeed_mps = 1e-3;
// the load is strictly inside the cone below (1 - this) mu F_n
inline constexpr double kInsideCone = 1e-3;
// m: a gap open by more than this (far above any engine's rounding of a
// resting contact's penetration, 1e-12 m) is apart
inline constexpr double kOpenGap_m = 1e-9;

struct ValiditySeries {
  int samples = 0;
  double max = std::numeric_limits<double>::quiet_NaN();
  double p99 = std::numeric_limits<double>::quiet_NaN();
  double floor = 0.0;           // of fraction_above
  double fraction_above = std::numeric_limits<double>::quiet_NaN();
};

struct PairValidity {
  std::string pair;  // the case's pair name
  int body_a = -1;
  int body_b = -1;
  double mu = 0.0;
  int samples = 0;        // rows of the pair
  int not_recorded = 0;   // of them, without tangential columns
  ValiditySeries cone;                  // floor 1e-6
  ValiditySeries frictionless_tangent;  // floor 1e-6
  ValiditySeries dissipation;           // floor 1e-6
  double power_deficit_j = std::numeric_limits<double>::quiet_NaN();
  ValiditySeries stick_creep_mps;       // floor 1e-6 m/s
  ValiditySeries force_at_distance_n;   // floor 0 N
  ValiditySeries law_residual;          // floor 1e-6 (smooth pairs only)
  ValiditySeries complementarity_w;     // floor 0 W
};

// One row of a pair's contacts table as the metrics read it: each value NaN
// where the row does not enter that series (above).
struct ValiditySample {
  double time_s = 0.0;
  bool recorded = false;  // the tangential columns are numbers
  bool sliding = false;   // pressed, with friction, |v_t| > kSlidingSpeed_mps
  double cone = std::numeric_limits<double>::quiet_NaN();
  double frictionless_tangent = std::numeric_limits<double>::quiet_NaN();
  double dissipation = std::numeric_limits<double>::quiet_NaN();
  double power_w = 0.0;  // F_t v_t + mu F_n |v_t| while sliding, else 0
  double stick_creep_mps = std::numeric_limits<double>::quiet_NaN();
  double force_at_distance_n = std::numeric_limits<double>::quiet_NaN();
  double law_residual = std::numeric_limits<double>::quiet_NaN();
  double complementarity_w = std::numeric_limits<double>::quiet_NaN();
};

// The rows of the case's pair `pair` (index into Case::contacts) in r.contacts, in order.
[[nodiscard]] std::vector<ValiditySample> validity_samples(const Case& c, const RunResult& r,
                                                           std::size_t pair);

// A pair's entry from its samples (validity_samples(c, r, pair)).
[[nodiscard]] PairValidity pair_validity(const Case& c, std::size_t pair,
                                         const std::vector<ValiditySample>& samples);

// One entry per pair of the case (in its order), from r.contacts.
[[nodiscard]] std::vector<PairValidity> contact_validity(const Case& c, const RunResult& r);

// The gate's view of them (SPEC §9, against "self"), each the largest max over
// the run's pairs, the note naming the pair: cone_violation (pairs with
// friction), dissipation_deficit, stick_creep (m/s), force_at_distance (N),
// law_residual, complementarity (W); a metric none of the pairs has a sample
// of is left out (a frictionless case has no cone_violation).
[[nodiscard]] std::vector<MetricValue> validity_metrics(const Case& c, const RunResult& r);

// the names above, for the thresholds file
[[nodiscard]] const std::vector<const char*>& validity_metric_names();

}  // namespace pb
