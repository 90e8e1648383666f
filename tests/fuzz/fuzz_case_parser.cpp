// Fuzz target for core/src/case_loader.cpp (pb::parse_case): the bytes are a
// case file's text, optionally followed by a line "#--set" and then one
// KEY=VALUE override per line (what `--set` gives the loader).
//
// The contract fuzzed (case_loader.hpp, case.hpp): every input either gives a
// Case or throws pb::InputError naming the file or `--set KEY` and a line
// inside the text. Any other exception, a crash, a sanitizer report, or a Case
// that breaks what the loader promises (checked below, independently of the
// loader's own code) is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <variant>
#include <vector>

#include "fuzz_check.hpp"
#include "planarbench/case.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/outline.hpp"
#include "planarbench/settings.hpp"

namespace {

using pb::Vec2;

// the loader's documented limits (case_loader.cpp, cases/README.md)
constexpr double kMaxDuration_s = 1e4;        // s
constexpr double kMaxOutputSamples = 1e7;     // duration / output_interval
constexpr int kMaxOutlinePoints = 100000;
constexpr std::size_t kMaxPolygonPoints = 10000;
constexpr double kMaxSize_m = 1e4;            // m
constexpr double kMaxCoordinate_m = 1e6;      // m
constexpr double kMaxThreshold_m = 1e-3;      // m

// the line that separates the case text from the overrides
constexpr std::string_view kSetMarker = "\n#--set\n";

bool finite(double x) { return std::isfinite(x); }
bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }
bool positive(double x) { return std::isfinite(x) && x > 0.0; }

// [A-Za-z_][A-Za-z0-9_]*, at most 64 characters (case_loader.hpp, identifier)
bool is_identifier(const std::string& s) {
  if (s.empty() || s.size() > 64) return false;
  const auto alpha = [](char ch) { return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z'); };
  if (!alpha(s[0]) && s[0] != '_') return false;
  for (const char ch : s) {
    if (!alpha(ch) && !(ch >= '0' && ch <= '9') && ch != '_') return false;
  }
  return true;
}

// twice the signed area by the shoelace sum, written here apart from outline.cpp
double twice_signed_area(const std::vector<Vec2>& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    s += (a.x() - p[0].x()) * (b.y() - p[0].y()) - (b.x() - p[0].x()) * (a.y() - p[0].y());
  }
  return s;
}

int line_count(std::string_view text) {
  int n = 1;
  for (const char ch : text) n += ch == '\n' ? 1 : 0;
  return n;
}

// ---- the promises of a loaded case ------------------------------------------

void check_shape(const pb::Body& b) {
  if (const auto* c = std::get_if<pb::Circle>(&b.shape)) {
    PB_FUZZ_CHECK(positive(c->radius_m) && c->radius_m <= kMaxSize_m);
  } else if (const auto* e = std::get_if<pb::Ellipse>(&b.shape)) {
    PB_FUZZ_CHECK(positive(e->semi_axis_a_m) && e->semi_axis_a_m <= kMaxSize_m);
    PB_FUZZ_CHECK(positive(e->semi_axis_b_m) && e->semi_axis_b_m <= kMaxSize_m);
  } else if (const auto* p = std::get_if<pb::Polygon>(&b.shape)) {
    PB_FUZZ_CHECK(p->points_m.size() >= 3 && p->points_m.size() <= kMaxPolygonPoints);
    PB_FUZZ_CHECK(b.outline_points == static_cast<int>(p->points_m.size()));
    for (const auto& q : p->points_m) {
      PB_FUZZ_CHECK(finite(q) && std::abs(q.x()) <= kMaxCoordinate_m &&
                    std::abs(q.y()) <= kMaxCoordinate_m);
    }
    // counter-clockwise: positive area
    PB_FUZZ_CHECK(twice_signed_area(p->points_m) > 0.0);
  } else {
    const auto& h = std::get<pb::HalfPlane>(b.shape);
    PB_FUZZ_CHECK(positive(h.extent_m) && h.extent_m <= kMaxSize_m);
    PB_FUZZ_CHECK(b.fixed);
  }

  // its outline: as many finite points as the body says
  const std::vector<Vec2> outline = pb::make_outline(b.shape, b.outline_points);
  PB_FUZZ_CHECK(outline.size() == static_cast<std::size_t>(b.outline_points));
  for (const auto& q : outline) PB_FUZZ_CHECK(finite(q));
}

void check_body(const pb::Body& b) {
  PB_FUZZ_CHECK(is_identifier(b.name));
  PB_FUZZ_CHECK(b.outline_points >= 3 && b.outline_points <= kMaxOutlinePoints);
  PB_FUZZ_CHECK(finite(b.position_m) && std::abs(b.position_m.x()) <= kMaxCoordinate_m &&
                std::abs(b.position_m.y()) <= kMaxCoordinate_m);
  PB_FUZZ_CHECK(finite(b.angle_rad));
  if (b.fixed) {
    // fixed bodies never move and carry no mass (case.hpp)
    PB_FUZZ_CHECK(b.mass_kg == 0.0 && b.inertia_kgm2 == 0.0);
    PB_FUZZ_CHECK(b.velocity_mps == Vec2::Zero() && b.angular_velocity_radps == 0.0);
  } else {
    PB_FUZZ_CHECK(positive(b.mass_kg));
    PB_FUZZ_CHECK(positive(b.inertia_kgm2));
    PB_FUZZ_CHECK(finite(b.velocity_mps));
    PB_FUZZ_CHECK(finite(b.angular_velocity_radps));
  }
  check_shape(b);
}

void check_joint(const pb::Case& c, std::size_t k) {
  const pb::RevoluteJoint& j = c.joints[k];
  PB_FUZZ_CHECK(is_identifier(j.name));
  PB_FUZZ_CHECK(j.body >= 0 && static_cast<std::size_t>(j.body) < c.bodies.size());
  const pb::Body& b = c.bodies[static_cast<std::size_t>(j.body)];
  PB_FUZZ_CHECK(!b.fixed);
  PB_FUZZ_CHECK(finite(j.anchor_world_m) && finite(j.anchor_local_m));
  // one joint per body, one name per joint
  for (std::size_t i = 0; i < k; ++i) {
    PB_FUZZ_CHECK(c.joints[i].body != j.body && c.joints[i].name != j.name);
  }
  // the local anchor maps back to the world anchor at t = 0:
  // world = position + R(angle) local; rounding of a rotation of magnitude
  // |anchor| + |position| <= 3e6 m is ~1e-9 m, 1e-12 relative leaves margin
  const double ct = std::cos(b.angle_rad);
  const double st = std::sin(b.angle_rad);
  const Vec2 w(b.position_m.x() + ct * j.anchor_local_m.x() - st * j.anchor_local_m.y(),
               b.position_m.y() + st * j.anchor_local_m.x() + ct * j.anchor_local_m.y());
  const double scale = 1.0 + j.anchor_world_m.norm() + b.position_m.norm();
  PB_FUZZ_CHECK((w - j.anchor_world_m).norm() <= 1e-12 * scale);
}

void check_material(const pb::HertzMaterial& m, double stiffness) {
  PB_FUZZ_CHECK(positive(m.young_modulus_i_pa) && positive(m.young_modulus_j_pa));
  PB_FUZZ_CHECK(m.poisson_ratio_i >= -1.0 && m.poisson_ratio_i <= 0.5);
  PB_FUZZ_CHECK(m.poisson_ratio_j >= -1.0 && m.poisson_ratio_j <= 0.5);
  PB_FUZZ_CHECK(positive(m.radius_i_m) && m.radius_i_m <= kMaxSize_m);
  PB_FUZZ_CHECK(positive(m.radius_j_m) && m.radius_j_m <= kMaxSize_m);
  // K came from eq. 3 of these materials
  PB_FUZZ_CHECK(stiffness == pb::hertz_stiffness(m));
}

void check_contact(const pb::Case& c, std::size_t k) {
  const pb::ContactPair& p = c.contacts[k];
  const auto n = static_cast<int>(c.bodies.size());
  PB_FUZZ_CHECK(is_identifier(p.name));
  PB_FUZZ_CHECK(p.body_a >= 0 && p.body_a < n && p.body_b >= 0 && p.body_b < n);
  PB_FUZZ_CHECK(p.body_a != p.body_b);
  // the fixed body, if any, comes first (normal from a to b)
  PB_FUZZ_CHECK(!c.bodies[static_cast<std::size_t>(p.body_b)].fixed);
  PB_FUZZ_CHECK(p.threshold_m >= 0.0 && p.threshold_m <= kMaxThreshold_m);
  for (std::size_t i = 0; i < k; ++i) {
    const pb::ContactPair& q = c.contacts[i];
    PB_FUZZ_CHECK(q.name != p.name);
    PB_FUZZ_CHECK(!(q.body_a == p.body_a && q.body_b == p.body_b));
    PB_FUZZ_CHECK(!(q.body_a == p.body_b && q.body_b == p.body_a));
  }
  if (const auto* kv = std::get_if<pb::KelvinVoigt>(&p.law)) {
    PB_FUZZ_CHECK(positive(kv->stiffness_n_per_m));
    PB_FUZZ_CHECK(finite(kv->damping_ns_per_m) && kv->damping_ns_per_m >= 0.0);
    PB_FUZZ_CHECK(finite(kv->damping_depth_m) && kv->damping_depth_m >= 0.0);
  } else if (const auto* h = std::get_if<pb::Hertz>(&p.law)) {
    PB_FUZZ_CHECK(positive(h->stiffness));
    PB_FUZZ_CHECK(h->exponent >= 1.0 && h->exponent < 3.0);
    if (h->material) check_material(*h->material, h->stiffness);
  } else {
    const auto& ln = std::get<pb::LankaraniNikravesh>(p.law);
    PB_FUZZ_CHECK(positive(ln.stiffness));
    PB_FUZZ_CHECK(ln.exponent >= 1.0 && ln.exponent < 3.0);
    PB_FUZZ_CHECK(ln.restitution >= 0.0 && ln.restitution < 1.0);
    if (ln.material) check_material(*ln.material, ln.stiffness);
  }
}

void check_case(const pb::Case& c, std::string_view text, const std::string& source,
                const std::string& name) {
  PB_FUZZ_CHECK(c.name == name && c.source_path == source && c.source_text == text);
  PB_FUZZ_CHECK(c.description.find('\n') == std::string::npos);
  PB_FUZZ_CHECK(positive(c.duration_s) && c.duration_s <= kMaxDuration_s);
  PB_FUZZ_CHECK(positive(c.output_interval_s) && c.output_interval_s <= c.duration_s);
  PB_FUZZ_CHECK(c.duration_s / c.output_interval_s <= kMaxOutputSamples);
  // t = 0 and t = duration at least; at most 1e7 intervals (+1 for rounding)
  PB_FUZZ_CHECK(c.output_samples() >= 2 && c.output_samples() <= kMaxOutputSamples + 2);
  PB_FUZZ_CHECK(finite(c.gravity_mps2));

  PB_FUZZ_CHECK(!c.bodies.empty());
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    check_body(c.bodies[i]);
    for (std::size_t j = 0; j < i; ++j) PB_FUZZ_CHECK(c.bodies[j].name != c.bodies[i].name);
    PB_FUZZ_CHECK(c.body_index(c.bodies[i].name) == static_cast<int>(i));
  }
  for (std::size_t k = 0; k < c.joints.size(); ++k) check_joint(c, k);
  for (std::size_t k = 0; k < c.contacts.size(); ++k) check_contact(c, k);
  // engine settings only: case keys belong to [case], [[bodies]], [[contacts]]
  for (const auto& [key, value] : c.settings) {
    PB_FUZZ_CHECK(!key.empty() && !pb::is_case_key(key));
  }
}

// "KEY=VALUE" lines after the marker; lines without '=' are skipped
pb::SettingsOverrides read_overrides(std::string_view lines) {
  pb::SettingsOverrides out;
  while (!lines.empty()) {
    const std::size_t end = lines.find('\n');
    const std::string_view line = lines.substr(0, end);
    lines = end == std::string_view::npos ? std::string_view() : lines.substr(end + 1);
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos) continue;
    out.set(std::string(line.substr(0, eq)), std::string(line.substr(eq + 1)),
            pb::SettingSource{"--set", 0});
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t marker = input.find(kSetMarker);
  const std::string_view text = input.substr(0, marker);
  const std::string source = "fuzz.toml";
  const std::string name = "fuzz";

  pb::SettingsOverrides overrides;
  if (marker != std::string_view::npos) {
    overrides = read_overrides(input.substr(marker + kSetMarker.size()));
    // the loader takes only case keys (the caller splits the others off)
    for (const auto& [key, value] : overrides.all()) {
      if (!pb::is_case_key(key)) return 0;
    }
  }

  // with PB_FUZZ_VERBOSE set: what the loader said, for triage
  static const bool verbose = std::getenv("PB_FUZZ_VERBOSE") != nullptr;
  try {
    const pb::Case c = pb::parse_case(text, source, name, overrides);
    check_case(c, text, source, name);
    if (verbose) std::fprintf(stderr, "loaded: %zu bodies\n", c.bodies.size());
  } catch (const pb::InputError& e) {
    if (verbose) std::fprintf(stderr, "InputError: %s\n", e.what());
    // the expected outcome for bad input: it says where and what
    PB_FUZZ_CHECK(std::string_view(e.what()).size() > 0);
    PB_FUZZ_CHECK(e.file() == source || e.file().rfind("--set ", 0) == 0);
    PB_FUZZ_CHECK(e.line() >= 0);
    if (e.file() == source) PB_FUZZ_CHECK(e.line() <= line_count(text));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception %s: %s\n", typeid(e).name(), e.what());
    __builtin_trap();
  }
  return 0;
}
