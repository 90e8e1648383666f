// Tests for adapters/ode/ode_engine.cpp
#include "planarbench/adapters/ode_engine.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <thread>

#include "ode_test_cases.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/outline.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

using ode_test::disk_body;
using ode_test::ellipse_body;
using ode_test::ground_body;
using ode_test::pair;

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.8066;  // m/s^2

SettingsOverrides overrides(std::initializer_list<std::pair<std::string, std::string>> kv) {
  SettingsOverrides o;
  for (const auto& [k, v] : kv) o.set(k, v, {"--set", 0});
  return o;
}

std::unique_ptr<Engine> built(const Case& c, const SettingsOverrides& o = {}) {
  auto e = make_ode_engine();
  e->settings().apply(o);
  e->build(c, o);
  return e;
}

// ---- closed form: one clamped Kelvin-Voigt impact with gravity -------------
//
// A mass m reaches a line at normal speed v0 with the gravity component g_n
// pushing it in. While the clamped force acts, the penetration obeys
// m d'' = m g_n - k d - c d', d(0) = 0, d'(0) = v0:
//   d(t) = d_s + exp(-a t) (A cos wd t + B sin wd t), d_s = m g_n / k,
//   A = -d_s, B = (v0 + a A) / wd, a = c / 2m, wd = sqrt(k/m - a^2).
// The force k d + c d' reaches 0 at t_r (root found by bisection); the mass
// then flies freely, d = d_r + v_r s + g_n s^2 / 2, back to d = 0. The
// restitution is the separation speed over v0.
struct KvImpact {
  double peak_force_n = 0.0;
  double duration_s = 0.0;  // penetration > 0
  double restitution = 0.0;
  double max_penetration_m = 0.0;
};

KvImpact clamped_kv_impact(double k, double c, double m, double g_n, double v0) {
  const double a = c / (2.0 * m);
  const double wd = std::sqrt(k / m - a * a);
  const double ds = m * g_n / k;
  const double A = -ds;
  const double B = (v0 + a * A) / wd;
  auto d = [&](double t) {
    return ds + std::exp(-a * t) * (A * std::cos(wd * t) + B * std::sin(wd * t));
  };
  auto dd = [&](double t) {
    return std::exp(-a * t) *
           ((-a * A + wd * B) * std::cos(wd * t) + (-a * B - wd * A) * std::sin(wd * t));
  };
  auto force = [&](double t) { return k * d(t) + c * dd(t); };
  KvImpact r;
  // scan for the release (the force is positive from t = 0+ until then)
  const double dt = 1e-3 / wd;
  double t = dt;
  while (force(t) > 0.0) {
    r.peak_force_n = std::max(r.peak_force_n, force(t));
    r.max_penetration_m = std::max(r.max_penetration_m, d(t));
    t += dt;
  }
  double lo = t - dt;
  double hi = t;
  for (int i = 0; i < 200; ++i) (force(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double tr = lo;
  const double dr = d(tr);
  const double vr = dd(tr);  // < 0, leaving
  const double s = (-vr - std::sqrt(vr * vr - 2.0 * g_n * dr)) / g_n;
  r.duration_s = tr + s;
  r.restitution = -(vr + g_n * s) / v0;
  return r;
}

// the closed form reproduces ENGINES.md's reference figures for the drop,
// within half a unit of their printed last digit (514 N, 51.2 mm, 0.855)
TEST(OdeEngineClosedForm, ReferenceDropFigures) {
  const KvImpact r = clamped_kv_impact(1e4, 10.0, 1.0, kG, std::sqrt(2.0 * kG * 1.5));
  EXPECT_NEAR(r.peak_force_n, 514.0, 0.5);
  EXPECT_NEAR(r.max_penetration_m, 0.0512, 5e-5);
  EXPECT_NEAR(r.restitution, 0.855, 5e-4);
}

// ---- free flight ----------------------------------------------------------

// A disk thrown with v0 = (1, 3) m/s spinning at 2 rad/s, no contact. ODE's
// integrator is semi-implicit Euler, v_{n+1} = v_n + g h, x_{n+1} = x_n +
// h v_{n+1}: the velocity is exact, the position leads the parabola by
// g h t / 2 (sum of the velocity ramp). ODE's default orientation update
// turns by 2 atan(w h / 2) per step, (w h)^3 / 12 short of w h. Tolerances:
// those bounds, plus 1e-12 of rounding.
TEST(OdeEngine, FreeFlightMatchesTheParabola) {
  Case c;
  c.duration_s = 1.0;
  c.bodies = {disk_body("disk", 0.5, 1.0, Vec2(0.0, 10.0))};
  c.bodies[0].velocity_mps = Vec2(1.0, 3.0);
  c.bodies[0].angular_velocity_radps = 2.0;
  auto e = built(c);
  const double h = 1e-4;
  e->advance_to(1.0);
  EXPECT_NEAR(e->time(), 1.0, 1e-12);
  EXPECT_EQ(e->steps(), 10000);
  std::vector<BodyState> s;
  e->body_states(s);
  const double t = e->time();
  EXPECT_NEAR(s[0].velocity_mps.x(), 1.0, 1e-12);
  EXPECT_NEAR(s[0].velocity_mps.y(), 3.0 - kG * t, 1e-12);
  EXPECT_NEAR(s[0].position_m.x(), 1.0 * t, 1e-12);
  const double y_exact = 10.0 + 3.0 * t - 0.5 * kG * t * t;
  EXPECT_LE(std::abs(s[0].position_m.y() - y_exact), 0.5 * kG * h * t + 1e-12);
  EXPECT_NEAR(s[0].angle_rad, 2.0 * t, 1e4 * std::pow(2.0 * h, 3) / 12.0 * 1.01 + 1e-12);
  EXPECT_NEAR(s[0].angular_velocity_radps, 2.0, 1e-12);
}

// ---- the Kelvin-Voigt reference drop (ENGINES.md) ---------------------------

ContactEpisode first_episode(const Engine& e) {
  const auto eps = e.episodes();
  EXPECT_FALSE(eps.empty());
  return eps.empty() ? ContactEpisode{} : eps.front();
}

// m = 1 kg dropped 1.5 m onto a line, k = 1e4 N/m, c = 10 N s/m: closed form
// above (peak 514.1 N, 31.85 ms, e = 0.8553). At the default h = 1e-4 s with
// the corrected mapping, ODE's soft contact is the spring-damper up to
// O(omega h) = 1 % phase errors that do not dissipate: the episode's onset
// and offset are interpolated within a step (duration within 2h); measured:
// restitution 1.3e-4 off, peak force and penetration 0.03 %. Bounds: 1e-3 on
// the restitution (the interpolated speeds alone are good to g h / v = 2e-4)
// and 0.5 % on the peaks (a step samples the force curve's top within
// (omega h)^2 / 8 = 1.3e-4, plus the O(omega h) phase).
TEST(OdeEngine, KelvinVoigtDropCorrected) {
  const Case c = ode_test::kelvin_voigt_drop();
  auto e = built(c);
  e->advance_to(c.duration_s);
  const ContactEpisode ep = first_episode(*e);
  const KvImpact exact = clamped_kv_impact(1e4, 10.0, 1.0, kG, ep.approach_speed_mps);
  EXPECT_NEAR(ep.approach_speed_mps, std::sqrt(2.0 * kG * 1.5), 2.0 * kG * 1e-4);
  EXPECT_NEAR(ep.restitution, exact.restitution, 1e-3);
  EXPECT_NEAR(ep.offset_time_s - ep.onset_time_s, exact.duration_s, 2e-4);
  EXPECT_NEAR(ep.peak_force_n, exact.peak_force_n, 0.005 * exact.peak_force_n);
  EXPECT_NEAR(ep.max_penetration_m, exact.max_penetration_m, 0.005 * exact.max_penetration_m);
  // the contact's impulse is the momentum change m (v_in + v_out) plus what
  // cancels gravity over the contact, m g T. Measured 5e-5 relative; bound
  // 1e-3: the speeds interpolated at onset and offset are good to
  // g h / v = 2e-4 each, and T to a fraction of a step
  EXPECT_NEAR(
      ep.impulse_ns,
      ep.approach_speed_mps + ep.separation_speed_mps + kG * (ep.offset_time_s - ep.onset_time_s),
      1e-3 * ep.impulse_ns);
}

// The textbook mapping at h = 1e-3 adds h k = 10 N s/m of damping (ENGINES.md:
// e = 0.738 instead of 0.855); the corrected one at the same step stays
// within 1 % (omega h = 0.1 phase error only). "Measurably worse": the
// textbook error exceeds 0.1, ten times the corrected tolerance.
TEST(OdeEngine, TextbookMappingIsMeasurablyWorse) {
  const Case c = ode_test::kelvin_voigt_drop();
  const double v0 = std::sqrt(2.0 * kG * 1.5);
  const double e_exact = clamped_kv_impact(1e4, 10.0, 1.0, kG, v0).restitution;
  auto corrected = built(c, overrides({{"dt", "1e-3"}}));
  corrected->advance_to(c.duration_s);
  auto textbook = built(c, overrides({{"dt", "1e-3"}, {"ode.damping_mapping", "textbook"}}));
  textbook->advance_to(c.duration_s);
  const double e_corrected = first_episode(*corrected).restitution;
  const double e_textbook = first_episode(*textbook).restitution;
  EXPECT_NEAR(e_corrected, e_exact, 0.01 * e_exact);
  EXPECT_GT(e_exact - e_textbook, 0.1);
  // ENGINES.md's measured figure, printed to 3 digits; 0.01: it was measured
  // by another harness (its own onset/offset detection), whose speeds differ
  // from ours by O(g h / v) = 2e-3 at h = 1e-3 s, and the O(omega h) = 0.1
  // phase error moves the release by a fraction of that
  EXPECT_NEAR(e_textbook, 0.738, 0.01);
  // the mapping says what was used
  const auto sc = textbook->mapping().at("contacts").at(0).at("soft_contact");
  EXPECT_NE(sc.at("rule").get<std::string>().find("textbook"), std::string::npos);
  // hk / (hk + c) = 10 / 20; 1e-15: one rounding
  EXPECT_NEAR(sc.at("one_contact").at("erp").get<double>(), 0.5, 1e-15);
}

// Inject mode applies the case's law itself (explicit over each step) at
// ODE's contact geometry: the same closed form holds, to the same bounds as
// the native drop (explicit force under semi-implicit Euler: no numerical
// damping, an O(omega h) = 1 % phase; measured: restitution 7.4e-5 off, peak
// force 2.4e-4 relative).
TEST(OdeEngine, KelvinVoigtDropInjected) {
  const Case c = ode_test::kelvin_voigt_drop();
  auto e = built(c, overrides({{"ode.mode", "inject"}}));
  e->advance_to(c.duration_s);
  const ContactEpisode ep = first_episode(*e);
  const KvImpact exact = clamped_kv_impact(1e4, 10.0, 1.0, kG, ep.approach_speed_mps);
  EXPECT_NEAR(ep.restitution, exact.restitution, 1e-3);
  EXPECT_NEAR(ep.peak_force_n, exact.peak_force_n, 0.005 * exact.peak_force_n);
  EXPECT_EQ(e->mapping().at("mode"), "inject");
}

// ---- pendulum period ------------------------------------------------------

// A disk (R = 0.1 m, m = 1 kg, I = m R^2 / 2) on a massless rod of L = 1 m,
// hinged at the origin, released from rest at theta0. Physical pendulum:
// omega0^2 = m g L / I_p, I_p = I + m L^2. Period: small amplitude
// 2 pi / omega0; exact 4 K(k) / omega0 with k = sin(theta0 / 2) (complete
// elliptic integral of the first kind, std::comp_ellint_1 takes the modulus).
// Measured from the times the rod passes the vertical (linear interpolation
// between steps, O(h^2) in time), over two full periods.
double measured_period(double theta0, double h) {
  Case c;
  c.duration_s = 6.0;
  const double l = 1.0;
  c.bodies = {disk_body("bob", 0.1, 1.0, Vec2(l * std::sin(theta0), -l * std::cos(theta0)))};
  RevoluteJoint j;
  j.name = "pivot";
  j.body = 0;
  j.anchor_world_m = Vec2::Zero();
  j.anchor_local_m = -c.bodies[0].position_m;
  c.joints = {j};
  auto e = built(c, overrides({{"dt", std::to_string(h)}}));
  std::vector<BodyState> s;
  std::vector<double> crossings;  // times of downward crossings of x = 0 (x: + -> -)
  double last_x = c.bodies[0].position_m.x();
  double last_t = 0.0;
  while (crossings.size() < 3 && e->time() < c.duration_s) {
    e->advance_to(e->time() + h);
    e->body_states(s);
    const double x = s[0].position_m.x();
    if (last_x > 0.0 && x <= 0.0) {
      crossings.push_back(last_t + (e->time() - last_t) * last_x / (last_x - x));
    }
    last_x = x;
    last_t = e->time();
  }
  EXPECT_EQ(crossings.size(), 3u);
  return crossings.size() == 3 ? 0.5 * (crossings[2] - crossings[0]) : 0.0;
}

double omega0() {
  const double inertia_pivot = 0.5 * 0.01 + 1.0;  // kg m^2
  return std::sqrt(kG * 1.0 / inertia_pivot);
}

// theta0 = 2 deg: the exact period is 1.00008 times the small-amplitude one,
// so the small-amplitude formula holds to 1e-4. Against the exact period:
// semi-implicit Euler's period error is (omega h)^2 / 24 = 4e-10 relative at
// h = 1e-4 s, the linear interpolation of the crossings O((omega h)^2) too;
// measured 4e-9. Bound 1e-6 (the hinge's ERP correction may add a little).
TEST(OdeEngine, PendulumSmallAmplitudePeriod) {
  const double theta0 = 2.0 * kPi / 180.0;
  const double t = measured_period(theta0, 1e-4);
  EXPECT_NEAR(t, 2.0 * kPi / omega0(), 1e-4 * t);
  EXPECT_NEAR(t, 4.0 * std::comp_ellint_1(std::sin(theta0 / 2.0)) / omega0(), 1e-6 * t);
}

// theta0 = 90 deg: the exact period is 1.18 times the small-amplitude one.
// Measured 2.6e-7 relative off the exact one (the swing's larger speeds make
// the hinge's per-step drift and its ERP correction larger); bound 2e-6.
TEST(OdeEngine, PendulumLargeAmplitudePeriod) {
  const double theta0 = kPi / 2.0;
  const double t = measured_period(theta0, 1e-4);
  const double exact = 4.0 * std::comp_ellint_1(std::sin(theta0 / 2.0)) / omega0();
  EXPECT_NEAR(t, exact, 2e-6 * exact);
  EXPECT_GT(t, 1.15 * 2.0 * kPi / omega0());
}

// ---- force sign and frame conventions ---------------------------------------

// A ball resting on a line inclined by -30 deg, held by gravity (frictionless:
// it slides). The contact's normal points from body_a to body_b: from the
// ground to the ball (sin 30, cos 30) when the ground is body_a, the opposite
// when the pair lists the ball first; the force is positive either way and
// carries the weight's normal component m g cos 30, with the static
// penetration m g cos 30 / k; the ball accelerates along the line at
// g sin 30 (the normal force has no tangential part): exact under semi-
// implicit Euler (constant acceleration), 1e-9. The ball starts at zero
// penetration, so the normal motion oscillates about the static one with
// amplitude m g cos 30 / k; after 1 s it has decayed by exp(-zeta omega t) =
// exp(-5) = 0.67 % (zeta = 0.05, omega = 100 rad/s): bounds 1 %.
TEST(OdeEngine, ForceSignAndFrameOnAnIncline) {
  const double angle = -kPi / 6.0;
  const Vec2 n_up(std::sin(kPi / 6.0), std::cos(kPi / 6.0));
  for (const bool ground_first : {true, false}) {
    Case c;
    c.duration_s = 1.0;
    c.bodies = {ground_body(angle), disk_body("ball", 0.5, 1.0, 0.5 * n_up)};
    c.contacts = {ground_first ? pair(0, 1, KelvinVoigt{1e4, 10.0, 0.0})
                               : pair(1, 0, KelvinVoigt{1e4, 10.0, 0.0})};
    auto e = built(c);
    e->advance_to(1.0);
    std::vector<ContactSample> cs;
    e->contacts(cs);
    ASSERT_EQ(cs.size(), 1u);
    const Vec2 expect_normal = ground_first ? n_up : Vec2(-n_up);
    // 1e-12: ODE's plane normal from the -30 deg turn, a few roundings
    EXPECT_NEAR((cs[0].normal - expect_normal).norm(), 0.0, 1e-12);
    EXPECT_EQ(cs[0].body_a, ground_first ? 0 : 1);
    const double f_static = kG * std::cos(kPi / 6.0);
    EXPECT_NEAR(cs[0].force_n, f_static, 0.01 * f_static);
    EXPECT_NEAR(cs[0].penetration_m, f_static / 1e4, 0.01 * f_static / 1e4);
    std::vector<BodyState> s;
    e->body_states(s);
    const Vec2 tangent(std::cos(angle), std::sin(angle));  // down the line toward +x
    EXPECT_NEAR(s[1].velocity_mps.dot(tangent), kG * 0.5 * e->time(), 1e-9);
    EXPECT_NEAR(s[1].angular_velocity_radps, 0.0, 1e-12);  // a normal force through the centre
  }
}

// ---- a rotated non-circular body ---------------------------------------------

// An ellipse (a = 0.7071, b = 0.25, m = 1 kg) turned +30 deg (counter-
// clockwise) falls from rest onto a horizontal line. Its lowest outline
// vertex, computed here from the outline, lies left of the centre at depth
// H below it: first contact at t = sqrt(2 (y0 - H) / g), at that vertex.
// The upward contact force acts left of the centre, so the ellipse starts
// turning clockwise, and its spin and fall speed change in the ratio of the
// rigid-body impulse equations: dw / dv_y = m (r x n) / I with r the lever
// from the centre to the contact point, n = +y. A sign or axis error in the
// frame mapping flips the side of the contact or the sense of the spin.
TEST(OdeEngine, RotatedEllipseLandsOnItsLowestVertex) {
  const double angle = kPi / 6.0;
  const double y0 = 1.0;
  Case c;
  c.bodies = {ground_body(), ellipse_body("ellipse", 0.7071, 0.25, 1.0, Vec2(0.0, y0), angle)};
  c.contacts = {pair(0, 1, KelvinVoigt{1e5, 50.0, 0.0})};
  const auto local = make_outline(c.bodies[1].shape, 180);
  Vec2 lowest(0.0, 1e300);
  for (const Vec2& q : local) {
    const Vec2 w = Eigen::Rotation2Dd(angle) * q;
    if (w.y() < lowest.y()) lowest = w;
  }
  ASSERT_LT(lowest.x(), 0.0);
  const double t_touch = std::sqrt(2.0 * (y0 + lowest.y()) / kG);
  // up to 30 ms after the touch: the ~6 ms impact is over, no second one yet
  c.duration_s = t_touch + 0.03;

  auto e = built(c);
  const double h = 1e-4;
  std::vector<BodyState> s;
  std::vector<ContactSample> cs;
  Vec2 first_point = Vec2::Zero();
  bool seen = false;
  while (e->time() < c.duration_s) {
    e->advance_to(e->time() + h);
    e->contacts(cs);
    if (!seen && !cs.empty()) {
      first_point = cs[0].point_m;
      seen = true;
    }
  }
  ASSERT_TRUE(seen);
  const ContactEpisode ep = first_episode(*e);
  // onset: interpolated within a step; the semi-implicit fall leads by
  // g h t / 2 in position, i.e. h / 2 in time
  EXPECT_NEAR(ep.onset_time_s, t_touch, 1.5 * h);
  // the first contact point is the lowest vertex (its x), within the x drift
  // of one step's penetration along the surface (< 1 mm)
  EXPECT_NEAR(first_point.x(), lowest.x(), 1e-3);
  e->body_states(s);
  EXPECT_LT(s[1].angular_velocity_radps, 0.0);  // clockwise after the impact
  // impulse ratio: dw / dv_y = m r_x / I (r x n = r_x for n = +y). The lever
  // moves as the ellipse turns during the contact: measured 0.5 %, bound 3 %.
  // gravity's share of the fall speed removed: dv = J / m
  const double dv = s[1].velocity_mps.y() + kG * e->time();
  const double ratio = s[1].angular_velocity_radps / dv;
  const double expect = 1.0 * lowest.x() / c.bodies[1].inertia_kgm2;
  EXPECT_NEAR(ratio, expect, 0.03 * std::abs(expect));
}

// ---- determinism, divergence, support, mapping -----------------------------

std::vector<double> trajectory_bits(const Case& c, const SettingsOverrides& o) {
  auto e = built(c, o);
  std::vector<double> out;
  std::vector<BodyState> s;
  for (int k = 1; k <= 50; ++k) {
    e->advance_to(c.duration_s * k / 50.0);
    e->body_states(s);
    for (const auto& b : s) {
      out.insert(out.end(), {b.position_m.x(), b.position_m.y(), b.angle_rad, b.velocity_mps.x(),
                             b.velocity_mps.y(), b.angular_velocity_radps});
    }
  }
  for (const auto& ep : e->episodes()) out.push_back(ep.restitution);
  return out;
}

// Same inputs, same bits: for the direct stepper, and for the quick stepper
// (row order from a reseeded global RNG) also when two engines run at once
// in two threads.
TEST(OdeEngine, Deterministic) {
  Case c = ode_test::kelvin_voigt_drop();
  c.bodies[1].position_m.x() = 0.1;
  c.bodies[1].angular_velocity_radps = 1.0;
  EXPECT_EQ(trajectory_bits(c, {}), trajectory_bits(c, {}));
  const auto quick = overrides({{"ode.stepper", "quick"}});
  const auto alone = trajectory_bits(c, quick);
  std::vector<double> a;
  std::vector<double> b;
  std::thread ta([&] { a = trajectory_bits(c, quick); });
  std::thread tb([&] { b = trajectory_bits(c, quick); });
  ta.join();
  tb.join();
  EXPECT_EQ(a, alone);
  EXPECT_EQ(b, alone);
}

// A ball between a floor and a ceiling 1 m apart (its diameter), with an
// explicit contact force far too stiff for its step (inject mode, one step
// per dt, omega h = 100): each bounce multiplies the speed (the force acts on
// the penetration one step late), so the state runs away within a few
// bounces: EngineError naming the time.
TEST(OdeEngine, BlowUpIsAnEngineError) {
  Case c;
  c.duration_s = 0.5;
  c.gravity_mps2 = Vec2::Zero();
  Body ceiling = ground_body(kPi, Vec2(0.0, 1.0));
  ceiling.name = "ceiling";
  c.bodies = {ground_body(), ceiling, disk_body("ball", 0.5, 1.0, Vec2(0.0, 0.5))};
  c.bodies[2].velocity_mps = Vec2(0.0, -1.0);
  c.contacts = {pair(0, 2, KelvinVoigt{1e12, 0.0, 0.0}, "floor"),
                pair(1, 2, KelvinVoigt{1e12, 0.0, 0.0}, "ceiling")};
  auto e = built(c, overrides({{"ode.mode", "inject"}, {"ode.substeps", "1"}}));
  try {
    e->advance_to(c.duration_s);
    FAIL() << "no divergence";
  } catch (const EngineError& err) {
    EXPECT_NE(std::string(err.what()).find("diverged at t ="), std::string::npos) << err.what();
    EXPECT_LT(e->time(), c.duration_s);
  }
}

TEST(OdeEngine, Supports) {
  auto e = make_ode_engine();
  Case kv = ode_test::kelvin_voigt_drop();
  EXPECT_EQ(e->supports(kv).support, Support::native);
  Case ln = kv;
  ln.contacts[0].law = LankaraniNikravesh{1e10, 1.5, 0.7, std::nullopt, {}};
  EXPECT_EQ(e->supports(ln).support, Support::mapped);
  EXPECT_NE(e->supports(ln).reason.find("lankarani_nikravesh"), std::string::npos);
  EXPECT_NE(e->supports(ln).reason.find("each step"), std::string::npos);
  e->settings().apply(overrides({{"ode.mode", "inject"}}));
  EXPECT_EQ(e->supports(ln).support, Support::native);
  Case moving_plane = kv;
  moving_plane.bodies[0].fixed = false;
  moving_plane.bodies[0].mass_kg = 1.0;
  moving_plane.bodies[0].inertia_kgm2 = 1.0;
  EXPECT_EQ(e->supports(moving_plane).support, Support::unsupported);
  // a concave polygon runs as convex prisms of its pieces (CGAL)
  e->settings().apply(overrides({{"ode.mode", "native"}}));
  Case dent = kv;
  dent.bodies[1].shape = Polygon{{{0, 0}, {2, 0}, {1, 0.2}, {2, 2}, {0, 2}}};
  EXPECT_EQ(e->supports(dent).support, Support::mapped);
  EXPECT_NE(e->supports(dent).reason.find("convex prisms"), std::string::npos)
      << e->supports(dent).reason;
}

// build() starts from the defaults: an earlier build's overrides do not leak
TEST(OdeEngine, BuildResetsSettings) {
  const Case c = ode_test::kelvin_voigt_drop();
  auto e = make_ode_engine();
  e->build(c, overrides({{"ode.mode", "inject"}, {"dt", "1e-3"}}));
  EXPECT_EQ(e->mapping().at("mode"), "inject");
  e->build(c, {});
  EXPECT_EQ(e->mapping().at("mode"), "native");
  EXPECT_EQ(e->mapping().at("step_s").get<double>(), 1e-4);
  EXPECT_EQ(e->time(), 0.0);
}

TEST(OdeEngine, VersionAndMapping) {
  const Case c = ode_test::kelvin_voigt_drop();
  auto e = built(c);
  EXPECT_NE(e->version().find("0.16"), std::string::npos) << e->version();
  EXPECT_NE(e->version().find("ODE_double_precision"), std::string::npos) << e->version();
  const auto m = e->mapping();
  const auto sc = m.at("contacts").at(0).at("soft_contact").at("one_contact");
  // h = 1e-4, k = 1e4, c = 10: c' = 9, ERP = CFM = 0.1 (see ode_contact_mapping_test);
  // 1e-15 and 1e-12 (on 9 N s/m): a few roundings
  EXPECT_NEAR(sc.at("erp").get<double>(), 0.1, 1e-15);
  EXPECT_NEAR(sc.at("cfm_m_per_ns").get<double>(), 0.1, 1e-15);
  EXPECT_NEAR(sc.at("damping_used_ns_per_m").get<double>(), 9.0, 1e-12);
  EXPECT_TRUE(sc.at("correction_valid").get<bool>());
  EXPECT_EQ(m.at("substeps").get<int>(), 1);
  EXPECT_TRUE(m.at("contacts").at(0).at("not_expressed").empty());
}

// ---- acceptance on the project's case files -------------------------------

std::optional<Case> case_file(const std::string& name) {
  const std::filesystem::path p = std::filesystem::path(PB_CASES_DIR) / (name + ".toml");
  if (!std::filesystem::exists(p)) return std::nullopt;
  return load_case(p);
}

// falling_ball (SPEC §2): the first impact's normal problem is the clamped
// oscillator with the gravity component g cos 30 along the normal, at the
// approach speed 6.1573 m/s: e = 0.8562. At the default settings the
// corrected mapping is within 1 % (acceptance); measured 6e-6 relative, so
// 1e-3 bounds it with the O(g h / v) = 2e-4 of the interpolated speeds. The
// textbook mapping at the same step is worse by its extra h k = 1 N s/m:
// ~1.5 %; asserted at least 5x the corrected error.
TEST(OdeEngineCases, FallingBall) {
  const auto c = case_file("falling_ball");
  if (!c) GTEST_SKIP() << "cases/falling_ball.toml not present";
  auto e = make_ode_engine();
  const RunResult r = run_engine(*e, *c, {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  ASSERT_EQ(r.bodies[0].time_s.size(), static_cast<std::size_t>(c->output_samples()));
  ASSERT_GE(r.events.size(), 2u);
  const double e_exact =
      clamped_kv_impact(1e4, 10.0, 1.0, kG * std::cos(kPi / 6.0), r.events[0].approach_speed_mps)
          .restitution;
  // SPEC §2's figure, printed to 4 digits (5e-5), at the engine's measured
  // approach speed (off the exact 6.1573 m/s by O(g h)): 1e-4
  EXPECT_NEAR(e_exact, 0.8562, 1e-4);
  const double err_corrected = std::abs(r.events[0].restitution - e_exact);
  EXPECT_LT(err_corrected, 1e-3 * e_exact);
  EXPECT_NEAR(r.events[0].onset_time_s, 0.72501, 1e-4);  // SPEC §2, within one step

  auto t = make_ode_engine();
  const RunResult rt = run_engine(*t, *c, overrides({{"ode.damping_mapping", "textbook"}}));
  ASSERT_EQ(rt.status, RunStatus::ok) << rt.reason;
  const double err_textbook = std::abs(rt.events[0].restitution - e_exact);
  EXPECT_GT(err_textbook, 5.0 * err_corrected);
  EXPECT_GT(err_textbook, 0.005 * e_exact);
}

// sliding (SPEC §2): frictionless, so the motion along the 45 deg line is
// uniform acceleration g sin 45 whatever the normal oscillation does; the
// velocity along the line is exact under semi-implicit Euler (constant
// acceleration): rounding only, 1e-9 relative (acceptance: 1 %).
TEST(OdeEngineCases, Sliding) {
  const auto c = case_file("sliding");
  if (!c) GTEST_SKIP() << "cases/sliding.toml not present";
  auto e = make_ode_engine();
  const RunResult r = run_engine(*e, *c, {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const auto& b = r.bodies[0];
  ASSERT_EQ(b.time_s.size(), static_cast<std::size_t>(c->output_samples()));
  const Vec2 tangent(std::cos(kPi / 4.0), -std::sin(kPi / 4.0));
  const std::size_t k1 = b.time_s.size() / 2;
  const std::size_t k2 = b.time_s.size() - 1;
  const double a = (b.velocity_mps[k2].dot(tangent) - b.velocity_mps[k1].dot(tangent)) /
                   (b.time_s[k2] - b.time_s[k1]);
  EXPECT_NEAR(a, kG * std::sin(kPi / 4.0), 1e-9 * kG);
  EXPECT_FALSE(r.contacts.empty());
}

// dual_pendulum (SPEC §2): first contact when the ellipse pendulum passes
// the vertical, the exact quarter period K(sin(theta0 / 2)) / omega0 of the
// physical pendulum (omega0^2 = m g L / I_p, I_p = I + m L^2, L and theta0
// from the case's pivot and centre), 0.4965 s (SPEC); acceptance within 1 ms;
// the run resolves it to a step of the case's dt (1e-5 s, [settings]). Momentum goes to the disk: the impulse J at
// lever L = 0.7071 m below both pivots gives the disk pendulum the angular
// momentum J L about its pivot and takes the same from the ellipse. Measured
// at the first sample after the episode: 0.07 % off. Bound 1 %: gravity's
// torque over the 0.26 ms contact and the sample's 0.1 ms after it change the
// disk's angular momentum by ~5e-3 of J L, the lever's change is smaller.
TEST(OdeEngineCases, DualPendulum) {
  const auto c = case_file("dual_pendulum");
  if (!c) GTEST_SKIP() << "cases/dual_pendulum.toml not present";
  auto e = make_ode_engine();
  // the case's own settings (its step), as `planarbench run` applies them
  SettingsOverrides given;
  for (const auto& [k, v] : c->settings) given.set(k, v, SettingSource{c->source_path, 0});
  const RunResult r = run_engine(*e, *c, given);
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  ASSERT_FALSE(r.events.empty());
  const ContactEpisode& ep = r.events[0];
  const Body& be = c->bodies[0];
  {
    const Vec2 lever = be.position_m - c->joints[0].anchor_world_m;  // pivot to centre, m
    const double length = lever.norm();
    const double theta0 = std::atan2(std::abs(lever.x()), -lever.y());
    const double w0 = std::sqrt(be.mass_kg * kG * length /
                                (be.inertia_kgm2 + be.mass_kg * length * length));
    const double t_quarter = std::comp_ellint_1(std::sin(theta0 / 2.0)) / w0;
    EXPECT_NEAR(t_quarter, 0.4965, 5e-5);  // SPEC's figure, half its last printed digit
    EXPECT_NEAR(ep.onset_time_s, t_quarter, 1e-4);
  }
  // the sample after the episode
  const auto& disk = r.bodies[1];
  const auto& ellipse = r.bodies[0];
  std::size_t k = 0;
  while (disk.time_s[k] < ep.offset_time_s) ++k;
  const double l = 0.7071;
  const Body& bd = c->bodies[1];
  const double ip_disk = bd.inertia_kgm2 + bd.mass_kg * l * l;
  const double ip_ellipse = be.inertia_kgm2 + be.mass_kg * l * l;
  EXPECT_NEAR(ip_disk * disk.angular_velocity_radps[k], ep.impulse_ns * l,
              0.01 * ep.impulse_ns * l);
  EXPECT_GT(disk.velocity_mps[k].x(), 0.0);
  // the ellipse lost that angular momentum (before: the sample at onset)
  std::size_t k0 = 0;
  while (ellipse.time_s[k0 + 1] < ep.onset_time_s) ++k0;
  EXPECT_NEAR(ip_ellipse * (ellipse.angular_velocity_radps[k0] - ellipse.angular_velocity_radps[k]),
              ep.impulse_ns * l, 0.01 * ep.impulse_ns * l);
  // the run says how often the corrected damping could not hold (Hertz-like
  // k grows faster than c near the onset: c / k = 3 (1 - e^2) delta / (4 v))
  const auto dc = r.mapping.at("damping_correction");
  EXPECT_GT(dc.at("rows").get<long>(), 0);
  EXPECT_LE(dc.at("rows_invalid").get<long>(), dc.at("rows").get<long>());
}

}  // namespace
}  // namespace pb
