#include "experiments/sweep_tables.h"

#include <set>
#include <string>

#include "common/atomic_file.h"

namespace multicpg::experiments {
namespace {

namespace fs = std::filesystem;
using document::value_text;
using nlohmann::json;

constexpr int kJsonIndent = 2;

std::string cell(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number_float()) return shortest(v.get<double>());
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_array() || v.is_object()) return value_text(v);
  return v.dump();  // integers
}

// The columns every CSV row of a run starts with: key, scenario, run, seed, grid values.
std::vector<std::string> run_columns(const Sweep& sweep) {
  std::vector<std::string> cols{"key", "scenario", "run", "seed"};
  for (const GridAxis& a : sweep.grid) cols.push_back(a.key);
  return cols;
}

std::vector<std::string> run_cells(const Sweep& sweep, const PlannedRun& r) {
  const Task& t = r.task;
  std::vector<std::string> cells{t.key, r.label.scenario, std::to_string(t.run),
                                 std::to_string(t.seed)};
  for (const GridAxis& a : sweep.grid) cells.push_back(cell(r.label.grid.at(a.key)));
  return cells;
}

}  // namespace

ExperimentTable write_results(const Sweep& sweep, const fs::path& out,
                              const std::vector<json>& results) {
  const robot::Morphology& morph = robot::morphology(sweep.robot);
  ExperimentTable table{sweep.table, std::string(robot::to_string(sweep.robot)),
                        summarize(morph, tasks_of(sweep), results)};
  Table data;
  Table shown;
  if (sweep.table == ExperimentKind::beta) {
    data = beta_data(table.rows);
    shown = beta_table(table.rows);
  } else if (sweep.table == ExperimentKind::grid) {
    data = scenario_data(table.rows, "group");
    shown = scenario_table(table.rows, "Grid point");
  } else {
    data = scenario_data(table.rows);
    shown = scenario_table(table.rows);
  }
  write_file_atomic(out / "table.csv", to_csv(data));
  write_file_atomic(out / "table.md", to_markdown(shown));
  write_file_atomic(out / "runs.csv", to_csv(runs_table(sweep, results)));
  write_file_atomic(out / "trials.csv", to_csv(trials_table(sweep, results)));
  json rows = json::array();
  for (const GroupSummary& row : table.rows) rows.push_back(to_json(row));
  json summary{{"experiment", to_string(table.experiment)},
               {"robot", table.robot},
               {"arguments", sweep.resolved},
               {"rows", rows}};
  record_robot_file(summary, sweep.robot_file);
  write_file_atomic(out / "summary.json", summary.dump(kJsonIndent) + "\n");
  return table;
}

Table runs_table(const Sweep& sweep, const std::vector<json>& results) {
  const robot::Morphology& morph = robot::morphology(sweep.robot);
  Table t;
  for (const std::string& c : run_columns(sweep)) t.columns.push_back({c});
  const std::vector<std::string> outcome{"converged",
                                         "status",
                                         "reason",
                                         "trials",
                                         "initial_deviation_deg",
                                         "final_deviation_deg",
                                         "steps_walked",
                                         "detection_step",
                                         "settle_steps",
                                         "steering_effort"};
  for (const std::string& c : outcome) t.columns.push_back({c});
  for (const robot::Leg& leg : morph.legs) t.columns.push_back({"period_" + leg.name});
  const bool holds = sweep.resolved.at("record").at("check_windows").get<long>() > 0;
  if (holds) t.columns.push_back({"holds_after"});
  for (std::size_t i = 0; i < results.size(); ++i) {
    const json& r = results[i];
    std::vector<std::string> cells = run_cells(sweep, sweep.runs[i]);
    for (const std::string& c : outcome) cells.push_back(cell(r.value(c, json())));
    for (const robot::Leg& leg : morph.legs) cells.push_back(cell(r.at("periods").at(leg.name)));
    if (holds) cells.push_back(cell(r.value("holds_after", json())));
    t.add_row(std::move(cells));
  }
  return t;
}

Table trials_table(const Sweep& sweep, const std::vector<json>& results) {
  const robot::Morphology& morph = robot::morphology(sweep.robot);
  Table t;
  for (const std::string& c : run_columns(sweep)) t.columns.push_back({c});
  t.columns.push_back({"trial"});
  for (const robot::Leg& leg : morph.legs) t.columns.push_back({"period_" + leg.name});
  // The neutral fields of a trial, then every learner's own details (learning/learner.h).
  std::set<std::string> details;
  for (const json& r : results) {
    for (const json& trial : r.value("trace", json::array())) {
      for (const auto& item : trial.items()) details.insert(item.key());
    }
  }
  std::vector<std::string> fields{"deviation_deg", "accepted"};
  for (const char* neutral : {"trial", "periods", "deviation_deg", "accepted"}) {
    details.erase(neutral);
  }
  fields.insert(fields.end(), details.begin(), details.end());
  for (const std::string& c : fields) t.columns.push_back({c});
  for (std::size_t i = 0; i < results.size(); ++i) {
    for (const json& trial : results[i].value("trace", json::array())) {
      std::vector<std::string> cells = run_cells(sweep, sweep.runs[i]);
      cells.push_back(cell(trial.at("trial")));
      for (const robot::Leg& leg : morph.legs) {
        cells.push_back(cell(trial.at("periods").at(leg.name)));
      }
      for (const std::string& c : fields) cells.push_back(cell(trial.value(c, json())));
      t.add_row(std::move(cells));
    }
  }
  return t;
}

}  // namespace multicpg::experiments
