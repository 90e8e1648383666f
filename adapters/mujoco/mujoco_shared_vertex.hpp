// One contact per point of a body cut into convex pieces. A vertex of a
// concave polygon where a seam of its decomposition ends (the L's outer
// corner, concave_corner; the boot's heel, concave_seam_face) is a vertex of
// two piece geoms, and MuJoCo's collider reports it once per geom: two
// constraint rows at one point. The case has one body there and one contact
// (SPEC §1); two rows at one point, whose positions differ only by the
// float rounding of each mesh (mjModel::mesh_vert is float, each mesh
// recentred on its own centroid: ~1e-8 m), make the pair's A = J M^-1 J^T
// singular up to that rounding, and its least-norm solve (contact_set_scale)
// then reads the rounding as two lever arms: m_set becomes the whole mass and
// sigma arbitrary (measured on concave_corner before this: contact 1.9x as
// long, penetration 1.9x the law's). Between mj_collision and
// mj_makeConstraint, every contact of a case pair that lies where an earlier
// one of the same pair lies is marked exclude = 2 ("fused", mjdata.h),
// MuJoCo's own flag for a contact merged into another: mj_instantiateContact
// (engine_core_constraint.c, 2.2.2) skips it.
#pragma once

#include <mujoco/mujoco.h>

#include "mujoco_contact_buckets.hpp"
#include "mujoco_model.hpp"

namespace pb::internal::mujoco {

// m: two contacts of one pair closer than this are one point. Far above the
// float rounding of a mesh vertex (6e-8 relative x a body of ~1 m: 6e-8 m),
// far below the distance of two distinct vertices of a case polygon (the
// loader refuses repeated points; a 180-point outline of a 1 cm disk has
// 3.5e-4 m between points).
inline constexpr double kSharedVertexTolerance_m = 1e-6;
// two normals closer than this (1 - cos of the angle, ~1.4e-3 rad) are one
// direction: plane contacts share the plane's normal exactly; MPR's normals
// carry ~1e-8 of noise (ENGINES.md)
inline constexpr double kSharedNormalTolerance = 1e-6;

// Marks exclude = 2 on every included contact of a case pair that coincides
// (point and normal, tolerances above) with an earlier included contact of
// the same pair whose geoms differ; returns how many it marked. `buckets`:
// d's contacts by pair (built on d).
int fuse_shared_vertex_contacts(mjData* d, const ModelLayout& layout,
                                const ContactBuckets& buckets);

}  // namespace pb::internal::mujoco
