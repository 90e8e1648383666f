// Reads and validates a case file (TOML, format in cases/README.md). Every
// error is one InputError naming the file (or `--set KEY`), the line, the
// field path and what is allowed.
#include "planarbench/case_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <sstream>
#include <toml++/toml.h>

#include "internal/case_fields.hpp"
#include "internal/case_overrides.hpp"
#include "internal/scene_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "internal/polygon_checks.hpp"
#include "internal/start_overlap.hpp"
#include "internal/toml_reader.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/outline.hpp"

namespace pb {

namespace {

using internal::Origins;
using internal::Range;
using internal::TableReader;
using internal::kMaxCaseFileBytes;
using internal::kMaxCoordinate_m;
using internal::kMaxDuration_s;
using internal::kMaxFriction;
using internal::kMaxOutlinePoints;
using internal::kMaxOutputSamples;
using internal::kMaxPolygonPoints;
using internal::kMaxSize_m;
using internal::kMaxThreshold_m;
using internal::kMinSize_m;
using internal::read_contact_law;
using internal::read_mass_properties;
using internal::read_shape;

const std::vector<std::string> kCaseKeys = {"duration", "output_interval", "contact_output_interval",
                                            "gravity", "outline_points", "truth"};
const std::vector<std::string> kTopKeys = {"case",     "bodies",         "generate", "joints",
                                           "contacts", "contact_groups", "settings"};
const std::vector<std::string> kCaseTableKeys = {
    "description",  "paper",          "duration", "output_interval", "contact_output_interval",
    "gravity",      "outline_points", "truth",    "assumptions"};
const std::vector<std::string> kBodyKeys = {"name", "fixed", "shape", "outline_points",
                                            "position", "angle", "angle_deg", "mass", "density",
                                            "inertia", "velocity", "angular_velocity"};
const std::vector<std::string> kMovingOnlyKeys = {"mass", "density", "inertia", "velocity",
                                                  "angular_velocity"};
const std::vector<std::string> kShapeTypes = {"circle", "ellipse", "polygon", "halfplane"};
const std::vector<std::string> kShapeKeys = {"type", "radius", "semi_axes", "points", "extent"};
const std::vector<std::string> kJointKeys = {"name", "type", "body", "anchor"};
const std::vector<std::string> kLaws = {"kelvin_voigt", "hertz", "lankarani_nikravesh"};
const std::vector<std::string> kContactKeys = {
    "name",          "bodies",    "law",      "stiffness",   "damping",
    "damping_depth", "threshold", "exponent", "restitution", "young_modulus",
    "poisson_ratio", "radius",    "friction"};
const std::vector<std::string> kKelvinVoigtKeys = {"law",           "stiffness", "damping",
                                                   "damping_depth", "threshold", "friction"};
const std::vector<std::string> kHertzKeys = {"law",           "stiffness",     "exponent",
                                             "threshold",     "young_modulus", "poisson_ratio",
                                             "radius",        "friction"};
const std::vector<std::string> kMaterialKeys = {"young_modulus", "poisson_ratio", "radius"};

std::vector<std::string> with(std::vector<std::string> keys, const std::string& extra) {
  keys.push_back(extra);
  return keys;
}

// ---- [case] ------------------------------------------------------------------

// fills the case-level fields; returns the default outline point count
int read_case_table(const TableReader& t, Case& c) {
  t.only_keys(kCaseTableKeys);
  c.description = t.string("description");
  if (c.description.find('\n') != std::string::npos) t.fail("description", "must be one line");
  c.paper = t.string_or("paper", "");
  c.duration_s = t.real("duration", Range::positive(kMaxDuration_s), "s");
  c.output_interval_s = t.real_or("output_interval", 1e-4, Range::positive(), "s");
  if (c.output_interval_s > c.duration_s) {
    t.fail("output_interval",
           fmt::format("must be <= duration = {} s (got {} s)", c.duration_s, c.output_interval_s));
  }
  if (c.duration_s / c.output_interval_s > kMaxOutputSamples) {
    t.fail("output_interval",
           fmt::format("gives {:g} output samples over duration = {} s; at most {:g}: make it "
                       ">= {:g} s",
                       c.duration_s / c.output_interval_s, c.duration_s, kMaxOutputSamples,
                       c.duration_s / kMaxOutputSamples));
  }
  if (t.has("contact_output_interval")) {
    const double every_s = t.real("contact_output_interval", Range::positive(c.duration_s), "s");
    const double ratio = every_s / c.output_interval_s;
    const double whole = std::round(ratio);
    if (whole < 1.0 || std::abs(ratio - whole) > 1e-9 * ratio) {
      t.fail("contact_output_interval",
             fmt::format("must be a whole multiple of output_interval = {} s (got {} s, {:.6g} "
                         "intervals)",
                         c.output_interval_s, every_s, ratio));
    }
    c.contact_output_every = static_cast<int>(whole);
  }
  c.gravity_mps2 = t.vec2_or("gravity", Vec2(0.0, -9.8066), Range::any(), "m/s^2");
  const int outline_points = t.integer_or("outline_points", 180, 3, kMaxOutlinePoints);
  const std::string truth =
      t.word_or("truth", "none", {"analytic", "analytic_until_first_contact", "converged", "none"});
  c.truth = truth == "analytic"                       ? TruthKind::analytic
            : truth == "analytic_until_first_contact" ? TruthKind::analytic_until_first_contact
            : truth == "converged"                    ? TruthKind::converged
                                                      : TruthKind::none;
  c.assumptions = t.strings_or_empty("assumptions");
  return outline_points;
}

// ---- [[bodies]] ----------------------------------------------------------------

Polygon read_polygon(const TableReader& s) {
  Polygon p;
  const toml::node* n = s.find("points");
  if (n == nullptr) s.fail_missing("points", "an array of [x, y] points, counter-clockwise, in m");
  const auto* a = n->as_array();
  if (a == nullptr || a->size() < 3 || a->size() > static_cast<std::size_t>(kMaxPolygonPoints)) {
    s.origins().fail(n, s.field("points"),
                     TableReader::must_be(
                         fmt::format("an array of 3 to {} [x, y] points", kMaxPolygonPoints), *n) +
                         ", in m");
  }
  for (std::size_t i = 0; i < a->size(); ++i) {
    const auto xy = s.pair_at(*a->get(i), fmt::format("{}[{}]", s.field("points"), i),
                              Range::magnitude(kMaxCoordinate_m), "m");
    p.points_m.emplace_back(xy[0], xy[1]);
  }
  if (const auto problem = internal::polygon_problem(p.points_m)) s.fail("points", *problem);
  return p;
}

Body read_body(const TableReader& t, int default_outline_points, internal::BodyNames& names) {
  t.only_keys(kBodyKeys);
  Body b;
  b.name = internal::body_name(t, "name");
  if (const auto it = names.find(b.name); it != names.end()) {
    t.fail("name", fmt::format("duplicate body name '{}' (also bodies[{}])", b.name, it->second));
  }
  b.fixed = t.boolean_or("fixed", false);
  if (b.fixed) {
    for (const auto& k : kMovingOnlyKeys) {
      if (t.has(k)) t.fail(k, fmt::format("a fixed body (fixed = true) never moves: remove {}", k));
    }
  }

  // shape and its outline
  b.shape = read_shape(t.subtable("shape"));
  if (std::holds_alternative<HalfPlane>(b.shape) && !b.fixed) {
    t.fail("shape", "a halfplane has no finite area or mass: it must be fixed (fixed = true)");
  }
  if (const auto* p = std::get_if<Polygon>(&b.shape)) {
    if (t.has("outline_points")) {
      t.fail("outline_points", "a polygon's outline is its own points: remove outline_points");
    }
    b.outline_points = static_cast<int>(p->points_m.size());
  } else {
    b.outline_points = t.integer_or("outline_points", default_outline_points, 3, kMaxOutlinePoints);
  }

  // initial pose and velocity
  b.position_m = t.vec2("position", Range::magnitude(kMaxCoordinate_m), "m");
  if (t.has("angle") && t.has("angle_deg")) {
    t.fail("angle_deg", "give angle (rad) or angle_deg, not both");
  }
  b.angle_rad = t.has("angle_deg")
                    ? t.real("angle_deg", Range::any(), "degrees") * std::numbers::pi / 180.0
                    : t.real_or("angle", 0.0, Range::any(), "rad");
  if (!b.fixed) {
    read_mass_properties(t, b);
    b.velocity_mps = t.vec2_or("velocity", Vec2::Zero(), Range::any(), "m/s");
    b.angular_velocity_radps = t.real_or("angular_velocity", 0.0, Range::any(), "rad/s");
  }
  return b;
}

// index of the body named by the string at `node`, or an error listing the bodies
int body_ref(const TableReader& t, const toml::node& node, const std::string& field, const Case& c) {
  const std::string name = t.string_at(node, field);
  const int index = c.body_index(name);
  if (index < 0) {
    std::vector<std::string> names;
    for (const auto& b : c.bodies) names.push_back(b.name);
    t.origins().fail(&node, field,
                     fmt::format("no body named {}{}; bodies: {}", echo_value(name),
                                 did_you_mean(name, names), join_words(names)));
  }
  return index;
}

// ---- [[joints]] ------------------------------------------------------------------

RevoluteJoint read_joint(const TableReader& t, const Case& c) {
  t.only_keys(kJointKeys);
  RevoluteJoint j;
  j.name = t.identifier("name");
  for (std::size_t k = 0; k < c.joints.size(); ++k) {
    if (c.joints[k].name == j.name) {
      t.fail("name", fmt::format("duplicate joint name '{}' (also joints[{}])", j.name, k));
    }
  }
  (void)t.word("type", {"revolute"});
  if (!t.has("body")) t.fail_missing("body", "the name of a moving body");
  j.body = body_ref(t, *t.find("body"), t.field("body"), c);
  const Body& body = c.bodies[static_cast<std::size_t>(j.body)];
  if (body.fixed) {
    t.fail("body", fmt::format("body '{}' is fixed: a joint to ground needs a moving body", body.name));
  }
  for (std::size_t k = 0; k < c.joints.size(); ++k) {
    if (c.joints[k].body == j.body) {
      t.fail("body", fmt::format("body '{}' already has a joint (joints[{}] '{}'): one revolute "
                                 "joint to ground per body",
                                 body.name, k, c.joints[k].name));
    }
  }
  j.anchor_world_m = t.vec2("anchor", Range::magnitude(kMaxCoordinate_m), "m");
  // body frame: anchor_local = R(theta)^T (anchor_world - position), at t = 0
  const double ct = std::cos(body.angle_rad);
  const double st = std::sin(body.angle_rad);
  const Vec2 d = j.anchor_world_m - body.position_m;
  j.anchor_local_m = Vec2(ct * d.x() + st * d.y(), -st * d.x() + ct * d.y());
  return j;
}

// ---- [[contacts]] ----------------------------------------------------------------

// material data of eqs. 3-4 from young_modulus, poisson_ratio, radius pairs
HertzMaterial read_material(const TableReader& t) {
  for (const auto& k : kMaterialKeys) {
    if (!t.has(k)) {
      t.fail_missing(k, fmt::format("[{0}_i, {0}_j]: the material needs young_modulus (Pa), "
                                    "poisson_ratio and radius (m)",
                                    k));
    }
  }
  const auto e = t.pair("young_modulus", Range::positive(), "Pa");
  const auto nu = t.pair("poisson_ratio", Range{-1.0, 0.5, true, true});
  const auto r = t.pair("radius", Range::positive(kMaxSize_m), "m");
  return HertzMaterial{e[0], e[1], nu[0], nu[1], r[0], r[1]};
}

// K given directly or computed from the material by eq. 3
double read_hertz_stiffness(const TableReader& t, std::optional<HertzMaterial>& material) {
  bool any_material = false;
  for (const auto& k : kMaterialKeys) any_material = any_material || t.has(k);
  if (t.has("stiffness") && any_material) {
    t.fail("stiffness",
           "give stiffness (N/m^n) or the material (young_modulus, poisson_ratio, radius), not both");
  }
  if (t.has("stiffness")) return t.real("stiffness", Range::positive(), "N/m^n");
  if (!any_material) {
    t.fail_missing("stiffness",
                   "stiffness (N/m^n, > 0) or young_modulus, poisson_ratio and radius");
  }
  material = read_material(t);
  const double k = hertz_stiffness(*material);
  if (!Range::positive().contains(k)) {
    t.fail("young_modulus", fmt::format("the material gives stiffness {} N/m^n: not finite > 0", k));
  }
  return k;
}

ContactPair read_contact(const TableReader& t, const Case& c) {
  t.only_keys(kContactKeys);
  ContactPair p;
  p.name = t.identifier("name");
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    if (c.contacts[k].name == p.name) {
      t.fail("name", fmt::format("duplicate contact name '{}' (also contacts[{}])", p.name, k));
    }
  }

  // the two bodies: fixed one first, normal from a to b
  const toml::node* bn = t.find("bodies");
  if (bn == nullptr) t.fail_missing("bodies", "[\"body_a\", \"body_b\"]");
  const auto* ba = bn->as_array();
  if (ba == nullptr || ba->size() != 2) {
    t.origins().fail(bn, t.field("bodies"),
                     TableReader::must_be("an array of 2 body names [\"body_a\", \"body_b\"]", *bn));
  }
  p.body_a = body_ref(t, *ba->get(0), t.field("bodies") + "[0]", c);
  p.body_b = body_ref(t, *ba->get(1), t.field("bodies") + "[1]", c);
  const Body& a = c.bodies[static_cast<std::size_t>(p.body_a)];
  const Body& b = c.bodies[static_cast<std::size_t>(p.body_b)];
  if (p.body_a == p.body_b) t.fail("bodies", fmt::format("a body cannot touch itself ('{}')", a.name));
  if (a.fixed && b.fixed) {
    t.fail("bodies", fmt::format("'{}' and '{}' are both fixed: they can never touch", a.name, b.name));
  }
  if (b.fixed) {
    t.fail("bodies", fmt::format("list the fixed body first: [\"{}\", \"{}\"] (the normal points "
                                 "from body_a to body_b)",
                                 b.name, a.name));
  }
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    const auto& q = c.contacts[k];
    if ((q.body_a == p.body_a && q.body_b == p.body_b) ||
        (q.body_a == p.body_b && q.body_b == p.body_a)) {
      t.fail("bodies", fmt::format("contacts[{}] '{}' already joins '{}' and '{}'", k, q.name,
                                   a.name, b.name));
    }
  }

  read_contact_law(t, {"name", "bodies"}, "contact", p.law, p.threshold_m, p.friction);
  return p;
}

// ---- [settings] --------------------------------------------------------------------

// a value as the text `--set` would give: strings bare, numbers shortest
// round-trip, arrays "[a, b]"
std::string setting_text(const toml::node& n) {
  if (const auto* s = n.as_string()) return s->get();
  if (const auto* a = n.as_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < a->size(); ++i) out += (i ? ", " : "") + setting_text(*a->get(i));
    return out + "]";
  }
  return internal::describe_value(n);
}

// flattens [settings] ("a.b" = v, or [settings.a] b = v) into (key, text)
void read_settings(const TableReader& t, const std::string& prefix,
                   std::vector<std::pair<std::string, std::string>>& out) {
  for (auto&& [k, v] : t.table()) {
    const std::string key = prefix + std::string(k.str());
    const std::string field = t.field(k.str());
    if (const auto* sub = v.as_table()) {
      read_settings(TableReader(*sub, field, t.origins()), key + ".", out);
      continue;
    }
    if (is_case_key(key)) {
      t.origins().fail(&v, field,
                       "a case key, not an engine setting: state it in [case], [[bodies]] or "
                       "[[contacts]]");
    }
    bool plain = !v.is_table() && !v.is_date() && !v.is_time() && !v.is_date_time();
    if (const auto* a = v.as_array()) {
      for (const auto& e : *a) plain = plain && (e.is_number() || e.is_string() || e.is_boolean());
    }
    if (!plain) {
      t.origins().fail(&v, field,
                       TableReader::must_be("a number, string, boolean or array of them", v));
    }
    out.emplace_back(key, setting_text(v));
  }
}

// ---- the whole case ------------------------------------------------------------------

// no body of a contact pair starts with its centre inside the other
// (internal/start_overlap.hpp says why); the error points at its position
void check_start_overlaps(const Case& c, const std::vector<TableReader>& bodies,
                          const internal::SceneTables& scene) {
  for (const ContactPair& cp : c.contacts) {
    for (const auto& [inner, outer] : {std::pair{cp.body_b, cp.body_a}, std::pair{cp.body_a, cp.body_b}}) {
      const Body& in = c.bodies[static_cast<std::size_t>(inner)];
      const Body& out = c.bodies[static_cast<std::size_t>(outer)];
      if (in.fixed && out.fixed) continue;                      // they never move
      if (std::holds_alternative<HalfPlane>(in.shape)) continue;  // no centre of mass
      const auto how = internal::point_inside_body(out, in.position_m);
      if (!how) continue;
      internal::fail_on_body(
          scene, c, bodies, inner, "position",
          fmt::format("the centre of '{}' ({:.6g}, {:.6g}) m starts inside '{}' ({}), its partner "
                      "in contact '{}': no engine can tell which way out (coincident or nested "
                      "bodies are pushed along an arbitrary axis, a centre below the ground falls "
                      "through); allowed: each centre outside the other body of its pairs (a "
                      "shallow overlap, a pre-loaded contact, is fine)",
                      in.name, in.position_m.x(), in.position_m.y(), out.name, *how, cp.name));
    }
  }
}

Case build_case(const toml::table& root, const Origins& origins) {
  const TableReader top(root, "", origins);
  top.only_keys(kTopKeys);
  Case c;
  const int default_outline_points = read_case_table(top.subtable("case"), c);

  const auto bodies = top.table_array("bodies");
  const auto generators = top.table_array("generate");
  if (bodies.empty() && generators.empty()) {
    top.fail_missing("bodies", "at least one [[bodies]] or [[generate]] table");
  }
  internal::BodyNames names;
  for (const auto& b : bodies) {
    if (c.bodies.size() >= static_cast<std::size_t>(internal::kMaxBodies)) {
      b.fail("name", fmt::format("more than {} bodies", internal::kMaxBodies));
    }
    c.bodies.push_back(read_body(b, default_outline_points, names));
    names.emplace(c.bodies.back().name, static_cast<int>(c.bodies.size()) - 1);
  }
  const internal::SceneTables scene{generators, top.table_array("contact_groups")};
  internal::read_generated_bodies(scene, default_outline_points, c, names);
  for (const auto& j : top.table_array("joints")) c.joints.push_back(read_joint(j, c));
  for (const auto& p : top.table_array("contacts")) c.contacts.push_back(read_contact(p, c));
  internal::read_contact_groups(scene, c, names);
  internal::place_resting_scenes(scene, c);
  check_start_overlaps(c, bodies, scene);
  internal::check_group_start_overlaps(scene, c, bodies);
  if (top.has("settings")) read_settings(top.subtable("settings"), "", c.settings);
  return c;
}

bool has_case_table(const std::filesystem::path& path) {
  // too large to be a case: listed, so that loading it says why
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) > kMaxCaseFileBytes && !ec) return true;
  try {
    const toml::table t = toml::parse_file(path.string());
    return t.get_as<toml::table>("case") != nullptr;
  } catch (const toml::parse_error&) {
    // a broken file that looks like a case is listed, so that loading it
    // reports the parse error instead of hiding the file
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
      const auto b = line.find_first_not_of(" \t");
      if (b != std::string::npos && line.compare(b, 6, "[case]") == 0) return true;
    }
    return false;
  }
}

}  // namespace

namespace internal {

Shape read_shape(const TableReader& s) {
  s.only_keys(kShapeKeys);
  const std::string type = s.word("type", kShapeTypes);
  if (type == "circle") {
    s.only_keys({"type", "radius"}, "of a circle");
    return Circle{s.real("radius", Range{kMinSize_m, kMaxSize_m}, "m")};
  }
  if (type == "ellipse") {
    s.only_keys({"type", "semi_axes"}, "of an ellipse");
    const auto ab = s.pair("semi_axes", Range{kMinSize_m, kMaxSize_m}, "m");
    return Ellipse{ab[0], ab[1]};
  }
  if (type == "polygon") {
    s.only_keys({"type", "points"}, "of a polygon");
    return read_polygon(s);
  }
  s.only_keys({"type", "extent"}, "of a halfplane");
  return HalfPlane{s.real_or("extent", 20.0, Range::positive(kMaxSize_m), "m")};
}

// mass and inertia of a moving body from mass | density and inertia
void read_mass_properties(const TableReader& t, Body& b) {
  const bool has_mass = t.has("mass");
  const bool has_density = t.has("density");
  if (has_mass && has_density) t.fail("density", "give mass (kg) or density (kg/m^2), not both");
  if (!has_mass && !has_density) {
    t.fail_missing("mass", "mass (kg, > 0) or density (kg/m^2, > 0): the body is not fixed");
  }

  // inertia: a number, or computed from the exact shape or from its outline
  std::string inertia_from = "shape";
  double inertia_kgm2 = 0.0;
  if (const toml::node* n = t.find("inertia")) {
    if (n->is_string()) {
      inertia_from = t.word_at(*n, t.field("inertia"), {"shape", "outline"});
    } else if (n->is_number()) {
      inertia_from = "number";
      inertia_kgm2 = t.real_at(*n, t.field("inertia"), Range::positive(), "kg m^2");
    } else {
      t.origins().fail(n, t.field("inertia"),
                       TableReader::must_be("a finite number > 0 (kg m^2), \"shape\" or \"outline\"",
                                            *n));
    }
  }
  const AreaProperties props = inertia_from == "outline"
                                   ? polygon_area_properties(make_outline(b.shape, b.outline_points))
                                   : shape_area_properties(b.shape);
  // J / A: the polar moment per unit mass of a uniform lamina, m^2
  const double gyration_m2 = props.polar_moment_centroid_m4 / props.area_m2;

  if (has_mass) {
    b.mass_kg = t.real("mass", Range::positive(), "kg");
  } else {
    const double density = t.real("density", Range::positive(), "kg/m^2");
    b.mass_kg = density * props.area_m2;
    if (!Range::positive().contains(b.mass_kg)) {
      t.fail("density", fmt::format("gives mass {} kg for area {} m^2: not a finite number > 0",
                                    b.mass_kg, props.area_m2));
    }
  }
  b.inertia_kgm2 = inertia_from == "number" ? inertia_kgm2 : b.mass_kg * gyration_m2;
  if (!Range::positive().contains(b.inertia_kgm2)) {
    t.fail("inertia", fmt::format("computes to {} kg m^2: not a finite number > 0", b.inertia_kgm2));
  }
}

void read_contact_law(const TableReader& t, const std::vector<std::string>& keys,
                      const std::string& what, ContactLaw& law_out, double& threshold_m,
                      double& friction) {
  auto own = [&](std::vector<std::string> law_keys) {
    law_keys.insert(law_keys.end(), keys.begin(), keys.end());
    return law_keys;
  };
  const std::string law = t.word("law", kLaws);
  threshold_m = t.real_or("threshold", 1e-10, Range::non_negative(kMaxThreshold_m), "m");
  friction = t.real_or("friction", 0.0, Range::non_negative(kMaxFriction));
  if (law == "kelvin_voigt") {
    t.only_keys(own(kKelvinVoigtKeys), "of a kelvin_voigt " + what);
    KelvinVoigt kv;
    kv.stiffness_n_per_m = t.real("stiffness", Range::positive(), "N/m");
    kv.damping_ns_per_m = t.real("damping", Range::non_negative(), "N s/m");
    kv.damping_depth_m = t.real_or("damping_depth", 0.0, Range::non_negative(kMaxSize_m), "m");
    law_out = kv;
    return;
  }
  const Range exponent_range{1.0, 3.0, true, false};
  if (law == "hertz") {
    t.only_keys(own(kHertzKeys), "of a hertz " + what);
    Hertz h;
    h.stiffness = read_hertz_stiffness(t, h.material);
    h.exponent = t.real_or("exponent", 1.5, exponent_range);
    law_out = h;
    return;
  }
  t.only_keys(own(with(kHertzKeys, "restitution")), "of a lankarani_nikravesh " + what);
  LankaraniNikravesh ln;
  ln.stiffness = read_hertz_stiffness(t, ln.material);
  ln.exponent = t.real_or("exponent", 1.5, exponent_range);
  ln.restitution = t.real("restitution", Range{0.0, 1.0, true, false});
  law_out = ln;
}

std::string body_name(const TableReader& t, std::string_view key) {
  std::string name = t.identifier(key);
  if (name.size() > kMaxBodyNameChars) {
    t.fail(key, fmt::format("'{}' has {} characters; a body name has at most {} (the results "
                            "file's name cells)",
                            name, name.size(), kMaxBodyNameChars));
  }
  return name;
}

}  // namespace internal

bool is_case_key(const std::string& key) {
  for (const auto& k : kCaseKeys) {
    if (key == k) return true;
  }
  const auto segs = internal::split_dotted(key);
  for (const auto& s : segs) {
    if (s.empty()) return false;
  }
  if (segs[0] == "contact") return segs.size() >= 2;
  if (segs[0] == "contacts" || segs[0] == "bodies" || segs[0] == "groups" ||
      segs[0] == "generate") {
    return segs.size() >= 3;
  }
  return false;
}

Case case_as_run(const CaseRuns& runs) {
  SettingsOverrides case_keys;
  for (const auto& [key, value] : runs.overrides) {
    if (is_case_key(key)) case_keys.set(key, value, SettingSource{"--set", 0});
  }
  return parse_case(runs.case_text, runs.case_path, runs.case_name, case_keys);
}

Case parse_case(std::string_view text, const std::string& source, const std::string& case_name,
                const SettingsOverrides& case_overrides) {
  toml::table root;
  try {
    root = toml::parse(text, std::string_view(source));
  } catch (const toml::parse_error& e) {
    throw InputError(source, static_cast<int>(e.source().begin.line), "",
                     std::string(e.description()));
  }
  // engine keys have no place here: the caller splits them off (is_case_key)
  for (const auto& [key, value] : case_overrides.all()) {
    if (!is_case_key(key)) {
      throw InputError(value.source.origin, value.source.line, key,
                       "not a case key (duration, output_interval, gravity, outline_points, "
                       "truth, contact.<field>, contacts.<name>.<field>, bodies.<name>.<field>)");
    }
  }
  Origins origins(source);
  internal::apply_case_overrides(root, case_overrides, origins);
  Case c = build_case(root, origins);
  c.name = case_name;
  c.source_path = source;
  c.source_text = std::string(text);
  return c;
}

Case load_case(const std::filesystem::path& path, const SettingsOverrides& case_overrides) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(path.string(), 0, "", "no such case file");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path.string(), 0, "", "is a directory, not a case file");
  }
  if (const auto bytes = std::filesystem::file_size(path, ec); !ec && bytes > kMaxCaseFileBytes) {
    throw InputError(path.string(), 0, "",
                     fmt::format("is {} bytes; a case file has at most {} bytes (8 MiB)", bytes,
                                 kMaxCaseFileBytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), 0, "", "cannot open the case file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_case(text.str(), path.string(), path.stem().string(), case_overrides);
}

std::vector<std::filesystem::path> resolve_cases(const std::string& spec,
                                                 const std::filesystem::path& cases_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;

  // every case of the folder, sorted by name
  std::vector<fs::path> all;
  if (fs::is_directory(cases_dir, ec)) {
    for (const auto& entry : fs::directory_iterator(cases_dir, ec)) {
      if (entry.is_regular_file(ec) && entry.path().extension() == ".toml" &&
          has_case_table(entry.path())) {
        all.push_back(entry.path());
      }
    }
  }
  std::sort(all.begin(), all.end(),
            [](const fs::path& a, const fs::path& b) { return a.stem().string() < b.stem().string(); });

  if (spec == "all") {
    if (!fs::is_directory(cases_dir, ec)) {
      throw InputError(cases_dir.string(), 0, "",
                       "no such cases folder; give --cases-dir (or $PLANARBENCH_CASES_DIR) a "
                       "folder of case files");
    }
    if (all.empty()) {
      throw InputError(cases_dir.string(), 0, "",
                       "holds no case files (*.toml with a [case] table); give --cases-dir (or "
                       "$PLANARBENCH_CASES_DIR) a folder of case files");
    }
    return all;
  }
  // the scenes (SPEC §11): their own folder, not in "all" (a pile of 1,000
  // bodies is minutes where a case is a second)
  const fs::path scenes_dir = cases_dir / "scenes";
  if (spec == "scenes") {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::directory_iterator(scenes_dir, ec)) {
      if (entry.is_regular_file(ec) && entry.path().extension() == ".toml" &&
          has_case_table(entry.path())) {
        scenes.push_back(entry.path());
      }
    }
    if (scenes.empty()) {
      throw InputError(scenes_dir.string(), 0, "", "holds no scene files (*.toml with a [case] table)");
    }
    std::sort(scenes.begin(), scenes.end(), [](const fs::path& a, const fs::path& b) {
      return a.stem().string() < b.stem().string();
    });
    return scenes;
  }
  const fs::path by_name = cases_dir / (spec + ".toml");
  if (!spec.empty() && spec.find('/') == std::string::npos && fs::is_regular_file(by_name, ec)) {
    return {by_name};
  }
  const fs::path scene_by_name = scenes_dir / (spec + ".toml");
  if (!spec.empty() && spec.find('/') == std::string::npos && fs::is_regular_file(scene_by_name, ec)) {
    return {scene_by_name};
  }
  if (fs::is_regular_file(fs::path(spec), ec)) return {fs::path(spec)};

  if (!fs::is_directory(cases_dir, ec)) {
    throw InputError("--case", 0, spec,
                     fmt::format("no such case file, and the cases folder '{}' does not exist; "
                                 "give a case file or a name in an existing cases folder",
                                 cases_dir.string()));
  }
  std::vector<std::string> names;
  for (const auto& p : all) names.push_back(p.stem().string());
  throw InputError("--case", 0, spec,
                   fmt::format("no such case or case file{}; cases in {}: {}, or all, or scenes "
                               "(the scenes of its scenes/ folder, each also by name)",
                               did_you_mean(spec, names), cases_dir.string(),
                               names.empty() ? "none" : join_words(names)));
}

}  // namespace pb
