#include "ode_friction.hpp"

namespace pb::internal::ode {

void add_coulomb_friction(dContact& contact, double mu) {
  if (!(mu > 0.0)) return;
  contact.surface.mode |= dContactApprox1 | dContactFDir1 | dContactMu2;
  contact.surface.mu = mu;
  contact.surface.mu2 = 0.0;
  // the normal turned by +90 deg in the plane: unit and tangent, as ODE
  // needs (it neither normalises fdir1 nor makes it perpendicular)
  contact.fdir1[0] = -contact.geom.normal[1];
  contact.fdir1[1] = contact.geom.normal[0];
  contact.fdir1[2] = 0.0;
}

nlohmann::json friction_mapping(double mu) {
  return {{"coefficient", mu},
          {"expressed_as",
           "exactly: each contact joint of the pair gets mu with dContactApprox1 (a Coulomb "
           "coefficient bounding the friction row by mu times that contact's normal force), one "
           "friction direction, the in-plane tangent (dContactFDir1), and no second one "
           "(dContactMu2, mu2 = 0: it would lie along z, held by Plane2D)"},
          {"stepper_note",
           "dWorldStep (the default for declared pairs) bounds each friction row by mu times "
           "the normal force the LCP solved before friction acts; dWorldQuickStep (the default "
           "for a scene) by the current iterate's"},
          {"not_expressed",
           nlohmann::json::array({"a stuck contact creeps at world CFM (1e-10) x its friction "
                                  "force per newton, ~1e-10 m/s"})}};
}

}  // namespace pb::internal::ode
