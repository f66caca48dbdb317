#include "report/stages/stage.h"

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/user_text.h"

namespace multicpg::report {

const std::vector<Stage>& reproduce_stages() {
  static const std::vector<Stage> stages{
      {"gaits", {"gait"}, gaits_stage},
      {"cpg-sync", {"cpg-sync"}, cpg_sync_stage},
      {"walking", {}, walking_stage},
      {"learning-r1", {"learning-trace", "motor", "contacts", "trunk-path"}, learning_r1_stage},
      {"hexapod-table", {"learning-hexapod"}, hexapod_table_stage, {}, /*early=*/true},
      {"quadruped-table", {"learning-quadruped"}, quadruped_table_stage, {}, /*early=*/true},
      {"beta", {"beta"}, beta_stage, {}, /*early=*/true},
      // "Our learning" in the tunnel is the hexapod table's most frequent learned combination.
      {"tunnel", {}, tunnel_stage, {"hexapod-table"}, /*early=*/true},
      // Draws the committed calibration data (docs/calibration): seconds.
      {"calibration", {"calibration"}, calibration_stage},
      // Where the quadruped table's learning runs with L2 disabled fall in the landscape.
      {"landscape", {"landscape"}, landscape_stage, {"quadruped-table"}},
      // Replays the committed landscape dataset (data/landscapes): CPU-minutes, no walking.
      {"learners", {"learner-benchmark"}, learner_benchmark_stage},
  };
  return stages;
}

const Stage& stage_by_id(std::string_view id) {
  std::vector<std::string> known;
  for (const Stage& s : reproduce_stages()) {
    if (s.id == id) return s;
    known.emplace_back(s.id);
  }
  throw BadInput(unknown_name("reproduce stage", id, known));
}

std::filesystem::path StageContext::dir(const std::string& name) const {
  const std::filesystem::path d = options.out / name;
  ensure_writable_dir(d);
  return d;
}

std::string StageContext::rel(const std::filesystem::path& file) const {
  return std::filesystem::relative(file, options.out).generic_string();
}

experiments::ExperimentSpec StageContext::experiment(robot::RobotKind kind, const std::string& name,
                                                     int runs) const {
  experiments::ExperimentSpec spec;
  spec.robot.kind = kind;
  spec.runs = runs;
  spec.seed = options.seed;
  spec.jobs = options.jobs;
  spec.out = dir("experiments/" + name);
  spec.progress = options.progress;
  spec.progress_label = "experiment " + name;
  spec.robot.sim = options.sim;
  spec.base.mode = learning::Mode::paper;  // the paper's experiments, its algorithm
  return spec;
}

std::vector<std::string> leg_names(const robot::Morphology& morph) {
  std::vector<std::string> out;
  for (const robot::Leg& leg : morph.legs) out.push_back(leg.name);
  return out;
}

}  // namespace multicpg::report
