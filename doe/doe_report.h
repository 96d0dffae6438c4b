#pragma once
// An analysis of variance as JSON and as an HTML table, for every report that prints one
// (planter-dem's calibration, planter-sim's sweep).
#include <nlohmann/json.hpp>
#include <string>

#include "doe/doe.h"

namespace planter::doe {

nlohmann::json anova_json(const Anova& a);
nlohmann::json lack_of_fit_json(const LackOfFit& l);
// Model, terms (p < 0.05 in bold) and residual, then R^2, adjusted R^2, adequate precision.
std::string anova_table_html(const Anova& a);

}  // namespace planter::doe
