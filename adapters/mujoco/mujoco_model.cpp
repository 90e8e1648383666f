#include "mujoco_model.hpp"

#include <fmt/format.h>

#include <cstring>
#include <mutex>

#include "mujoco_frame.hpp"
#include "mujoco_mjcf.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {

namespace {

std::mutex& load_mutex() {
  static std::mutex m;
  return m;
}

int id_of(const mjModel* m, int type, const std::string& name) {
  return mj_name2id(m, type, name.c_str());
}

}  // namespace

ModelPtr load_mjcf(const std::string& xml) {
  constexpr const char* kFile = "planarbench.xml";
  // mjVFS holds 2000 file names of 1000 chars: too large for a stack
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), kFile, static_cast<int>(xml.size())) != 0) {
    throw EngineError("mujoco: mj_makeEmptyFileVFS failed");
  }
  const int index = mj_findFileVFS(vfs.get(), kFile);
  std::memcpy(vfs->filedata[index], xml.data(), xml.size());
  char error[1024] = "";
  mjModel* m = nullptr;
  {
    std::lock_guard<std::mutex> lock(load_mutex());
    m = mj_loadXML(kFile, vfs.get(), error, sizeof(error));
  }
  mj_deleteVFS(vfs.get());
  if (!m) throw EngineError(fmt::format("mujoco: mj_loadXML failed: {}", error));
  return ModelPtr(m);
}

namespace {

// the case bodies of two geoms, false when either is none of the case's
bool bodies_of(const ModelLayout& L, int geom1, int geom2, int& a, int& b) {
  const auto g = L.body_of_geom.size();
  if (geom1 < 0 || geom2 < 0 || static_cast<std::size_t>(geom1) >= g ||
      static_cast<std::size_t>(geom2) >= g) {
    return false;
  }
  a = L.body_of_geom[static_cast<std::size_t>(geom1)];
  b = L.body_of_geom[static_cast<std::size_t>(geom2)];
  return a >= 0 && b >= 0 && a != b;
}

}  // namespace

int ModelLayout::pair_of(int geom1, int geom2) const {
  int a = -1;
  int b = -1;
  if (!rules || !bodies_of(*this, geom1, geom2, a, b)) return -1;
  return rules->find(a, b);
}

int ModelLayout::find_or_add_pair(int geom1, int geom2) {
  int a = -1;
  int b = -1;
  if (!rules || !bodies_of(*this, geom1, geom2, a, b)) return -1;
  const int k = rules->find_or_add(a, b);
  if (k >= static_cast<int>(pairs.size())) {
    // a group pair MuJoCo's broad phase has just found
    const ContactPair& cp = (*rules)[k];
    PairLayout p;
    p.body_a = cp.body_a;
    p.body_b = cp.body_b;
    p.mj_body_a = bodies[static_cast<std::size_t>(cp.body_a)].mj_body;
    p.mj_body_b = bodies[static_cast<std::size_t>(cp.body_b)].mj_body;
    p.present = true;  // a group pair never joins two fixed bodies
    pairs.push_back(std::move(p));
  }
  return k;
}

bool ModelLayout::on_body_a(int geom, int k) const {
  return body_of_geom.at(static_cast<std::size_t>(geom)) ==
         pairs.at(static_cast<std::size_t>(k)).body_a;
}

ModelLayout model_layout(const mjModel* m, const Case& c, const MujocoPlan& plan) {
  ModelLayout L;
  L.body_of_geom.assign(static_cast<std::size_t>(m->ngeom), -1);
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const int id = static_cast<int>(i);
    BodyLayout b;
    for (int copy = 0; copy < plan.bodies[i].copy_count(); ++copy) {
      for (int piece = 0; piece < plan.bodies[i].geom_count(); ++piece) {
        const int g = id_of(m, mjOBJ_GEOM, geom_name(id, piece, copy));
        if (g < 0) continue;
        if (copy == 0) b.geoms.push_back(g);
        L.body_of_geom[static_cast<std::size_t>(g)] = id;
      }
    }
    b.geom = b.geoms.empty() ? -1 : b.geoms.front();
    if (!c.bodies[i].fixed) {
      b.mj_body = id_of(m, mjOBJ_BODY, body_name(id));
      const int jx = id_of(m, mjOBJ_JOINT, slide_x_name(id));
      const int jz = id_of(m, mjOBJ_JOINT, slide_z_name(id));
      const int jh = id_of(m, mjOBJ_JOINT, hinge_name(id));
      if (jx >= 0) b.qpos_x = m->jnt_qposadr[jx], b.dof_x = m->jnt_dofadr[jx];
      if (jz >= 0) b.qpos_z = m->jnt_qposadr[jz], b.dof_z = m->jnt_dofadr[jz];
      if (jh >= 0) b.qpos_hinge = m->jnt_qposadr[jh], b.dof_hinge = m->jnt_dofadr[jh];
    }
    L.bodies.push_back(b);
  }
  L.rules.emplace(c);
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    const ContactPair& cp = c.contacts[k];
    PairLayout p;
    const BodyLayout& a = L.bodies.at(static_cast<std::size_t>(cp.body_a));
    const BodyLayout& b = L.bodies.at(static_cast<std::size_t>(cp.body_b));
    p.body_a = cp.body_a;
    p.body_b = cp.body_b;
    p.mj_body_a = a.mj_body;
    p.mj_body_b = b.mj_body;
    p.present = !(c.bodies[static_cast<std::size_t>(cp.body_a)].fixed &&
                  c.bodies[static_cast<std::size_t>(cp.body_b)].fixed);
    if (p.present) {
      for (std::size_t pa = 0; pa < a.geoms.size(); ++pa) {
        for (std::size_t pb = 0; pb < b.geoms.size(); ++pb) {
          const int id = id_of(m, mjOBJ_PAIR,
                               pair_name(static_cast<int>(k), static_cast<int>(pa),
                                         static_cast<int>(pb)));
          if (id >= 0) p.mj_pairs.push_back(id);
        }
      }
    }
    L.pairs.push_back(p);
  }
  return L;
}

void set_initial_state(const mjModel* m, mjData* d, const Case& c, const ModelLayout& L) {
  mj_resetData(m, d);
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    const BodyLayout& l = L.bodies[i];
    if (b.fixed) continue;
    // the reference pose is angle 0: the initial angle lives in the hinge
    d->qpos[l.qpos_hinge] = hinge_from_ccw(b.angle_rad);
    d->qvel[l.dof_hinge] = hinge_rate_from_ccw(b.angular_velocity_radps);
    if (l.qpos_x >= 0) {
      d->qpos[l.qpos_x] = 0.0;
      d->qpos[l.qpos_z] = 0.0;
      d->qvel[l.dof_x] = b.velocity_mps.x();
      d->qvel[l.dof_z] = b.velocity_mps.y();
    }
  }
}

}  // namespace pb::internal::mujoco
