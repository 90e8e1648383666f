// The closed-form motion along a fixed line of a body on it with Coulomb
// friction (SPEC §7), given its normal motion: a disk (rolling or slipping)
// or a polygon that translates on a face (a block). Written from the rigid
// body's equations, independently of the reference solver.
//
// Along the line (tangent t, outward normal n of the half-plane) the centre
// moves with speed w, the body turns at omega (counter-clockwise), and its
// contact point, the lowest point at distance R below the centre (a disk's
// radius; a block does not turn), moves at the slip speed
//   v = w + omega R                     (the point -R n turns with omega),
// under gravity's tangential part g_t = g . t and the friction force f t at
// that point, whose torque about the centre is R f:
//   m w' = m g_t + f,   I omega' = R f,   v' = g_t + f / m_t,
//   1 / m_t = 1 / m + R^2 / I           (disk: m_t = m / 3; block: m_t = m).
// f acts only while the normal force F(t) > 0 (NormalContactMotion, pressed),
// in one of three phases:
//   flight  F = 0 (or the pair not pressing): f = 0;
//   slip    f = -mu F(t) s, s = +-1 the sign of v during the phase, so with
//           Phi(t) = int_0^t F, Psi(t) = int_0^t Phi (closed forms of the
//           normal motion: Phi = m (u'(t) - u'(0)) - m a t, Psi = m (u(t) -
//           u(0) - u'(0) t - a t^2 / 2), u the gap, a = g . n):
//           w = w0 + g_t T - mu s dPhi / m, omega = omega0 - R mu s dPhi / I
//           (T = t - t0, dPhi = Phi(t) - Phi(t0)), and the same with dPsi
//           for the position and angle;
//   stick   v = 0 held by f = -m_t g_t (constant), which needs
//           |m_t g_t| <= mu F(t): w' = g_t (1 - m_t / m), omega' = -R m_t g_t / I.
// Events (found by scanning the closed form in steps of a tenth of the
// normal oscillation's 1 / omega_0 and bisecting to the last bit):
//   slip  -> when s v falls below 0 (the slip stops or reverses),
//   stick -> when mu F(t) falls below |m_t g_t| (the load leaves the cone),
//   any   -> at every change of the normal phase;
// at each the next phase is stick if it holds (|v| <= 1e-9 m/s and
// |m_t g_t| <= mu F), else slip along v, or, from rest, along g_t.
// The closed forms of SPEC §7 are this with F = m |a| constant (a body
// pressed in at rest): a block holds iff tan(theta) <= mu, else slides with
// a = g (sin theta - mu cos theta); it stops after v0 / (mu g); a disk rolls
// with a = (2/3) g sin theta iff mu >= tan(theta) / 3; a thrown disk slips
// until t* = v0 / (3 mu g).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "normal_contact_motion.hpp"

namespace pb::internal {

struct TangentialParams {
  double mass_kg = 0.0;             // m, kg
  double inertia_kgm2 = 0.0;        // I, kg m^2 (a block: unused)
  double radius_m = 0.0;            // R, m: centre to contact point; 0 for a block
  bool rotates = false;             // a disk turns; a block does not
  double friction = 0.0;            // mu, > 0
  double tangential_gravity_mps2 = 0.0;  // g_t, m/s^2
  double along0_m = 0.0;            // s(0), m
  double along_rate0_mps = 0.0;     // w(0), m/s
  double angle0_rad = 0.0;          // rad
  double spin0_radps = 0.0;         // omega(0), rad/s
};

enum class TangentialPhaseKind { flight, slip, stick };

struct TangentialPhase {
  TangentialPhaseKind kind = TangentialPhaseKind::flight;
  double start_s = 0.0;
  double end_s = 0.0;           // s, +inf while open
  double slip_sign = 0.0;       // s of a slip phase
  double along0_m = 0.0;        // state at start_s
  double along_rate0_mps = 0.0;
  double angle0_rad = 0.0;
  double spin0_radps = 0.0;
  double phi0_ns = 0.0;         // Phi(start_s), N s
  double psi0_ns2 = 0.0;        // Psi(start_s), N s^2
};

struct TangentialState {
  double along_m = 0.0;         // s, m
  double along_rate_mps = 0.0;  // w, m/s
  double angle_rad = 0.0;
  double spin_radps = 0.0;
  double slip_rate_mps = 0.0;   // v = w + omega R, m/s
  double friction_n = 0.0;      // f, N (on the body along t)
};

class TangentialMotion {
 public:
  // `normal` must outlive this and be extended at least as far (extend_to)
  TangentialMotion(const TangentialParams& p, const NormalContactMotion& normal);

  // locates every phase change up to t_s (the normal motion must be known that far)
  void extend_to(double t_s);
  [[nodiscard]] TangentialState state_at(double t_s) const;
  [[nodiscard]] const std::vector<TangentialPhase>& phases() const { return phases_; }
  [[nodiscard]] long phases_begun(double t_s) const;
  // the parameters, effective mass, and every phase so far
  [[nodiscard]] nlohmann::json mapping() const;

  // 1 / m_t = 1 / m + R^2 / I
  [[nodiscard]] double tangential_mass_kg() const { return m_t_; }

 private:
  // Phi(t) and Psi(t) of the normal force (see top)
  [[nodiscard]] double phi_ns(double t_s) const;
  [[nodiscard]] double psi_ns2(double t_s) const;
  [[nodiscard]] TangentialState state_in(const TangentialPhase& ph, double t_s) const;
  // the phase that starts at t_s from state s, with the normal motion there
  [[nodiscard]] TangentialPhase begin_phase(double t_s, const TangentialState& s) const;
  // the first event of phase ph in (from, until], or +inf
  [[nodiscard]] double next_event(const TangentialPhase& ph, double from_s, double until_s) const;

  TangentialParams p_;
  const NormalContactMotion& normal_;
  double m_t_ = 0.0;            // kg
  double scan_step_s_ = 0.0;    // s
  std::vector<TangentialPhase> phases_;
  double searched_until_s_ = 0.0;
};

}  // namespace pb::internal
