// The shared model of a case: bodies, joints, contact pairs and their force
// laws, stated once in SI units (SPEC §2). Every engine builds from this.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace pb {

using Vec2 = Eigen::Vector2d;

// ---- shapes, in the body frame (origin = centre of mass) --------------------

// disk of the given radius centred on the body origin
struct Circle {
  double radius_m = 0.0;  // m
};

// ellipse (a cos t, b sin t) centred on the body origin, a along body x
struct Ellipse {
  double semi_axis_a_m = 0.0;  // m, along body x
  double semi_axis_b_m = 0.0;  // m, along body y
};

// simple polygon, counter-clockwise, body frame; its centroid is the origin
struct Polygon {
  std::vector<Vec2> points_m;  // m
};

// solid half-plane y <= 0 of the body frame; its surface is the body x axis and
// its outward normal is body +y. extent_m is the length of the surface segment
// used when the half-plane is represented by outline points (centred on the
// body origin); exact geometry treats the line as infinite.
struct HalfPlane {
  double extent_m = 20.0;  // m
};

using Shape = std::variant<Circle, Ellipse, Polygon, HalfPlane>;

[[nodiscard]] const char* shape_type_name(const Shape& shape);

// ---- bodies -----------------------------------------------------------------

struct Body {
  std::string name;
  Shape shape;
  bool fixed = false;          // fixed bodies never move (ground)
  int outline_points = 180;    // points of the outline (paper: 180)
  double mass_kg = 0.0;        // kg (0 for fixed bodies)
  double inertia_kgm2 = 0.0;   // kg m^2 about the centre of mass, out of plane
  Vec2 position_m = Vec2::Zero();        // m, centre of mass, world frame
  double angle_rad = 0.0;                // rad, counter-clockwise positive
  Vec2 velocity_mps = Vec2::Zero();      // m/s
  double angular_velocity_radps = 0.0;   // rad/s
};

// ---- joints -----------------------------------------------------------------

// revolute joint between a body and the ground (the world)
struct RevoluteJoint {
  std::string name;
  int body = -1;                          // index into Case::bodies
  Vec2 anchor_world_m = Vec2::Zero();     // m, pivot in the world frame
  Vec2 anchor_local_m = Vec2::Zero();     // m, pivot in the body frame (derived at t = 0)
};

// ---- contact force laws (paper §2.1.2) ------------------------------------

// Kelvin-Voigt, paper eq. 1: F = K delta + c delta_dot, clamped at F >= 0.
// With damping_depth_m > 0 the damping is ramped by a cubic step from 0 at
// delta = 0 to c at delta = damping_depth_m (MSC ADAMS IMPACT convention).
struct KelvinVoigt {
  double stiffness_n_per_m = 0.0;   // N/m
  double damping_ns_per_m = 0.0;    // N s/m
  double damping_depth_m = 0.0;     // m, 0 = plain Kelvin-Voigt (no ramp)
};

// Material data from which eqs. 3-4 compute the Hertz stiffness.
struct HertzMaterial {
  double young_modulus_i_pa = 0.0;  // Pa
  double young_modulus_j_pa = 0.0;  // Pa
  double poisson_ratio_i = 0.0;     // -
  double poisson_ratio_j = 0.0;     // -
  double radius_i_m = 0.0;          // m
  double radius_j_m = 0.0;          // m
};

// Hertz, elastic: F = K delta^n, clamped at F >= 0.
struct Hertz {
  double stiffness = 0.0;   // N/m^n
  double exponent = 1.5;    // n
  std::optional<HertzMaterial> material;  // set when K came from eq. 3
};

// Lankarani-Nikravesh, paper eq. 7:
// F = K delta^n [1 + 3(1 - e^2)/4 * delta_dot / delta_dot_minus], clamped at 0,
// delta_dot_minus = approach speed at the onset of this contact.
// `damping_factor` chi, when set, replaces 3(1 - e^2)/4: the laws of this
// family differ only in chi (Flores et al., "On the continuous contact force
// models for soft materials in multibody dynamics", Multibody Syst. Dyn. 25,
// 2011: Hunt-Crossley 3(1 - e)/2, Lankarani-Nikravesh 3(1 - e^2)/4, Flores
// 8(1 - e)/(5e)), and chi = alpha delta_dot_minus is Hunt and Crossley's own
// F = K delta^n (1 + alpha delta_dot) for a contact of that approach speed.
// Not read from case files (the measured impacts set it, issue 34).
struct LankaraniNikravesh {
  double stiffness = 0.0;    // N/m^n
  double exponent = 1.5;     // n
  double restitution = 0.0;  // e, nominal coefficient of restitution
  std::optional<HertzMaterial> material;  // set when K came from eq. 3
  std::optional<double> damping_factor;   // chi, >= 0; unset: 3(1 - e^2)/4
};

using ContactLaw = std::variant<KelvinVoigt, Hertz, LankaraniNikravesh>;

[[nodiscard]] const char* contact_law_name(const ContactLaw& law);

// K of paper eq. 3 with the square root of the published Lankarani-Nikravesh
// model (SPEC §1): K = 4 / (3 pi (h_i + h_j)) sqrt(R_i R_j / (R_i + R_j)),
// h_l = (1 - nu_l^2) / (pi E_l)  (eq. 4).
[[nodiscard]] double hertz_stiffness(const HertzMaterial& m);

struct ContactPair {
  std::string name;
  int body_a = -1;          // index into Case::bodies
  int body_b = -1;          // index into Case::bodies
  ContactLaw law;
  double threshold_m = 1e-10;  // m, distance counted as contact (paper: 1e-10)
  // Coulomb coefficient of the pair (SPEC §7), dimensionless, >= 0: the
  // tangential force is bounded by friction x the normal force; one
  // coefficient, no static / kinetic split. 0 = frictionless (the paper's law).
  double friction = 0.0;
  [[nodiscard]] bool has_friction() const { return friction > 0.0; }
};

// Every pair of a group of bodies may touch, with one law and one friction
// coefficient (SPEC §11): the pairs are found by a broad phase each step, not
// declared one by one. A declared pair ([[contacts]]) takes precedence for its
// two bodies; two fixed bodies never touch. A pair's normal points from its
// fixed body, else from the body listed first in Case::bodies.
struct ContactGroup {
  std::string name;
  std::vector<int> bodies;     // indices into Case::bodies, ascending, no repeats
  ContactLaw law;
  double threshold_m = 1e-10;  // m, as ContactPair::threshold_m
  double friction = 0.0;       // Coulomb coefficient, as ContactPair::friction
  [[nodiscard]] bool has_friction() const { return friction > 0.0; }
};

// The bodies one [[generate]] table made (SPEC §11): named name_1 ..
// name_count in Case::bodies order, from first_body on. Truths and reports
// read the scene's structure from here.
enum class SceneKind { stack, pyramid, row, grid };

[[nodiscard]] const char* scene_kind_name(SceneKind kind);

enum class SceneStart {
  given,     // positions as generated (a row's gaps, a grid's spacing)
  touching,  // the rigid pose: every interface at zero penetration
  resting,   // the static pose of the case's law: each interface pressed by its load
};

struct GeneratedBodies {
  std::string name;            // the prefix of the bodies' names
  SceneKind kind = SceneKind::grid;
  int first_body = 0;          // index of name_1 in Case::bodies
  int count = 0;               // bodies made
  int rows = 0;                // pyramid: rows (row r from the bottom holds rows - r bodies)
  int support = -1;            // stack, pyramid: the fixed half-plane it stands on, else -1
  SceneStart start = SceneStart::given;
  double gap_m = 0.0;          // m, row: surface gap between neighbours; pyramid: within a row
  [[nodiscard]] int body(int k) const { return first_body + k; }  // k from 0
};

// ---- truth ------------------------------------------------------------------

enum class TruthKind {
  none,                          // no ground truth: compare against the reference
  analytic,                      // closed form over the whole run
  // closed form up to the first contact onset, then the converged reference
  // at exact geometry (SPEC §3)
  analytic_until_first_contact,
  converged,                     // no closed form: the converged reference at exact geometry
};

[[nodiscard]] const char* truth_kind_name(TruthKind kind);

// ---- the case ---------------------------------------------------------------

struct Case {
  std::string name;          // file stem, e.g. "falling_ball"
  std::string description;   // one line
  std::string paper;         // where in the paper, e.g. "§3.1, Table 1, Figs 4-6"
  std::string source_path;   // the case file as given
  std::string source_text;   // the case file's text, verbatim
  Vec2 gravity_mps2 = Vec2(0.0, -9.8066);  // m/s^2
  double duration_s = 1.0;                 // s
  double output_interval_s = 1e-4;         // s, the common output grid
  // the contacts table holds every this many grid samples (SPEC §11: a
  // scene's thousands of contacts at every sample would dwarf its bodies);
  // 1 = every sample, with the dense samples of a young contact set (runner)
  int contact_output_every = 1;
  TruthKind truth = TruthKind::none;
  // what the reference solver uses as the truth after first contact, if any
  std::vector<std::string> assumptions;    // each assumption the paper leaves open
  std::vector<Body> bodies;
  std::vector<RevoluteJoint> joints;
  std::vector<ContactPair> contacts;
  std::vector<ContactGroup> contact_groups;
  std::vector<GeneratedBodies> generated;
  // engine settings stated by the case ([settings] table), "key" -> TOML text
  // of the value; --set overrides these.
  std::vector<std::pair<std::string, std::string>> settings;

  [[nodiscard]] int body_index(const std::string& body_name) const;  // -1 if absent
  // a case with contact groups: its pairs come from a broad phase (ContactPairs)
  [[nodiscard]] bool has_contact_groups() const { return !contact_groups.empty(); }
  // the first contact pair with friction > 0, or nullptr (a frictionless case)
  [[nodiscard]] const ContactPair* first_pair_with_friction() const;
  [[nodiscard]] int output_samples() const;  // number of grid points, t = 0 included
  [[nodiscard]] double output_time(int k) const;  // t_k = k * output_interval_s
};

// Why an adapter's force-injection mode cannot run a case with friction, ""
// for a frictionless case: `inject` applies the case's normal law as an
// external force at the engine's contact geometry, and Coulomb friction is a
// constraint (stick) that no applied force of the previous step expresses.
[[nodiscard]] std::string inject_friction_reason(const Case& c);

}  // namespace pb
