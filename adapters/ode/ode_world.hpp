// The ODE model of a case: one dWorld, one dSpace (a dSweepAndPruneSpace for
// a scene, whose pairs ODE's broad phase finds; a dSimpleSpace, never
// traversed, for a case of declared pairs) and one contact joint group per
// instance, a body per moving case body with its explicit mass and planar
// inertia, Plane2D for free bodies, a z-axis hinge to the world per revolute
// joint, and a geom per body (a scene's rectangles as dBoxes). Owns every
// ODE object and every array ODE points into.
#pragma once

#include <ode/ode.h>

#include <memory>
#include <string>
#include <vector>

#include "ode_geometry.hpp"
#include "planarbench/energy_budget.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::ode {

// dWorldStep(world, h), counted: every ODE step of this thread, whoever takes
// it (a run, the oracle's probe). The count is a trace: the engine reads it
// before and after build to prove that its default mode steps nothing ahead
// of t = 0 (SPEC §5b).
void step_world(dWorldID world, double step_s);
// dWorldQuickStep(world, h), counted the same way
void quick_step_world(dWorldID world, double step_s);
[[nodiscard]] long world_steps_on_this_thread();

class OdeWorld {
 public:
  // Throws EngineError when a body cannot be built (e.g. a moving half-plane).
  explicit OdeWorld(const Case& c);
  ~OdeWorld();
  OdeWorld(const OdeWorld&) = delete;
  OdeWorld& operator=(const OdeWorld&) = delete;

  [[nodiscard]] dWorldID world() const { return world_; }
  [[nodiscard]] dSpaceID space() const { return space_; }
  [[nodiscard]] dJointGroupID contact_group() const { return contact_group_; }
  // nullptr for fixed bodies
  [[nodiscard]] dBodyID body(int i) const { return bodies_[static_cast<std::size_t>(i)]; }
  // the geoms of body i: one per convex piece of its shape
  [[nodiscard]] const std::vector<dGeomID>& geoms(int i) const {
    return geoms_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] int geom_count(int i) const {
    return static_cast<int>(geoms_[static_cast<std::size_t>(i)].size());
  }
  // the vertices of body i's geoms: a prism's 2 n (both faces), a box's 8,
  // 1 for a sphere or a plane (the bound on its contacts, ode_pair_contact.hpp)
  [[nodiscard]] int vertex_count(int i) const { return vertex_counts_[static_cast<std::size_t>(i)]; }
  // the case body index of a geom of this world (stored as the geom's data)
  [[nodiscard]] static int body_index_of(dGeomID g);
  [[nodiscard]] int body_count() const { return static_cast<int>(bodies_.size()); }
  // a scene's sweep and prune axes (scene_space), "" for a simple space
  [[nodiscard]] const std::string& sweep_axes() const { return sweep_axes_; }
  [[nodiscard]] const std::string& geom_description(int i) const {
    return descriptions_[static_cast<std::size_t>(i)];
  }

  // state of body i in the case frame; fixed bodies: the case's initial state.
  // angle_rad is wrapped to (-pi, pi].
  [[nodiscard]] BodyState state(int i) const;
  // centres of every body, m (index = Case::bodies index)
  [[nodiscard]] std::vector<Vec2> centres() const;

  // Plane2D keeps z and the x/y angular velocities at 0 through its rows but
  // leaves the orientation's drift to the application (ODE manual,
  // "Plane 2D"; ENGINES.md): keep only the z rotation and spin.
  void remove_planar_drift();

  // The runaway bounds come from the a-priori energy bound of a passive
  // system (planarbench/energy_budget.hpp) over the case's duration, widened
  // by kRunawayEnergyFactor in energy: a body faster than sqrt(2 F KE_max /
  // m), spinning faster than sqrt(2 F KE_max / I) or farther from its start
  // than sqrt(F) times its displacement bound is running away. The constructor
  // takes E(0) = KE(0); the engine adds the elastic energy of contacts that
  // start penetrated (J) once it has collided the initial state.
  void set_initial_contact_energy(double elastic_j);
  // the first moving body whose state is not finite or exceeds the runaway
  // bounds; -1 if none
  [[nodiscard]] int first_blown_up_body() const;
  // why body i is flagged by first_blown_up_body()
  [[nodiscard]] std::string blow_up_reason(int i) const;
  // Why a force the adapter is about to apply would take body i past its
  // runaway bounds in the coming step of step_s ("" when not): the velocity
  // after the step, v + h (g + F / m) and omega + h tau / I (torque about the
  // centre of mass), checked before ODE integrates it. A non-finite or
  // overflowing state inside dWorldStep trips ODE's own asserts (measured:
  // "ODE INTERNAL ERROR 1: assertion !bSafeNormalize4Fault failed in
  // dxNormalize4()" after an infinite force), which abort the process.
  [[nodiscard]] std::string applied_force_reason(int i, const Vec2& force_n, double torque_nm,
                                                 double step_s) const;

 private:
  void build(const Case& c);
  void destroy();
  void set_runaway_bounds();
  dSpaceID scene_space(const Case& c);

  // per body: the runaway bounds (infinite for fixed bodies)
  struct Bounds {
    double speed_mps = 0.0;
    double spin_radps = 0.0;
    double displacement_m = 0.0;
  };

  std::vector<Body> case_bodies_;
  EnergyBound energy_bound_;
  Vec2 gravity_mps2_ = Vec2::Zero();
  double kinetic_start_j_ = 0.0;  // J, KE(0)
  double duration_s_ = 0.0;
  std::vector<Bounds> bounds_;
  dWorldID world_ = nullptr;
  dThreadingImplementationID threading_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contact_group_ = nullptr;
  std::vector<dBodyID> bodies_;
  std::vector<std::vector<dGeomID>> geoms_;
  std::vector<int> vertex_counts_;
  std::vector<bool> planar_;                          // held by a Plane2D joint
  std::vector<std::unique_ptr<ConvexPrism>> prisms_;  // stable addresses for dCreateConvex
  std::vector<std::unique_ptr<int>> geom_data_;       // body index behind each geom's data
  std::vector<std::string> descriptions_;
  std::string sweep_axes_;
};

}  // namespace pb::internal::ode
