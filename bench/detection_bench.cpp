// The cost of one contact detection on outlines, registered at run time as
// detection/<method>/<configuration>/N:<points>:
//   brute        OutlineContactSearch::evaluate (every point against every edge)
//   default_cold PairGeometry::evaluate with detection=fast, the engine's
//                default, without history: for this pair (a disk on a
//                half-plane) the closed form of convex_line_contact.hpp
//   default_warm the same along the pose sequence (the engine's case)
//   fast_cold    FastOutlineContactSearch::evaluate without history (as a fresh
//                search object; the object itself is built once, outside the
//                timing: building it builds the trees, O(N log N), not a detection)
//   fast_warm    the same along the pose sequence, each call seeded by the last
//                (temporal coherence)
//   paper_two_stage  place_outline of both bodies + paper_two_stage_distance
//                (the paper's closest point pair, then its adjacent edges);
//                meaningful apart only: in contact it still runs its O(N M)
//                first stage, which is its whole cost
// for N = 45 .. 1440 points on both outlines, in two configurations of the
// falling_ball case (cases/falling_ball.toml: disk radius 0.5 m on ground
// declined 30 deg, represented by a 40 m surface segment):
//   near_contact  gap 1 mm (the steps before the impact)
//   in_contact    pressed in by the first impact's peak penetration, computed
//                 from the case (about 57 mm: ~15 % of the disk's points inside)
//
// Each iteration evaluates one pose of a sequence of 64 slowly moving poses
// (the disk slides 10 um and turns 1e-4 rad per step, there and back), the
// way an integrator asks for them; all methods walk the same sequence.
// Counters: detections_per_s (a rate: one detection per iteration) and N.
#include <benchmark/benchmark.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "bench_errors.hpp"
#include "deferred_registration.hpp"
#include "planarbench/case.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/reference/fast_outline_contact.hpp"
#include "planarbench/reference/outline_contact.hpp"
#include "planarbench/reference/pair_geometry.hpp"

namespace pb::bench {

namespace {

constexpr int kPoses = 64;             // poses in the sequence (there and back)
constexpr double kSlideStepM = 1e-5;   // m, disk motion along the ground per pose
constexpr double kTurnStepRad = 1e-4;  // rad, disk rotation per pose
constexpr double kNearGapM = 1e-3;     // m, near_contact gap

// The falling_ball scene: ground and disk, and the disk's poses.
struct Scene {
  Body ground_body;
  Body disk_body;
  Shape ground_shape;
  Shape disk_shape;
  Pose ground;
  std::vector<Pose> disk;  // kPoses poses
};

// The first impact's peak penetration, m: the disk falls from rest onto the
// line, arriving with normal speed v_n; a Kelvin-Voigt contact (paper eq. 1)
// is then a damped oscillator m delta'' + c delta' + K delta = 0 from
// delta = 0, delta' = v_n, whose first maximum is
//   delta_max = (v_n / w_n) exp(-zeta / sqrt(1 - zeta^2) atan(sqrt(1 - zeta^2) / zeta)),
// w_n = sqrt(K / m), zeta = c / (2 sqrt(K m)) (the underdamped response, e.g.
// S. S. Rao, Mechanical Vibrations, §2.6; gravity's static offset m g_n / K
// = 0.85 mm is left out: a figure, not a truth).
double peak_penetration_m(const Case& c, const Body& ground, const Body& ball, double radius_m) {
  const auto* kv = std::get_if<KelvinVoigt>(&c.contacts.at(0).law);
  if (!kv) throw InputError(c.source_path, 0, "contacts", "falling_ball's law is not kelvin_voigt");
  const Vec2 n = Pose{ground.position_m, ground.angle_rad}.rotation() * Vec2(0.0, 1.0);
  // falling along gravity, the gap closes at |g| n . (-g_hat) per unit speed
  const double g = c.gravity_mps2.norm();
  const double closing = n.dot(-c.gravity_mps2 / g);  // -, cos 30 deg
  const double gap_m = n.dot(ball.position_m - ground.position_m) - radius_m;
  const double v_n = std::sqrt(2.0 * g * gap_m / closing) * closing;
  const double k = kv->stiffness_n_per_m;
  const double m = ball.mass_kg;
  const double zeta = kv->damping_ns_per_m / (2.0 * std::sqrt(k * m));
  const double s = std::sqrt(1.0 - zeta * zeta);
  return v_n / std::sqrt(k / m) * std::exp(-zeta / s * std::atan(s / zeta));
}

// ground and disk of falling_ball; the disk at `gap_m` (< 0: pressed in) at
// the first impact's point, then moving slowly there and back
Scene make_scene(bool in_contact) {
  const Case c = load_case(std::filesystem::path(PB_CASES_DIR) / "falling_ball.toml");
  const Body& ground = c.bodies.at(static_cast<std::size_t>(c.body_index("ground")));
  const Body& ball = c.bodies.at(static_cast<std::size_t>(c.body_index("ball")));
  const auto* circle = std::get_if<Circle>(&ball.shape);
  if (!circle) throw InputError(c.source_path, 0, "bodies", "falling_ball's ball is not a circle");
  const double r = circle->radius_m;
  Scene s{ground, ball, ground.shape, ball.shape, Pose{ground.position_m, ground.angle_rad}, {}};
  const Vec2 n = s.ground.rotation() * Vec2(0.0, 1.0);
  const Vec2 t = s.ground.rotation() * Vec2(1.0, 0.0);
  // the centre at the first impact: the start moved along gravity by lambda
  // until its distance from the line is r
  const Vec2 down = c.gravity_mps2.normalized();
  const Vec2 start = ball.position_m - ground.position_m;
  const double lambda_m = (r - n.dot(start)) / n.dot(down);
  const double along_m = t.dot(start) + lambda_m * t.dot(down);
  const double gap_m = in_contact ? -peak_penetration_m(c, ground, ball, r) : kNearGapM;
  for (int k = 0; k < kPoses; ++k) {
    const int step = k < kPoses / 2 ? k : kPoses - k;  // there and back
    s.disk.push_back(Pose{ground.position_m + (along_m + kSlideStepM * step) * t + (r + gap_m) * n,
                          ball.angle_rad + kTurnStepRad * step});
  }
  return s;
}

enum class Method { brute, default_cold, default_warm, fast_cold, fast_warm, paper_two_stage };

void detect(benchmark::State& state, const Scene& scene, Method method) {
  const int n = static_cast<int>(state.range(0));
  const std::vector<Vec2> a = contact_outline(scene.ground_shape, n);
  const std::vector<Vec2> b = contact_outline(scene.disk_shape, n);
  OutlineContactSearch brute(a, b);
  FastOutlineContactSearch fast(a, b);
  Body ground_body = scene.ground_body;
  Body disk_body = scene.disk_body;
  ground_body.outline_points = n;
  disk_body.outline_points = n;
  PairGeometry pair(ground_body, disk_body, GeometryMode::outline, DetectionMode::fast);
  WorldOutline wa, wb;
  int k = 0;
  for (auto _ : state) {
    const Pose& disk = scene.disk[static_cast<std::size_t>(k)];
    k = k + 1 == kPoses ? 0 : k + 1;
    switch (method) {
      case Method::brute:
        benchmark::DoNotOptimize(brute.evaluate(scene.ground, disk));
        break;
      case Method::default_cold:
        pair.forget_history();
        benchmark::DoNotOptimize(pair.evaluate(scene.ground, disk));
        break;
      case Method::default_warm:
        benchmark::DoNotOptimize(pair.evaluate(scene.ground, disk));
        break;
      case Method::fast_cold:
        fast.forget_history();
        benchmark::DoNotOptimize(fast.evaluate(scene.ground, disk));
        break;
      case Method::fast_warm:
        benchmark::DoNotOptimize(fast.evaluate(scene.ground, disk));
        break;
      case Method::paper_two_stage:
        place_outline(a, scene.ground, wa);
        place_outline(b, disk, wb);
        benchmark::DoNotOptimize(paper_two_stage_distance(wa, wb));
        break;
    }
  }
  if (pair.tree_evaluations() > 0 && (method == Method::default_cold || method == Method::default_warm)) {
    state.SkipWithError("the closed form refused a pose of the sequence");
    return;
  }
  state.counters["detections_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["N"] = static_cast<double>(n);
}

void register_detection_benchmarks() {
  const std::vector<std::pair<std::string, Method>> methods = {
      {"brute", Method::brute},
      {"default_cold", Method::default_cold},
      {"default_warm", Method::default_warm},
      {"fast_cold", Method::fast_cold},
      {"fast_warm", Method::fast_warm},
      {"paper_two_stage", Method::paper_two_stage}};
  for (const bool in_contact : {false, true}) {
    auto scene = std::make_shared<const Scene>(make_scene(in_contact));
    const std::string config = in_contact ? "in_contact" : "near_contact";
    for (const auto& [name, method] : methods) {
      const Method m = method;
      benchmark::RegisterBenchmark(("detection/" + name + "/" + config).c_str(),
                                   [scene, m](benchmark::State& state) {
                                     try {
                                       detect(state, *scene, m);
                                     } catch (const std::exception& e) {
                                       skip_with_error(state, e.what());
                                     }
                                   })
          ->ArgName("N")
          ->Arg(45)
          ->Arg(90)
          ->Arg(180)
          ->Arg(360)
          ->Arg(720)
          ->Arg(1440)
          ->Unit(benchmark::kMicrosecond);
    }
  }
}

const DeferredRegistration kRegistration(register_detection_benchmarks);

}  // namespace

}  // namespace pb::bench
