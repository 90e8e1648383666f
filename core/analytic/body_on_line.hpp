// The closed-form truth of a body on a fixed line (the cases falling_ball,
// sliding, square_landing, concave_arch, incline_launch; SPEC §2-§3): in the
// frame of the line (tangent t, outward normal n of the half-plane) the normal
// motion is a NormalContactMotion; without friction the tangential motion is
// uniform acceleration g . t for all time and the rotation keeps its initial
// rate; with friction (SPEC §7) both follow a TangentialMotion. This holds
// when the normal force passes through the centre of mass: for a disk always;
// for a polygon that does not turn and touches the line with a face (or one
// vertex) whose depth-weighted contact point (SPEC §1: equal depths, the
// face's middle) lies on the normal through its centre of mass, while no
// other vertex reaches the line. With friction a polygon (a block) is held
// not to turn: the friction's moment about its centre, which tilts a
// compliant block slightly, is left out (the mapping says so).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "normal_contact_motion.hpp"
#include "tangential_motion.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

// How a body meets a line without turning: the distance from its centre of
// mass to its lowest point along -n (the support), and the height of the
// next-lowest vertex level above the lowest (infinite for a disk). nullopt:
// the body would turn (a polygon's lowest vertices are not centred under its
// centre of mass), `why` says so.
struct TranslatingSupport {
  double support_m = 0.0;     // m
  double clearance_m = 0.0;   // m
  int face_vertices = 0;      // polygon vertices at the lowest level (0 for a disk)
  // m, the face's ends along the line's tangent (n rotated by -90 deg) from
  // the foot of the centre of mass: face_min <= 0 <= face_max (0, 0: a disk)
  double face_min_m = 0.0;
  double face_max_m = 0.0;
};
// level_m: vertices within level_m of the lowest count as its face (0: to
// the rounding of the rotated coordinates); see static_level_m
[[nodiscard]] std::optional<TranslatingSupport> translating_support(const Body& body,
                                                                    const Vec2& normal,
                                                                    std::string* why,
                                                                    double level_m = 0.0);

// Why the closed form's premise that a polygon does not turn fails for `body`
// on a line of unit normal `normal` through `pair`: the friction the motion
// needs puts the contact's resultant beyond the face's nearer end (the block
// tips); "" when it holds (a disk, a frictionless pair, a wide enough face).
[[nodiscard]] std::string tipping_reason(const Case& c, const Body& body, const ContactPair& pair,
                                         const Vec2& normal, const TranslatingSupport& s);

// m: how far a block's face may stand from level and still be the rigid
// closed form's face. A compliant face held by friction on an incline rests
// tilted: the friction's moment m g sin(theta) x (centre to face) must be
// balanced by the normal force's line of action moved off the middle, which
// the law (SPEC §1) does by the face's tilt, its deeper end pressed in by the
// static penetration m g_n / K; the tilt vanishes as K grows, which is the
// rigid limit the closed form describes. A case may start there (the shipped
// square_hold): its face's ends then differ in height by less than the static
// penetration. 0 without friction (nothing tilts the face) or for a law
// other than plain Kelvin-Voigt.
[[nodiscard]] double static_level_m(const Case& c, int body, int line, int pair);

class BodyOnLine {
 public:
  // body: the moving body, line: the fixed HalfPlane body, pair: the contact
  // pair between them (Kelvin-Voigt without ramp); indices into c. The body
  // must pass translating_support (a polygon: also no spin).
  BodyOnLine(const Case& c, int body, int line, int pair);

  // locates every event up to t_s; throws EngineError when a polygon's
  // penetration would bring another vertex level to the line (the closed
  // form no longer holds)
  void extend_to(double t_s);

  // states of every body of the case at t_s (fixed bodies stay put)
  void body_states(double t_s, std::vector<BodyState>& out) const;
  // one sample while the body penetrates the line (delta > 0), else none
  void contacts(double t_s, std::vector<ContactSample>& out) const;
  // the episode table up to now_s
  [[nodiscard]] std::vector<ContactEpisode> episodes(double now_s) const;
  // phases of the normal motion begun by t_s
  [[nodiscard]] long phases_begun(double t_s) const;
  // what closed form is used, with its parameters
  [[nodiscard]] nlohmann::json mapping() const;

  [[nodiscard]] const NormalContactMotion& normal_motion() const { return normal_; }
  // with friction: the motion along the line (nullptr without)
  [[nodiscard]] const TangentialMotion* tangential_motion() const { return tangential_.get(); }

 private:
  static NormalContactParams normal_params(const Case& c, int body, int line, int pair,
                                           bool& snapped);

  int body_ = -1;
  int pair_body_a_ = -1;
  int pair_body_b_ = -1;
  bool body_is_a_ = false;
  std::string shape_;               // the body's shape type
  TranslatingSupport support_;      // m: support distance and clearance
  Vec2 line_origin_m_;              // m, a point of the line
  Vec2 tangent_;                    // unit, line direction
  Vec2 normal_dir_;                 // unit, outward normal of the half-plane
  double along0_m_ = 0.0;           // m, tangential coordinate of the centre at t = 0
  double along_rate0_mps_ = 0.0;    // m/s
  double along_accel_mps2_ = 0.0;   // m/s^2, g . t
  double angle0_rad_ = 0.0;         // rad
  double spin_radps_ = 0.0;         // rad/s, constant
  bool gap_snapped_ = false;        // the initial gap was rounding of zero
  std::vector<BodyState> initial_;  // every body at t = 0
  NormalContactMotion normal_;
  std::unique_ptr<TangentialMotion> tangential_;  // with friction only
};

}  // namespace pb::internal
