// The fixed part of the Box2D adapter's mapping (SPEC §5 `mapping`): how the
// case's frame, geometry and contact laws are expressed in Box2D and what
// Box2D cannot express. The per-case part (bodies, pairs, onsets) is built by
// the engine.
#pragma once

#include <nlohmann/json.hpp>

namespace pb::internal::box2d {

// The notes for engine mode (rigid contact, restitution) or injection mode;
// interval_force: the contacts table's force is the mean over each output
// interval (box2d.reported_force), else the last step's.
[[nodiscard]] nlohmann::json mapping_notes(bool inject, bool interval_force = false);

}  // namespace pb::internal::box2d
