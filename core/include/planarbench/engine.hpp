// The engine interface: the reference solver, the analytic truth and every
// adapter implement it. The runner drives an engine through a case onto the
// common output grid (runner.hpp).
#pragma once

#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/settings.hpp"

namespace pb {

// state of one body at the engine's current time, world frame, SI
struct BodyState {
  Vec2 position_m = Vec2::Zero();        // m, centre of mass
  double angle_rad = 0.0;                // rad, counter-clockwise positive
  Vec2 velocity_mps = Vec2::Zero();      // m/s
  double angular_velocity_radps = 0.0;   // rad/s
};

// m/s, the velocity of the body's material point at world point p_m:
// v + omega x (p - x)
[[nodiscard]] inline Vec2 point_velocity(const BodyState& body, const Vec2& p_m) {
  const Vec2 r = p_m - body.position_m;
  return body.velocity_mps + body.angular_velocity_radps * Vec2(-r.y(), r.x());
}

// one active contact at the engine's current time
struct ContactSample {
  int body_a = -1;                   // index into Case::bodies
  int body_b = -1;                   // index into Case::bodies
  double force_n = 0.0;              // N, normal force magnitude, >= 0
  double penetration_m = 0.0;        // m, >= 0 (NaN when the engine does not give it)
  Vec2 normal = Vec2::Zero();        // unit normal, pointing from body_a to body_b
  Vec2 point_m = Vec2::Zero();       // m, world contact point: midpoint of the two
                                     // bodies' contact (deepest / closest) points
  // Friction (issue 32), along the tangent t = n rotated by +90 deg
  // (contact_tangent): the tangential force on body_b (N, signed; 0 for a
  // frictionless pair) and the slip, body_b's material point's velocity
  // relative to body_a's at point_m (m/s, signed; the runner fills it from
  // the engine's body states). NaN: not recorded (an older file, an engine
  // that does not give it), never 0.
  double tangential_force_n = std::numeric_limits<double>::quiet_NaN();
  double slip_mps = std::numeric_limits<double>::quiet_NaN();
};

// t = n rotated by +90 deg: the tangent of a contact's tangential columns
[[nodiscard]] inline Vec2 contact_tangent(const Vec2& n) { return Vec2(-n.y(), n.x()); }

// one contact episode: from penetration > 0 until it returns to 0 (SPEC §4)
struct ContactEpisode {
  int body_a = -1;
  int body_b = -1;
  double onset_time_s = 0.0;         // s
  double offset_time_s = 0.0;        // s (NaN while still in contact at the end)
  double approach_speed_mps = 0.0;   // m/s, normal relative speed at onset, > 0 approaching
  double separation_speed_mps = 0.0; // m/s, normal relative speed at offset, > 0 separating
  double restitution = 0.0;          // separation / approach
  double peak_force_n = 0.0;         // N
  double impulse_ns = 0.0;           // N s, integral of the normal force
  double max_penetration_m = 0.0;    // m
};

enum class Support {
  native,       // the engine expresses the case as stated
  mapped,       // the engine runs it through a documented approximation
  unsupported,  // the engine cannot run it (reason says why)
};

[[nodiscard]] const char* support_name(Support s);

struct Capability {
  Support support = Support::unsupported;
  std::string reason;  // why mapped or unsupported; empty for native
};

// Whose physics produced a run (SPEC §5b): whose collision detection found the
// contacts and whose contact model turned them into forces, and whether any
// parameter was calibrated with knowledge of the run's future. Every run's
// mapping carries it as "physics"; `list` and the report show it.
struct Physics {
  std::string mode;              // the engine's mode setting, e.g. "native", "oracle", "inject"
  std::string collision_by;      // "engine", "adapter", "reference" or "closed form"
  std::string collision;         // one line: what finds the contacts
  std::string contact_force_by;  // "engine", "adapter (case law)", "reference (case law)", "closed form"
  std::string contact_force;     // one line: what makes the force
  std::string parameters;        // one line: how the law's parameters are set
  bool foreknowledge = false;    // a parameter comes from a probe or look-ahead run
};

[[nodiscard]] nlohmann::json physics_json(const Physics& p);

class Engine {
 public:
  Engine() = default;
  virtual ~Engine() = default;
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  // "analytic", "reference", "mujoco", "box2d", "ode"
  [[nodiscard]] virtual std::string name() const = 0;
  // the engine's version as the engine reports it (and any caveat)
  [[nodiscard]] virtual std::string version() const = 0;
  // whether and how this engine runs the case; cheap, no building
  [[nodiscard]] virtual Capability supports(const Case& c) const = 0;
  // the settings this engine binds (keys, docs, defaults); the binder points
  // into the engine's own settings struct
  [[nodiscard]] virtual const SettingsBinder& settings() const = 0;

  // Builds the model of the case with the given overrides applied.
  // Throws InputError for bad settings, EngineError when the engine refuses.
  virtual void build(const Case& c, const SettingsOverrides& overrides) = 0;

  // Advances to time t_s >= time(). An engine with a fixed step stops at its
  // last step not after t_s (within 1e-9 of a step); variable-step engines land
  // on t_s. Throws EngineError on divergence.
  virtual void advance_to(double t_s) = 0;
  // the engine's current time, s
  [[nodiscard]] virtual double time() const = 0;

  // state of every body (index = Case::bodies index), fixed bodies included
  virtual void body_states(std::vector<BodyState>& out) const = 0;
  // active contacts at the current time
  virtual void contacts(std::vector<ContactSample>& out) const = 0;
  // every contact episode so far, resolved at the engine's own steps (or
  // located events); an episode still open has offset_time_s = NaN
  [[nodiscard]] virtual std::vector<ContactEpisode> episodes() const = 0;

  // steps taken so far
  [[nodiscard]] virtual long steps() const = 0;
  // how the case's contact law was expressed in this engine and what could
  // not be expressed (SPEC §5 `mapping`)
  [[nodiscard]] virtual nlohmann::json mapping() const = 0;
  // whose collision and contact model run with the current settings (before
  // or after build; cheap)
  [[nodiscard]] virtual Physics physics() const = 0;
  // steps the engine's own integrator took during build, before t = 0 (a
  // probe or look-ahead run); 0 for every default mode (SPEC §5b)
  [[nodiscard]] virtual long steps_before_start() const { return 0; }
  // every step the engine's library integrator has taken on this thread, by
  // whoever asked for it (a thread-local counter per library: mj_Euler /
  // mj_RungeKutta, b2World::Step, dWorldStep / dWorldQuickStep, the reference
  // solver's accepted steps); 0 for the truth, which may look ahead. run_engine
  // reads it around build: the no-look-ahead guard (SPEC §5b), which neither
  // an engine's own bookkeeping nor a wrapper around it can hide.
  [[nodiscard]] virtual long library_steps_on_this_thread() const { return 0; }

  // extra attributes for the results file (e.g. "valid_until_s")
  [[nodiscard]] virtual nlohmann::json extra_attributes() const { return nlohmann::json::object(); }
};

}  // namespace pb
