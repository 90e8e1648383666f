#include "report_mapping.hpp"

#include <algorithm>

namespace pb::internal {

namespace {

bool is_scalar_array(const nlohmann::json& j) {
  return j.is_array() && std::all_of(j.begin(), j.end(), [](const nlohmann::json& e) {
           return !e.is_object() && !e.is_array();
         });
}

std::string scalar_text(const nlohmann::json& j) {
  return j.is_string() ? j.get<std::string>() : j.dump();
}

// the name an object in a list goes by, for prefixes: its name, pair or body
std::string item_name(const nlohmann::json& j) {
  for (const char* key : {"name", "pair", "body"}) {
    if (j.is_object() && j.contains(key) && j[key].is_string()) return j[key].get<std::string>();
  }
  return "";
}

void collect_not_expressed(const nlohmann::json& j, const std::string& prefix,
                           std::vector<std::string>& out) {
  if (j.is_object()) {
    const std::string name = item_name(j);
    const std::string here = name.empty() ? prefix : (prefix.empty() ? name : prefix + "/" + name);
    for (const auto& [key, value] : j.items()) {
      if (key.rfind("not_express", 0) == 0) {
        const std::string lead = here.empty() ? "" : here + ": ";
        if (value.is_array()) {
          for (const auto& e : value) out.push_back(lead + scalar_text(e));
        } else if (!value.is_null() && !(value.is_string() && value.get<std::string>().empty())) {
          out.push_back(lead + scalar_text(value));
        }
      } else {
        collect_not_expressed(value, here, out);
      }
    }
  } else if (j.is_array()) {
    for (const auto& e : j) collect_not_expressed(e, prefix, out);
  } else if (j.is_string() && j.get<std::string>().rfind("not expressed", 0) == 0) {
    out.push_back((prefix.empty() ? "" : prefix + ": ") + j.get<std::string>());
  }
}

void flatten(const nlohmann::json& j, const std::string& path,
             std::vector<std::pair<std::string, std::string>>& out) {
  if (j.is_object()) {
    if (j.empty()) out.emplace_back(path, "{}");
    for (const auto& [key, value] : j.items()) {
      flatten(value, path.empty() ? key : path + "." + key, out);
    }
  } else if (j.is_array() && !is_scalar_array(j)) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      flatten(j[i], path + "[" + std::to_string(i) + "]", out);
    }
  } else if (j.is_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < j.size(); ++i) text += (i ? ", " : "") + scalar_text(j[i]);
    out.emplace_back(path, text + "]");
  } else {
    out.emplace_back(path, scalar_text(j));
  }
}

}  // namespace

std::vector<std::string> not_expressed(const nlohmann::json& mapping) {
  std::vector<std::string> out;
  collect_not_expressed(mapping, "", out);
  return out;
}

std::vector<std::pair<std::string, std::string>> flatten_mapping(const nlohmann::json& mapping) {
  std::vector<std::pair<std::string, std::string>> out;
  flatten(mapping, "", out);
  return out;
}

}  // namespace pb::internal
