#include "doe/doe_report.h"

#include <sstream>

namespace planter::doe {

nlohmann::json anova_json(const Anova& a) {
  nlohmann::json j;
  j["intercept"] = a.intercept;
  j["model"] = {{"sum_of_squares", a.model_ss},
                {"df", a.model_df},
                {"f_value", a.model_f},
                {"p_value", a.model_p}};
  j["residual"] = {{"sum_of_squares", a.residual_ss}, {"df", a.residual_df}};
  j["r2"] = a.r2;
  j["r2_adjusted"] = a.r2_adjusted;
  j["adequate_precision"] = a.adequate_precision;
  for (const auto& t : a.terms) {
    j["terms"].push_back({{"term", t.name},
                          {"coefficient", t.coefficient},
                          {"sum_of_squares", t.sum_of_squares},
                          {"f_value", t.f_value},
                          {"p_value", t.p_value}});
  }
  return j;
}

nlohmann::json lack_of_fit_json(const LackOfFit& l) {
  return {{"sum_of_squares", l.ss},
          {"df", l.df},
          {"pure_error_sum_of_squares", l.pure_error_ss},
          {"pure_error_df", l.pure_error_df},
          {"f_value", l.f_value},
          {"p_value", l.p_value}};
}

std::string anova_table_html(const Anova& a) {
  std::ostringstream s;
  s.precision(4);
  s << "<table><tr><th>source</th><th>coefficient</th><th>sum of squares</th><th>F</th>"
       "<th>p</th></tr><tr><td>model</td><td>"
    << a.intercept << " (intercept)</td><td>" << a.model_ss << "</td><td>" << a.model_f
    << "</td><td>" << a.model_p << "</td></tr>";
  for (const auto& t : a.terms) {
    s << "<tr><td>" << t.name << "</td><td>" << t.coefficient << "</td><td>" << t.sum_of_squares
      << "</td><td>" << t.f_value << "</td><td>" << (t.p_value < 0.05 ? "<b>" : "") << t.p_value
      << (t.p_value < 0.05 ? "</b>" : "") << "</td></tr>";
  }
  s << "<tr><td>residual</td><td></td><td>" << a.residual_ss << " (df " << a.residual_df
    << ")</td></tr></table><p>R<sup>2</sup> " << a.r2 << ", adjusted " << a.r2_adjusted
    << ", adequate precision " << a.adequate_precision << "</p>";
  return s.str();
}

}  // namespace planter::doe
