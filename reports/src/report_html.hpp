// The self-contained HTML page of a report: the page template with uPlot's
// JS and CSS (and its MIT licence text) inlined and the report's data embedded
// as JSON; nothing is fetched when the page is opened.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "report_model.hpp"
#include "report_web_assets.hpp"

namespace pb::internal {

// The report as the page's script reads it. Series share time grids: equal
// down-sampled time vectors are stored once in "grids" and referenced by
// index. Times keep 9 significant digits, values 7 (well below a pixel at any
// zoom a reader can reach within one contact pulse).
[[nodiscard]] nlohmann::json report_data_json(const Report& report);

// Replaces each "@@NAME@@" token of `page` by its value in one pass (values
// are not searched for tokens). Throws std::invalid_argument naming a token
// of `values` the template lacks.
[[nodiscard]] std::string fill_template(
    const std::string& page, const std::vector<std::pair<std::string, std::string>>& values);

// The whole page.
[[nodiscard]] std::string report_html(const Report& report, const WebAssets& assets);

}  // namespace pb::internal
