#include "mujoco_shared_vertex.hpp"

#include <cmath>

namespace pb::internal::mujoco {

namespace {

// MuJoCo's flag for a contact merged into another (mjdata.h: 2 = fused)
constexpr int kExcludeFused = 2;

bool same_point(const mjContact& a, const mjContact& b) {
  const double dx = a.pos[0] - b.pos[0];
  const double dy = a.pos[1] - b.pos[1];
  const double dz = a.pos[2] - b.pos[2];
  if (std::sqrt(dx * dx + dy * dy + dz * dz) > kSharedVertexTolerance_m) return false;
  // both normals from the pair's body a to body b: flip b's when its geoms
  // are listed the other way round
  const double dot =
      a.frame[0] * b.frame[0] + a.frame[1] * b.frame[1] + a.frame[2] * b.frame[2];
  return std::abs(dot) >= 1.0 - kSharedNormalTolerance;
}

bool same_orientation(const mjContact& a, const mjContact& b, const ModelLayout& layout, int k) {
  return layout.on_body_a(a.geom1, k) == layout.on_body_a(b.geom1, k);
}

}  // namespace

int fuse_shared_vertex_contacts(mjData* d, const ModelLayout& layout,
                                const ContactBuckets& buckets) {
  int fused = 0;
  for (std::size_t bucket = 0; bucket < buckets.pairs().size(); ++bucket) {
    const int k = buckets.pairs()[bucket];
    const auto list = buckets.contacts(bucket);
    for (std::size_t at = 1; at < list.size(); ++at) {
      mjContact& c = d->contact[list[at]];
      if (c.exclude != 0) continue;
      // the pair's earlier contacts, in d->contact's order
      for (std::size_t before = 0; before < at; ++before) {
        const mjContact& e = d->contact[list[before]];
        if (e.exclude != 0) continue;
        // one geom pair reports distinct points; a repeat comes from another piece
        if (e.geom1 == c.geom1 && e.geom2 == c.geom2) continue;
        if (!same_point(e, c)) continue;
        // the normals must agree as directions a -> b, not only as lines
        const double dot =
            e.frame[0] * c.frame[0] + e.frame[1] * c.frame[1] + e.frame[2] * c.frame[2];
        if ((dot > 0.0) != same_orientation(e, c, layout, k)) continue;
        c.exclude = kExcludeFused;
        ++fused;
        break;
      }
    }
  }
  return fused;
}

}  // namespace pb::internal::mujoco
