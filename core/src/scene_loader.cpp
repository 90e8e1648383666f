// [[generate]] and [[contact_groups]] (internal/scene_loader.hpp).
#include "internal/scene_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "internal/case_fields.hpp"
#include "internal/start_overlap.hpp"
#include "planarbench/broad_phase.hpp"
#include "planarbench/contact_pairs.hpp"
#include "planarbench/did_you_mean.hpp"

namespace pb::internal {

namespace {

// at most this many bodies in one generator, rows of a pyramid (R (R + 1) / 2
// bodies: 447 rows are 100128, past kMaxBodies anyway)
constexpr int kMaxGeneratedCount = kMaxBodies;
constexpr int kMaxPyramidRows = 446;

const std::vector<std::string> kKinds = {"stack", "pyramid", "row", "grid"};
const std::vector<std::string> kCommonKeys = {"kind", "name", "shape", "mass", "density",
                                              "inertia", "outline_points"};
const std::vector<std::string> kStackKeys = {"count", "on", "at", "gap", "start", "velocity",
                                             "angular_velocity"};
const std::vector<std::string> kPyramidKeys = {"rows", "on", "at", "gap", "start"};
const std::vector<std::string> kRowKeys = {"count", "first", "direction", "gap", "angle",
                                           "velocity", "angular_velocity", "first_velocity"};
const std::vector<std::string> kGridKeys = {"count",  "columns", "origin", "spacing",
                                            "jitter", "angle",   "angle_jitter", "seed",
                                            "shapes", "velocity", "angular_velocity"};
const std::vector<std::string> kGroupKeys = {
    "name",          "bodies",    "law",      "stiffness",   "damping",
    "damping_depth", "threshold", "exponent", "restitution", "young_modulus",
    "poisson_ratio", "radius",    "friction"};

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

SceneKind kind_of(const std::string& word) {
  if (word == "stack") return SceneKind::stack;
  if (word == "pyramid") return SceneKind::pyramid;
  if (word == "row") return SceneKind::row;
  return SceneKind::grid;
}

// m, the farthest reach of a shape turned by `angle` along the world unit
// direction d (its support function): max over the shape of p . d
double reach_along(const Shape& shape, double angle_rad, const Vec2& d) {
  // the direction in the body frame
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  const Vec2 local(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  if (const auto* circle = std::get_if<Circle>(&shape)) return circle->radius_m;
  if (const auto* e = std::get_if<Ellipse>(&shape)) {
    return std::hypot(e->semi_axis_a_m * local.x(), e->semi_axis_b_m * local.y());
  }
  double best = -std::numeric_limits<double>::infinity();
  for (const Vec2& p : std::get<Polygon>(shape).points_m) best = std::max(best, p.dot(local));
  return best;
}

// splitmix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014): the same sequence on every machine and standard
// library, which std::uniform_real_distribution does not promise
class SeededUniform {
 public:
  explicit SeededUniform(std::uint64_t seed) : state_(seed) {}
  // uniform in [-1, 1)
  double symmetric() {
    state_ += 0x9E3779B97F4A7C15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return 2.0 * (static_cast<double>(z >> 11) * 0x1.0p-53) - 1.0;
  }

 private:
  std::uint64_t state_;
};

// a fixed half-plane named by `key`, the body a stack or pyramid stands on
int support_body(const TableReader& t, const Case& c, const BodyNames& names) {
  const std::string name = t.string("on");
  const auto it = names.find(name);
  if (it == names.end() || !std::holds_alternative<HalfPlane>(c.bodies[static_cast<std::size_t>(it->second)].shape)) {
    std::vector<std::string> planes;
    for (const Body& b : c.bodies) {
      if (std::holds_alternative<HalfPlane>(b.shape)) planes.push_back(b.name);
    }
    t.fail("on", fmt::format("must name a fixed halfplane body the {} stands on (got {}{}); "
                             "halfplanes: {}",
                             t.string("kind"), echo_value(name), did_you_mean(name, planes),
                             planes.empty() ? "none" : join_words(planes)));
  }
  return it->second;
}

// the support's frame: origin, tangent (its surface direction) and outward normal
struct SupportFrame {
  Vec2 origin = Vec2::Zero();
  Vec2 tangent = Vec2(1.0, 0.0);
  Vec2 normal = Vec2(0.0, 1.0);
  double angle_rad = 0.0;
};
SupportFrame frame_of(const Body& plane) {
  SupportFrame f;
  f.origin = plane.position_m;
  f.angle_rad = plane.angle_rad;
  f.tangent = Vec2(std::cos(plane.angle_rad), std::sin(plane.angle_rad));
  f.normal = Vec2(-std::sin(plane.angle_rad), std::cos(plane.angle_rad));
  return f;
}

// one body of a generator: its shape, mass properties, outline points and
// velocities from the table; the caller places it
Body make_body(const TableReader& t, const Shape& shape, int default_outline_points) {
  Body b;
  b.shape = shape;
  if (std::holds_alternative<HalfPlane>(shape)) {
    t.fail("shape", "a halfplane has no finite area or mass: generated bodies move; declare a "
                    "fixed halfplane in [[bodies]]");
  }
  if (const auto* p = std::get_if<Polygon>(&shape)) {
    if (t.has("outline_points")) {
      t.fail("outline_points", "a polygon's outline is its own points: remove outline_points");
    }
    b.outline_points = static_cast<int>(p->points_m.size());
  } else {
    b.outline_points = t.integer_or("outline_points", default_outline_points, 3, kMaxOutlinePoints);
  }
  read_mass_properties(t, b);
  b.velocity_mps = t.vec2_or("velocity", Vec2::Zero(), Range::any(), "m/s");
  b.angular_velocity_radps = t.real_or("angular_velocity", 0.0, Range::any(), "rad/s");
  return b;
}

SceneStart read_start(const TableReader& t) {
  return t.word_or("start", "touching", {"touching", "resting"}) == "resting" ? SceneStart::resting
                                                                             : SceneStart::touching;
}

void place_stack(const TableReader& t, const Case& c, const BodyNames& names, GeneratedBodies& g,
                 std::vector<Body>& made, const Shape& shape, int default_outline_points) {
  if (!t.has("count")) t.fail_missing("count", fmt::format("the number of bodies, 1 to {}", kMaxGeneratedCount));
  g.count = t.integer_or("count", 0, 1, kMaxGeneratedCount);
  g.support = support_body(t, c, names);
  g.start = read_start(t);
  g.gap_m = t.real_or("gap", 0.0, Range::non_negative(kMaxSize_m), "m");
  if (g.start == SceneStart::resting && g.gap_m > 0.0) {
    t.fail("gap", "a resting stack presses every interface: give gap = 0 or start = \"touching\"");
  }
  const SupportFrame f = frame_of(c.bodies[static_cast<std::size_t>(g.support)]);
  const double at = t.real_or("at", 0.0, Range::magnitude(kMaxCoordinate_m), "m");
  // heights of the centres above the surface, the touching pose
  const double below = reach_along(shape, f.angle_rad, -f.normal);
  const double above = reach_along(shape, f.angle_rad, f.normal);
  double h = below + g.gap_m;
  for (int k = 0; k < g.count; ++k) {
    Body b = make_body(t, shape, default_outline_points);
    b.angle_rad = f.angle_rad;
    b.position_m = f.origin + at * f.tangent + h * f.normal;
    made.push_back(std::move(b));
    h += above + g.gap_m + below;
  }
}

void place_pyramid(const TableReader& t, const Case& c, const BodyNames& names,
                   GeneratedBodies& g, std::vector<Body>& made, const Shape& shape,
                   int default_outline_points) {
  if (!t.has("rows")) t.fail_missing("rows", fmt::format("the rows, 1 to {}", kMaxPyramidRows));
  g.rows = t.integer_or("rows", 1, 1, kMaxPyramidRows);
  g.support = support_body(t, c, names);
  g.start = read_start(t);
  g.gap_m = t.real_or("gap", 0.0, Range::non_negative(kMaxSize_m), "m");
  const SupportFrame f = frame_of(c.bodies[static_cast<std::size_t>(g.support)]);
  const double at = t.real_or("at", 0.0, Range::magnitude(kMaxCoordinate_m), "m");
  const double below = reach_along(shape, f.angle_rad, -f.normal);
  const double above = reach_along(shape, f.angle_rad, f.normal);
  const double left = reach_along(shape, f.angle_rad, -f.tangent);
  const double right = reach_along(shape, f.angle_rad, f.tangent);
  const double pitch = left + right + g.gap_m;  // m, centre to centre within a row
  for (int r = 0; r < g.rows; ++r) {
    const int n = g.rows - r;
    const double h = below + r * (below + above);
    for (int i = 0; i < n; ++i) {
      // centred on `at`: offsets (i - (n - 1) / 2) pitches
      const double x = at + (static_cast<double>(i) - 0.5 * static_cast<double>(n - 1)) * pitch;
      Body b = make_body(t, shape, default_outline_points);
      b.angle_rad = f.angle_rad;
      b.position_m = f.origin + x * f.tangent + h * f.normal;
      made.push_back(std::move(b));
    }
  }
  g.count = g.rows * (g.rows + 1) / 2;
}

void place_row(const TableReader& t, GeneratedBodies& g, std::vector<Body>& made,
               const Shape& shape, int default_outline_points) {
  if (!t.has("count")) t.fail_missing("count", fmt::format("the number of bodies, 1 to {}", kMaxGeneratedCount));
  g.count = t.integer_or("count", 0, 1, kMaxGeneratedCount);
  g.start = SceneStart::given;
  g.gap_m = t.real_or("gap", 0.0, Range::non_negative(kMaxSize_m), "m");
  const Vec2 first = t.vec2("first", Range::magnitude(kMaxCoordinate_m), "m");
  Vec2 d = t.vec2_or("direction", Vec2(1.0, 0.0), Range::magnitude(kMaxCoordinate_m));
  if (!(d.norm() > 0.0)) t.fail("direction", "must not be [0, 0]: the direction along the row");
  d.normalize();
  const double angle = t.real_or("angle", 0.0, Range::any(), "rad");
  const double back = reach_along(shape, angle, -d);
  const double front = reach_along(shape, angle, d);
  const bool has_first_velocity = t.has("first_velocity");
  const Vec2 first_velocity = t.vec2_or("first_velocity", Vec2::Zero(), Range::any(), "m/s");
  for (int k = 0; k < g.count; ++k) {
    Body b = make_body(t, shape, default_outline_points);
    b.angle_rad = angle;
    b.position_m = first + static_cast<double>(k) * (front + g.gap_m + back) * d;
    if (k == 0 && has_first_velocity) b.velocity_mps = first_velocity;
    made.push_back(std::move(b));
  }
}

void place_grid(const TableReader& t, GeneratedBodies& g, std::vector<Body>& made,
                const std::vector<Shape>& shapes, int default_outline_points) {
  if (!t.has("count")) t.fail_missing("count", fmt::format("the number of bodies, 1 to {}", kMaxGeneratedCount));
  g.count = t.integer_or("count", 0, 1, kMaxGeneratedCount);
  g.start = SceneStart::given;
  const int default_columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(g.count))));
  const int columns = t.integer_or("columns", default_columns, 1, kMaxGeneratedCount);
  const Vec2 origin = t.vec2("origin", Range::magnitude(kMaxCoordinate_m), "m");
  const Vec2 spacing = t.vec2("spacing", Range::magnitude(kMaxCoordinate_m), "m");
  const double jitter = t.real_or("jitter", 0.0, Range::non_negative(kMaxSize_m), "m");
  const double angle = t.real_or("angle", 0.0, Range::any(), "rad");
  const double angle_jitter = t.real_or("angle_jitter", 0.0, Range::non_negative(std::numbers::pi), "rad");
  const int seed = t.integer_or("seed", 1, 0, std::numeric_limits<int>::max());
  SeededUniform uniform(static_cast<std::uint64_t>(seed));
  for (int k = 0; k < g.count; ++k) {
    Body b = make_body(t, shapes[static_cast<std::size_t>(k) % shapes.size()], default_outline_points);
    const int col = k % columns;
    const int row = k / columns;
    // three draws a body, in this order, whatever is zero: a body's draws do
    // not depend on the others' settings
    const double jx = uniform.symmetric();
    const double jy = uniform.symmetric();
    const double ja = uniform.symmetric();
    b.position_m = origin + Vec2(col * spacing.x(), row * spacing.y()) + jitter * Vec2(jx, jy);
    b.angle_rad = angle + angle_jitter * ja;
    made.push_back(std::move(b));
  }
}

// the shapes of a grid: `shape`, or the `shapes` array taken in turn
std::vector<Shape> read_shapes(const TableReader& t, bool many_allowed) {
  if (t.has("shape") && t.has("shapes")) t.fail("shapes", "give shape or shapes, not both");
  if (!t.has("shapes") || !many_allowed) return {read_shape(t.subtable("shape"))};
  std::vector<Shape> out;
  for (const TableReader& s : t.table_array("shapes")) out.push_back(read_shape(s));
  if (out.empty()) t.fail("shapes", "must hold at least one shape table");
  return out;
}

// the law's compression at rest under a load F: delta with F_law(delta, 0) = F
double resting_penetration_m(const ContactLaw& law, double load_n) {
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) return load_n / kv->stiffness_n_per_m;
  if (const auto* h = std::get_if<Hertz>(&law)) return std::pow(load_n / h->stiffness, 1.0 / h->exponent);
  const auto& ln = std::get<LankaraniNikravesh>(law);
  return std::pow(load_n / ln.stiffness, 1.0 / ln.exponent);
}

}  // namespace

void read_generated_bodies(const SceneTables& scene, int default_outline_points, Case& c,
                           BodyNames& names) {
  for (const TableReader& t : scene.generators) {
    t.only_keys(joined(joined(kCommonKeys, kStackKeys),
                       joined(joined(kPyramidKeys, kRowKeys), kGridKeys)));
    GeneratedBodies g;
    g.name = t.identifier("name");
    g.kind = kind_of(t.word("kind", kKinds));
    const std::string kind_word = scene_kind_name(g.kind);
    const std::vector<std::string>& own = g.kind == SceneKind::stack     ? kStackKeys
                                          : g.kind == SceneKind::pyramid ? kPyramidKeys
                                          : g.kind == SceneKind::row     ? kRowKeys
                                                                         : kGridKeys;
    t.only_keys(joined(kCommonKeys, own), "of a " + kind_word);
    for (const GeneratedBodies& other : c.generated) {
      if (other.name == g.name) t.fail("name", fmt::format("duplicate generator name '{}'", g.name));
    }
    const std::vector<Shape> shapes = read_shapes(t, g.kind == SceneKind::grid);
    std::vector<Body> made;
    switch (g.kind) {
      case SceneKind::stack: place_stack(t, c, names, g, made, shapes[0], default_outline_points); break;
      case SceneKind::pyramid: place_pyramid(t, c, names, g, made, shapes[0], default_outline_points); break;
      case SceneKind::row: place_row(t, g, made, shapes[0], default_outline_points); break;
      case SceneKind::grid: place_grid(t, g, made, shapes, default_outline_points); break;
    }
    if (c.bodies.size() + made.size() > static_cast<std::size_t>(kMaxBodies)) {
      t.fail(g.kind == SceneKind::pyramid ? "rows" : "count",
             fmt::format("makes {} bodies, {} in all with the case's others; at most {}",
                         made.size(), c.bodies.size() + made.size(), kMaxBodies));
    }
    const std::string last = fmt::format("{}_{}", g.name, made.size());
    if (last.size() > kMaxBodyNameChars) {
      t.fail("name", fmt::format("gives body names up to '{}', {} characters; a body name has at "
                                 "most {} (the results file's name cells)",
                                 last, last.size(), kMaxBodyNameChars));
    }
    g.first_body = static_cast<int>(c.bodies.size());
    for (std::size_t k = 0; k < made.size(); ++k) {
      Body& b = made[k];
      b.name = fmt::format("{}_{}", g.name, k + 1);
      if (b.position_m.cwiseAbs().maxCoeff() > kMaxCoordinate_m || !b.position_m.allFinite()) {
        t.fail(g.kind == SceneKind::grid ? "spacing" : "gap",
               fmt::format("places body '{}' at ({:.6g}, {:.6g}) m, beyond the +-{:g} m of any "
                           "coordinate",
                           b.name, b.position_m.x(), b.position_m.y(), kMaxCoordinate_m));
      }
      if (const auto it = names.find(b.name); it != names.end()) {
        t.fail("name", fmt::format("makes body '{}', a name bodies[{}] already has", b.name,
                                   it->second));
      }
      names.emplace(b.name, static_cast<int>(c.bodies.size()));
      c.bodies.push_back(std::move(b));
    }
    c.generated.push_back(g);
  }
}

void read_contact_groups(const SceneTables& scene, Case& c, const BodyNames& names) {
  for (std::size_t gi = 0; gi < scene.groups.size(); ++gi) {
    const TableReader& t = scene.groups[gi];
    t.only_keys(kGroupKeys);
    ContactGroup g;
    g.name = t.identifier("name");
    for (const ContactGroup& other : c.contact_groups) {
      if (other.name == g.name) t.fail("name", fmt::format("duplicate contact group name '{}'", g.name));
    }
    // members: body names, or generator names standing for their bodies
    const toml::node* bn = t.find("bodies");
    if (bn == nullptr || bn->as_array() == nullptr) {
      t.fail_missing("bodies", "an array of body or [[generate]] names");
    }
    const auto& arr = *bn->as_array();
    for (std::size_t k = 0; k < arr.size(); ++k) {
      const std::string field = fmt::format("{}[{}]", t.field("bodies"), k);
      const std::string name = t.string_at(*arr.get(k), field);
      bool found = false;
      for (const GeneratedBodies& gen : c.generated) {
        if (gen.name != name) continue;
        for (int i = 0; i < gen.count; ++i) g.bodies.push_back(gen.body(i));
        found = true;
      }
      if (!found) {
        const auto it = names.find(name);
        if (it == names.end()) {
          std::vector<std::string> known;
          for (const GeneratedBodies& gen : c.generated) known.push_back(gen.name);
          for (const Body& b : c.bodies) {
            if (known.size() < 40) known.push_back(b.name);
          }
          t.origins().fail(arr.get(k), field,
                           fmt::format("no body or [[generate]] named {}{}; some names: {}",
                                       echo_value(name), did_you_mean(name, known), join_words(known)));
        }
        g.bodies.push_back(it->second);
      }
    }
    std::sort(g.bodies.begin(), g.bodies.end());
    if (const auto dup = std::adjacent_find(g.bodies.begin(), g.bodies.end()); dup != g.bodies.end()) {
      t.fail("bodies", fmt::format("names body '{}' twice (directly or through its generator)",
                                   c.bodies[static_cast<std::size_t>(*dup)].name));
    }
    int moving = 0;
    for (const int i : g.bodies) moving += c.bodies[static_cast<std::size_t>(i)].fixed ? 0 : 1;
    if (g.bodies.size() < 2 || moving == 0) {
      t.fail("bodies", "must hold at least two bodies, one of them moving: a group's pairs touch");
    }
    read_contact_law(t, {"name", "bodies"}, "contact group", g.law, g.threshold_m, g.friction);
    // a pair of bodies takes one rule: no two groups share two bodies, one moving
    for (std::size_t o = 0; o < c.contact_groups.size(); ++o) {
      const ContactGroup& other = c.contact_groups[o];
      std::vector<int> common;
      std::set_intersection(g.bodies.begin(), g.bodies.end(), other.bodies.begin(),
                            other.bodies.end(), std::back_inserter(common));
      int common_moving = -1;
      for (const int i : common) {
        if (!c.bodies[static_cast<std::size_t>(i)].fixed) common_moving = i;
      }
      if (common.size() >= 2 && common_moving >= 0) {
        const int partner = common[0] == common_moving ? common[1] : common[0];
        t.fail("bodies",
               fmt::format("shares bodies '{}' and '{}' with contact_groups[{}] '{}': a pair of "
                           "bodies takes one group's law; split the groups (a declared "
                           "[[contacts]] pair overrides a group for its two bodies)",
                           c.bodies[static_cast<std::size_t>(partner)].name,
                           c.bodies[static_cast<std::size_t>(common_moving)].name, o, other.name));
      }
    }
    c.contact_groups.push_back(std::move(g));
  }
}

void place_resting_scenes(const SceneTables& scene, Case& c) {
  if (c.generated.empty()) return;
  const ContactPairs rules(c);
  for (std::size_t gi = 0; gi < c.generated.size(); ++gi) {
    const GeneratedBodies& g = c.generated[gi];
    if (g.start != SceneStart::resting) continue;
    const TableReader& t = scene.generators[gi];
    if (g.kind == SceneKind::pyramid) {
      t.fail("start", "\"resting\" is not available for a pyramid: its static pose needs a "
                      "static solve of the whole pyramid; give start = \"touching\"");
    }
    const Body& plane = c.bodies[static_cast<std::size_t>(g.support)];
    const SupportFrame f = frame_of(plane);
    // the load along the normal: gravity must act along it (else friction
    // would hold the stack and its pose would not be the law's alone)
    const double g_normal = -c.gravity_mps2.dot(f.normal);
    const double g_tangent = c.gravity_mps2.dot(f.tangent);
    if (!(g_normal > 0.0) || std::abs(g_tangent) > 1e-12 * c.gravity_mps2.norm()) {
      t.fail("start", fmt::format("\"resting\" needs gravity along the inward normal of '{}' "
                                  "(gravity ({:g}, {:g}) m/s^2, normal ({:.6g}, {:.6g}))",
                                  plane.name, c.gravity_mps2.x(), c.gravity_mps2.y(),
                                  f.normal.x(), f.normal.y()));
    }
    // the law of each interface, from the support up
    auto law_between = [&](int lower, int upper) -> const ContactLaw& {
      const int k = rules.find(lower, upper);
      if (k >= 0) return rules[k].law;
      const int grp = rules.group_of(lower, upper);
      if (grp < 0) {
        t.fail("start", fmt::format("\"resting\" presses '{}' on '{}', but no [[contacts]] pair "
                                    "or [[contact_groups]] lets them touch",
                                    c.bodies[static_cast<std::size_t>(upper)].name,
                                    c.bodies[static_cast<std::size_t>(lower)].name));
      }
      return c.contact_groups[static_cast<std::size_t>(grp)].law;
    };
    // weight carried by each interface: everything above it
    double above_n = 0.0;
    std::vector<double> load_n(static_cast<std::size_t>(g.count));
    for (int k = g.count - 1; k >= 0; --k) {
      above_n += c.bodies[static_cast<std::size_t>(g.body(k))].mass_kg * g_normal;
      load_n[static_cast<std::size_t>(k)] = above_n;  // interface below body k
    }
    // shift each body down by the compressions below it
    double sink_m = 0.0;
    for (int k = 0; k < g.count; ++k) {
      const int lower = k == 0 ? g.support : g.body(k - 1);
      sink_m += resting_penetration_m(law_between(lower, g.body(k)), load_n[static_cast<std::size_t>(k)]);
      Body& b = c.bodies[static_cast<std::size_t>(g.body(k))];
      b.position_m -= sink_m * f.normal;
    }
  }
}

void fail_on_body(const SceneTables& scene, const Case& c,
                  const std::vector<TableReader>& body_tables, int i, const std::string& field,
                  const std::string& what) {
  if (static_cast<std::size_t>(i) < body_tables.size()) {
    body_tables[static_cast<std::size_t>(i)].fail(field, what);
  }
  for (std::size_t g = 0; g < c.generated.size(); ++g) {
    const GeneratedBodies& gen = c.generated[g];
    if (i < gen.first_body || i >= gen.first_body + gen.count) continue;
    const TableReader& t = scene.generators[g];
    const char* placement = gen.kind == SceneKind::grid  ? "spacing"
                            : gen.kind == SceneKind::row ? "gap"
                                                         : "start";
    t.fail(placement, fmt::format("body '{}' (made by this [[generate]]): {}",
                                  c.bodies[static_cast<std::size_t>(i)].name, what));
  }
  throw InputError("", 0, field, what);
}

void check_group_start_overlaps(const SceneTables& scene, const Case& c,
                                const std::vector<TableReader>& body_tables) {
  if (c.contact_groups.empty()) return;
  const ContactPairs rules(c);
  auto refuse = [&](int inner, int outer, const std::string& how, const std::string& group) {
    const Body& in = c.bodies[static_cast<std::size_t>(inner)];
    fail_on_body(scene, c, body_tables, inner, "position",
                 fmt::format("the centre of '{}' ({:.6g}, {:.6g}) m starts inside '{}' ({}), a "
                             "partner of contact group '{}': no engine can tell which way out; "
                             "allowed: each centre outside the other body of its pairs (a shallow "
                             "overlap, a pre-loaded contact, is fine)",
                             in.name, in.position_m.x(), in.position_m.y(),
                             c.bodies[static_cast<std::size_t>(outer)].name, how, group));
  };
  auto check = [&](int i, int j) {
    if (rules.find(i, j) >= 0) return;  // a declared pair: checked with the declared ones
    const int grp = rules.group_of(i, j);
    if (grp < 0) return;
    const std::string& group = c.contact_groups[static_cast<std::size_t>(grp)].name;
    for (const auto& [inner, outer] : {std::pair{i, j}, std::pair{j, i}}) {
      const Body& in = c.bodies[static_cast<std::size_t>(inner)];
      if (in.fixed || std::holds_alternative<HalfPlane>(in.shape)) continue;
      if (const auto how = point_inside_body(c.bodies[static_cast<std::size_t>(outer)], in.position_m)) {
        refuse(inner, outer, *how, group);
      }
    }
  };
  // half-planes against every body of their groups; the rest by their boxes
  std::vector<Aabb> boxes;
  std::vector<int> ids;
  std::vector<bool> seen(c.bodies.size(), false);
  for (const ContactGroup& g : c.contact_groups) {
    for (const int i : g.bodies) {
      if (seen[static_cast<std::size_t>(i)]) continue;
      seen[static_cast<std::size_t>(i)] = true;
      const Body& b = c.bodies[static_cast<std::size_t>(i)];
      if (std::holds_alternative<HalfPlane>(b.shape)) {
        for (const int j : g.bodies) {
          if (j != i) check(i, j);
        }
        continue;
      }
      boxes.push_back(shape_aabb(b.shape, b.position_m, b.angle_rad));
      ids.push_back(i);
    }
  }
  std::vector<std::pair<int, int>> pairs;
  std::vector<int> order;
  overlapping_pairs(boxes, ids, pairs, order);
  for (const auto& [i, j] : pairs) check(i, j);
}

}  // namespace pb::internal
