#include "mujoco_mjcf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "mujoco_frame.hpp"
#include "mujoco_geometry.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {

namespace {

// every number with round-trip precision
std::string num(double x) {
  return fmt::format("{:.17g}", x);
}
std::string vec3(const std::array<double, 3>& v) {
  return fmt::format("{} {} {}", num(v[0]), num(v[1]), num(v[2]));
}
std::string quat(const std::array<double, 4>& q) {
  return fmt::format("{} {} {} {}", num(q[0]), num(q[1]), num(q[2]), num(q[3]));
}

// rotation of a case vector by angle theta (counter-clockwise)
Vec2 rotated(const Vec2& v, double theta) {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

std::string reals(const double* v, std::size_t n) {
  std::string s;
  for (std::size_t k = 0; k < n; ++k) {
    if (k) s.append(" ");
    s.append(num(v[k]));
  }
  return s;
}

// the geoms of body i (one per piece, per copy), placed at `pos` with
// orientation `q` in its parent
std::string geom_elements(const Body& b, const BodyPlan& plan, int i,
                          const std::array<double, 3>& pos, const std::array<double, 4>& q,
                          const MujocoPlan& all, const MjcfOptions& o) {
  auto common = [&](int piece, int copy) {
    if (plan.groups.empty()) {
      // collisions only through explicit <pair>s: contype = conaffinity = 0
      return fmt::format(R"(name="{}" pos="{}" quat="{}" contype="0" conaffinity="0" condim="1")",
                         geom_name(i, piece), vec3(pos), quat(q));
    }
    // a copy of a group: MuJoCo's broad phase pairs it with the group's
    // other geoms, with the group's attributes (GroupPlan)
    const auto g = static_cast<std::size_t>(plan.groups[static_cast<std::size_t>(copy)]);
    const GroupPlan& gp = all.groups[g];
    const PairParams& p = o.groups[g];
    const double margin = plan.copy_margin_m[static_cast<std::size_t>(copy)];
    const std::string friction =
        gp.condim > 1 ? fmt::format(R"( friction="{}")", reals(gp.friction.data(), 3)) : "";
    return fmt::format(
        R"(name="{}" pos="{}" quat="{}" contype="{}" conaffinity="{}" condim="{}"{} solref="{}" solimp="{}" margin="{}" gap="{}")",
        geom_name(i, piece, copy), vec3(pos), quat(q), 1u << gp.bit, 1u << gp.bit, gp.condim,
        friction, reals(p.solref.data(), 2), reals(p.solimp.data(), 5), num(margin), num(margin));
  };
  std::string out;
  for (int copy = 0; copy < plan.copy_count(); ++copy) {
    out += std::visit(
        [&](const auto& s) -> std::string {
          using T = std::decay_t<decltype(s)>;
          if constexpr (std::is_same_v<T, Circle>) {
            return fmt::format(R"(<geom {} type="sphere" size="{}"/>)", common(0, copy),
                               num(s.radius_m));
          } else if constexpr (std::is_same_v<T, Ellipse>) {
            return fmt::format(R"(<geom {} type="ellipsoid" size="{}"/>)", common(0, copy),
                               vec3(ellipsoid_size_m(s)));
          } else if constexpr (std::is_same_v<T, Polygon>) {
            std::string geoms;
            for (int k = 0; k < plan.geom_count(); ++k) {
              geoms += fmt::format(R"(<geom {} type="mesh" mesh="{}"/>)", common(k, copy),
                                   mesh_name(i, k));
            }
            return geoms;
          } else {
            // size only affects rendering: MuJoCo planes are infinite for collision
            return fmt::format(R"(<geom {} type="plane" size="{} 1 1"/>)", common(0, copy),
                               num(0.5 * s.extent_m));
          }
        },
        b.shape);
  }
  return out;
}

// one mesh asset per convex piece: a bipyramid over the plan's apex
std::string mesh_assets(const BodyPlan& plan, int i) {
  std::string out;
  for (std::size_t k = 0; k < plan.pieces.size(); ++k) {
    std::string v;
    for (const auto& x : bipyramid_vertices(plan.pieces[k], plan.apexes[k])) {
      if (!v.empty()) v.append("  ");
      v.append(vec3(x));
    }
    out += fmt::format(R"(<mesh name="{}" vertex="{}"/>)", mesh_name(i, static_cast<int>(k)), v);
    out += "\n";
  }
  return out;
}

// explicit mass and planar inertia: the inertia about y is the case's; the two
// other diagonal entries only need to be valid (triangle inequality), so all
// three are equal
std::string inertial_element(const Body& b, const std::array<double, 3>& pos) {
  const std::string inertia = num(b.inertia_kgm2);
  return fmt::format(R"(<inertial pos="{}" mass="{}" diaginertia="{} {} {}"/>)", vec3(pos),
                     num(b.mass_kg), inertia, inertia, inertia);
}

std::string moving_body(const Case& c, const BodyPlan& plan, int i, const MujocoPlan& all,
                        const MjcfOptions& o) {
  const Body& b = c.bodies[static_cast<std::size_t>(i)];
  const int j = plan.joint;
  const std::array<double, 4> identity = {1.0, 0.0, 0.0, 0.0};
  std::string s;
  if (j < 0) {
    // free planar body: its frame origin is the centre of mass at t = 0
    s += fmt::format(R"(<body name="{}" pos="{}">)", body_name(i), vec3(to_mj(b.position_m)));
    s += fmt::format(R"(<joint name="{}" type="slide" axis="1 0 0"/>)", slide_x_name(i));
    s += fmt::format(R"(<joint name="{}" type="slide" axis="0 0 1"/>)", slide_z_name(i));
    s += fmt::format(R"(<joint name="{}" type="hinge" axis="0 1 0"/>)", hinge_name(i));
    s += inertial_element(b, {0.0, 0.0, 0.0});
    s += geom_elements(b, plan, i, {0.0, 0.0, 0.0}, identity, all, o);
  } else {
    // pendulum: frame origin at the pivot; centre of mass at -pivot_in_body
    // in the reference pose (angle 0)
    const RevoluteJoint& rj = c.joints[static_cast<std::size_t>(j)];
    const auto com = to_mj(-pivot_in_body_m(c, rj));
    s += fmt::format(R"(<body name="{}" pos="{}">)", body_name(i), vec3(to_mj(rj.anchor_world_m)));
    s += fmt::format(R"(<joint name="{}" type="hinge" axis="0 1 0"/>)", hinge_name(i));
    s += inertial_element(b, com);
    s += geom_elements(b, plan, i, com, identity, all, o);
  }
  s += "</body>\n";
  return s;
}

// the group both bodies are in (the loader allows one at most), -1 if none
int shared_group(const BodyPlan& a, const BodyPlan& b) {
  for (const int g : a.groups) {
    if (std::find(b.groups.begin(), b.groups.end(), g) != b.groups.end()) return g;
  }
  return -1;
}

}  // namespace

std::string body_name(int i) {
  return fmt::format("body{}", i);
}
std::string geom_name(int i, int piece, int copy) {
  const std::string base = copy == 0 ? fmt::format("geom{}", i) : fmt::format("geom{}c{}", i, copy);
  return piece == 0 ? base : fmt::format("{}_{}", base, piece);
}
std::string mesh_name(int i, int piece) {
  return piece == 0 ? fmt::format("mesh{}", i) : fmt::format("mesh{}_{}", i, piece);
}
std::string pair_name(int k, int piece_a, int piece_b) {
  return piece_a == 0 && piece_b == 0 ? fmt::format("pair{}", k)
                                      : fmt::format("pair{}_{}_{}", k, piece_a, piece_b);
}
std::string slide_x_name(int i) {
  return fmt::format("body{}_x", i);
}
std::string slide_z_name(int i) {
  return fmt::format("body{}_z", i);
}
std::string hinge_name(int i) {
  return fmt::format("body{}_hinge", i);
}

int joint_of_body(const Case& c, int body) {
  for (std::size_t k = 0; k < c.joints.size(); ++k) {
    if (c.joints[k].body == body) return static_cast<int>(k);
  }
  return -1;
}

Vec2 pivot_in_body_m(const Case& c, const RevoluteJoint& j) {
  const Body& b = c.bodies.at(static_cast<std::size_t>(j.body));
  return rotated(j.anchor_world_m - b.position_m, -b.angle_rad);
}

std::string write_mjcf(const Case& c, const MujocoPlan& plan, const MjcfOptions& o) {
  if (o.pairs.size() != c.contacts.size() || plan.pairs.size() != c.contacts.size() ||
      plan.bodies.size() != c.bodies.size() || o.groups.size() != c.contact_groups.size() ||
      plan.groups.size() != c.contact_groups.size()) {
    throw EngineError(
        "mujoco: write_mjcf needs the case's plan and one PairParams per pair and group");
  }
  const bool own_friction_solref = o.solreffriction[0] != 0.0 || o.solreffriction[1] != 0.0;
  if (o.mujoco_major < 3 &&
      (own_friction_solref || o.integrator == "implicit" || o.integrator == "implicitfast")) {
    throw EngineError(fmt::format(
        "mujoco: MuJoCo 2.2.2 has neither solreffriction nor the integrator '{}' (MuJoCo 3 "
        "does: engine mujoco3)",
        o.integrator));
  }
  std::string assets;
  std::string world;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    const BodyPlan& bp = plan.bodies[i];
    const int id = static_cast<int>(i);
    assets += mesh_assets(bp, id);
    if (b.fixed) {
      // fixed bodies are geoms of the world body at their pose
      world += geom_elements(b, bp, id, to_mj(b.position_m), quat_from_ccw(b.angle_rad), plan, o) +
               "\n";
    } else {
      if (std::holds_alternative<HalfPlane>(b.shape)) {
        throw EngineError(fmt::format("mujoco: half-plane '{}' must be fixed", b.name));
      }
      world += moving_body(c, bp, id, plan, o);
    }
  }
  std::string pairs;
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    const ContactPair& cp = c.contacts[k];
    const PairPlan& pp = plan.pairs[k];
    // two fixed bodies never move: MuJoCo has nothing to compute
    if (!pp.present) continue;
    const PairParams& p = o.pairs[k];
    // Coulomb friction on both tangents (the plan says why); none at condim 1
    std::string friction =
        pp.condim > 1 ? fmt::format(R"( friction="{}")", reals(pp.friction.data(), 5)) : "";
    if (pp.condim > 1 && own_friction_solref) {
      friction += fmt::format(R"( solreffriction="{}")", reals(o.solreffriction.data(), 2));
    }
    // every piece of a against every piece of b, with the case pair's
    // parameters; on the copies of a group both bodies are in, if any: MuJoCo
    // then skips the geom pairs its broad phase finds that a <pair> names
    // (mj_collision's merge), so the declared pair takes precedence
    const BodyPlan& ba = plan.bodies[static_cast<std::size_t>(cp.body_a)];
    const BodyPlan& bb = plan.bodies[static_cast<std::size_t>(cp.body_b)];
    const int shared = shared_group(ba, bb);
    const int ca = shared < 0 ? 0 : ba.copy_of_group(shared);
    const int cb = shared < 0 ? 0 : bb.copy_of_group(shared);
    const int na = ba.geom_count();
    const int nb = bb.geom_count();
    for (int pa = 0; pa < na; ++pa) {
      for (int pb = 0; pb < nb; ++pb) {
        pairs += fmt::format(
            R"(<pair name="{}" geom1="{}" geom2="{}" condim="{}"{} solref="{}" solimp="{}" margin="{}" gap="{}"/>)",
            pair_name(static_cast<int>(k), pa, pb), geom_name(cp.body_a, pa, ca),
            geom_name(cp.body_b, pb, cb), pp.condim, friction, reals(p.solref.data(), 2),
            reals(p.solimp.data(), 5), num(pp.margin_m), num(p.gap_m));
        pairs += "\n";
      }
    }
  }
  const auto g = to_mj(c.gravity_mps2);
  std::string size;
  const int memory_mb = o.mujoco_major >= 3 ? o.memory_mb : 0;
  if (o.nconmax > 0 || o.njmax > 0 || memory_mb > 0) {
    size = "<size";
    if (o.nconmax > 0) size += fmt::format(R"( nconmax="{}")", o.nconmax);
    if (o.njmax > 0) size += fmt::format(R"( njmax="{}")", o.njmax);
    if (memory_mb > 0) size += fmt::format(R"( memory="{}M")", memory_mb);
    size += "/>\n";
  }
  return fmt::format(
      R"(<mujoco model="{}">
<compiler angle="radian" inertiafromgeom="false"/>
<option timestep="{}" integrator="{}" solver="{}" iterations="{}" tolerance="{}" gravity="{}" cone="{}" impratio="{}" noslip_iterations="{}"{}
{}<asset>
{}</asset>
<worldbody>
{}</worldbody>
<contact>
{}</contact>
</mujoco>
)",
      "planarbench", num(o.dt_s), o.integrator, o.solver, o.iterations, num(o.tolerance), vec3(g),
      o.cone, num(o.impratio), o.noslip_iterations,
      o.multiccd ? R"(><flag multiccd="enable"/></option>)" : "/>", size, assets, world, pairs);
}

}  // namespace pb::internal::mujoco
