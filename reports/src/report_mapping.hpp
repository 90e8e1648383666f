// Reading an engine's `mapping` JSON (SPEC §5) for people: what it could not
// express, and the whole mapping as "path: value" lines.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace pb::internal {

// Every entry of every member whose key starts with "not_express" (the
// adapters write "not_expressed" or "not_expressible"), at any depth, and every
// string value that starts with "not expressed", in document order. Entries of
// a member inside a list of pairs or bodies are prefixed with that item's name.
[[nodiscard]] std::vector<std::string> not_expressed(const nlohmann::json& mapping);

// The mapping flattened to (path, value) pairs: "pairs[0].solref" ->
// "[-10000, -10]". Arrays of scalars stay one value; arrays of objects and
// objects are descended into. Strings are shown without quotes.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> flatten_mapping(
    const nlohmann::json& mapping);

}  // namespace pb::internal
