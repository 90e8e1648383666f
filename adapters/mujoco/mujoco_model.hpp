// A compiled MuJoCo model of a case: loading MJCF text through MuJoCo's
// virtual file system, owning mjModel/mjData, and knowing where each case body
// and pair lives in it. The run's pairs are its declared pairs (indices
// 0 .. declared - 1, Case::contacts) and, in a scene, the pairs of its
// contact groups in the order MuJoCo's collider first reports them
// (pb::ContactPairs, find_or_add): per-pair state lives in vectors indexed
// like this list, grown as pairs are added.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mujoco_plan.hpp"
#include "planarbench/case.hpp"
#include "planarbench/contact_pairs.hpp"

namespace pb::internal::mujoco {

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

// Compiles MJCF text from memory: a heap-allocated mjVFS (about 2 MB) holding
// one file, mj_loadXML, mj_deleteVFS. Loads are serialised by a mutex (the
// XML parser keeps process-global state). Throws EngineError with MuJoCo's
// message.
[[nodiscard]] ModelPtr load_mjcf(const std::string& xml);

// MuJoCo ids of one case body; -1 where absent
struct BodyLayout {
  int mj_body = 0;  // 0 = the world body (fixed case bodies)
  int geom = -1;    // the first geom (a body cut into convex pieces has more)
  // the geoms of copy 0, one per convex piece (a body in two contact groups
  // has a copy of them per group: body_of_geom knows them all)
  std::vector<int> geoms;
  int qpos_x = -1;      // slide x (free bodies)
  int qpos_z = -1;      // slide z (free bodies)
  int qpos_hinge = -1;  // hinge about y (every moving body)
  int dof_x = -1;
  int dof_z = -1;
  int dof_hinge = -1;
};

// MuJoCo ids of one pair of the run
struct PairLayout {
  int body_a = -1;  // the pair's body_a (Case::contacts[k] or the group pair's)
  int body_b = -1;
  int mj_body_a = 0;
  int mj_body_b = 0;
  bool present = false;  // false when both bodies are fixed (no <pair> written)
  // the MuJoCo <pair>s of a declared pair (one per two pieces); none for a
  // group pair (MuJoCo's broad phase finds it)
  std::vector<int> mj_pairs;
};

struct ModelLayout {
  std::vector<BodyLayout> bodies;  // index = Case::bodies index
  std::vector<PairLayout> pairs;   // index = the run's pair index (rules)
  std::vector<int> body_of_geom;   // MuJoCo geom id -> Case::bodies index (-1: none)
  std::optional<ContactPairs> rules;  // the run's pairs and the rules that make them
  // the pair of a MuJoCo contact (geom1, geom2 in either order), -1 if none yet
  [[nodiscard]] int pair_of(int geom1, int geom2) const;
  // ... adding it, when a contact group lets the two bodies touch and it has
  // no index yet (its PairLayout appended); -1 if no rule lets them touch
  int find_or_add_pair(int geom1, int geom2);
  // whether MuJoCo geom `geom` belongs to body_a of pair k
  [[nodiscard]] bool on_body_a(int geom, int k) const;
  // pair k's bodies, law, friction (declared: Case::contacts[k])
  [[nodiscard]] const ContactPair& pair(int k) const { return (*rules)[k]; }
  [[nodiscard]] int declared() const { return rules ? rules->declared() : 0; }
};

// Looks the names written by write_mjcf (from `plan`) up in the compiled model.
[[nodiscard]] ModelLayout model_layout(const mjModel* m, const Case& c, const MujocoPlan& plan);

// qpos, qvel of the case's initial state: slides at 0 (the body starts at its
// reference position), hinges at hinge_from_ccw(angle), velocities mapped.
void set_initial_state(const mjModel* m, mjData* d, const Case& c, const ModelLayout& layout);

}  // namespace pb::internal::mujoco
