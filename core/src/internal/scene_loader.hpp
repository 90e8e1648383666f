// The scene tables of a case file (SPEC §11, cases/README.md "Scenes"):
// [[generate]] makes bodies (a stack of N, a brick pyramid of R rows, a row
// of N touching or gapped bodies, a grid of N bodies), [[contact_groups]]
// lets every pair of a group touch under one law. Called by build_case
// (case_loader.cpp) in this order: generated bodies after [[bodies]], groups
// after [[contacts]], then the resting poses (which need the laws), then the
// start-overlap check of the groups' pairs.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "planarbench/case.hpp"
#include "toml_reader.hpp"

namespace pb::internal {

// body name -> index into Case::bodies
using BodyNames = std::unordered_map<std::string, int>;

struct SceneTables {
  std::vector<TableReader> generators;  // [[generate]]
  std::vector<TableReader> groups;      // [[contact_groups]]
};

// appends the bodies of every [[generate]] table to c.bodies (named
// <name>_1 .. <name>_N) and records each table in c.generated
void read_generated_bodies(const SceneTables& scene, int default_outline_points, Case& c,
                           BodyNames& names);

// reads every [[contact_groups]] table into c.contact_groups; a group names
// bodies or generators (all of a generator's bodies)
void read_contact_groups(const SceneTables& scene, Case& c, const BodyNames& names);

// moves the bodies of every generator with start = "resting" to the static
// pose of the case's law (each interface pressed by the weight it carries)
void place_resting_scenes(const SceneTables& scene, Case& c);

// no pair of a group starts with a centre inside its partner (the rule
// check_start_overlaps applies to declared pairs), found by a broad phase
void check_group_start_overlaps(const SceneTables& scene, const Case& c,
                                const std::vector<TableReader>& body_tables);

// throws the InputError for `field` of body i: on its [[bodies]] table, or on
// the [[generate]] table that made it (naming the body)
[[noreturn]] void fail_on_body(const SceneTables& scene, const Case& c,
                               const std::vector<TableReader>& body_tables, int i,
                               const std::string& field, const std::string& what);

}  // namespace pb::internal
