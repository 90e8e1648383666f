// A compiled MuJoCo model of a case: loading MJCF text through MuJoCo's
// virtual file system, owning mjModel/mjData, and knowing where each case body
// and pair lives in it.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <string>
#include <vector>

#include "mujoco_plan.hpp"
#include "planarbench/case.hpp"

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
  std::vector<int> geoms;  // every geom of the body, one per convex piece
  int qpos_x = -1;      // slide x (free bodies)
  int qpos_z = -1;      // slide z (free bodies)
  int qpos_hinge = -1;  // hinge about y (every moving body)
  int dof_x = -1;
  int dof_z = -1;
  int dof_hinge = -1;
};

// MuJoCo ids of one case contact pair
struct PairLayout {
  int body_a = -1;  // Case::contacts[k].body_a
  int body_b = -1;
  int mj_body_a = 0;
  int mj_body_b = 0;
  bool present = false;  // false when both bodies are fixed (no <pair> written)
  std::vector<int> mj_pairs;  // the MuJoCo <pair>s of the case pair (one per two pieces)
};

struct ModelLayout {
  std::vector<BodyLayout> bodies;  // index = Case::bodies index
  std::vector<PairLayout> pairs;   // index = Case::contacts index
  std::vector<int> body_of_geom;   // MuJoCo geom id -> Case::bodies index (-1: none)
  std::vector<int> pair_table;     // bodies x bodies -> Case::contacts index (-1: none)
  // the pair of a MuJoCo contact (geom1, geom2 in either order), -1 if none
  [[nodiscard]] int pair_of(int geom1, int geom2) const;
  // whether MuJoCo geom `geom` belongs to body_a of case pair k
  [[nodiscard]] bool on_body_a(int geom, int k) const;
};

// Looks the names written by write_mjcf (from `plan`) up in the compiled model.
[[nodiscard]] ModelLayout model_layout(const mjModel* m, const Case& c, const MujocoPlan& plan);

// qpos, qvel of the case's initial state: slides at 0 (the body starts at its
// reference position), hinges at hinge_from_ccw(angle), velocities mapped.
void set_initial_state(const mjModel* m, mjData* d, const Case& c, const ModelLayout& layout);

}  // namespace pb::internal::mujoco
