// 3D replays (docs/replay.md) end to end: the real CLI writes the page, headless Chromium opens it
// from file:// and the page's own hook (window.multicpgReplay) is read back: no console errors,
// the pose it shows at a step is the simulation's at that step within 1 mm, its timeline holds
// the run's events, and a screenshot shows the robot. Also a robot file on rough ground, the
// tunnel, a model with a mesh, `multicpg replay` of saved runs and its refusals.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "body/fault_spec.h"
#include "cli_runner.h"
#include "report/image.h"
#include "robot/morphology.h"
#include "sim/fault_effects.h"
#include "sim/sim.h"
#include "sim/walk.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace multicpg;
using namespace multicpg::testing;

// The replay shows positions quantised to 0.1 mm; it must show the simulation's within 1 mm.
constexpr double kToleranceM = 1e-3;

const std::string kChromium =
    "chromium --headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader --disable-quic "
    "--no-first-run --disable-background-networking --disable-component-update --disable-sync "
    "--window-size=1000,800 ";

std::string slurp(const fs::path& p) {
  return read_file(p.string());
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

std::string unescape_html(std::string s) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) {
      s.replace(at, std::string(from).size(), to);
    }
  }
  return s;
}

// The page's console messages in Chromium's log (every one is a failure: the page logs nothing).
// Left out: the note Chromium's GPU process writes on every WebGL page when its software
// compositor reads the canvas back ("GL Driver Message (OpenGL, Performance, ...): GPU stall due
// to ReadPixels"), which no page can avoid in this headless configuration.
std::vector<std::string> console_lines(const std::string& log) {
  std::vector<std::string> out;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(":CONSOLE") == std::string::npos) continue;
    if (line.find("GL Driver Message (OpenGL, Performance") != std::string::npos &&
        line.find("GPU stall due to ReadPixels") != std::string::npos) {
      continue;
    }
    out.push_back(line);
  }
  return out;
}

// Opens a copy of `page` with `probe` (JavaScript) run after the page's scripts; the probe's
// result is a JSON value written into <pre id="probe">. Console lines go to `console`.
json probe_page(const fs::path& page, const std::string& probe, std::vector<std::string>& console) {
  std::string html = slurp(page);
  const std::size_t end = html.rfind("</body>");
  EXPECT_NE(end, std::string::npos);
  html.insert(end,
              "<script>(function(){const out=document.createElement('pre');out.id='probe';"
              "try{out.textContent=JSON.stringify((function(){" +
                  probe +
                  "})());}catch(e){out.textContent=JSON.stringify({exception:String(e)});}"
                  "document.body.appendChild(out);})();</script>");
  const fs::path copy = page.parent_path() / ("probe-" + page.filename().string());
  write_text(copy, html);
  const std::string profile = make_temp_dir("chromium-");
  const CliResult r = run_shell(kChromium + "--user-data-dir=" + profile +
                                " --enable-logging=stderr --v=0 --virtual-time-budget=5000 "
                                "--dump-dom file://" +
                                fs::absolute(copy).string());
  fs::remove_all(profile);
  console = console_lines(r.err);
  std::smatch m;
  const std::regex pre("<pre id=\"probe\">([^<]*)</pre>");
  if (!std::regex_search(r.out, m, pre)) {
    ADD_FAILURE() << "no probe result in the page's DOM\n" << r.err.substr(0, 2000);
    return json();
  }
  return json::parse(unescape_html(m[1].str()));
}

// What every page must say: loaded, no error, no console message.
void expect_clean(const json& result, const std::vector<std::string>& console) {
  EXPECT_FALSE(result.contains("exception")) << result.dump();
  EXPECT_EQ(result.value("ready", ""), "ready") << result.dump().substr(0, 500);
  EXPECT_EQ(result.value("errors", json::array()), json::array());
  for (const std::string& line : console) ADD_FAILURE() << "console: " << line;
}

const char* kStateProbe =
    "const r=window.multicpgReplay;return {ready:document.body.dataset.replay,"
    "errors:window.multicpgErrors,first:r.firstStep,last:r.lastStep,bodies:r.bodies(),"
    "events:r.events(),trials:r.trials()";

// The recording the page holds (its <script type="application/json">).
json page_data(const fs::path& page) {
  const std::string html = slurp(page);
  const std::string open = "<script type=\"application/json\" id=\"multicpg-replay-data\">";
  const std::size_t from = html.find(open);
  const std::size_t to = html.find("</script>", from);
  if (from == std::string::npos || to == std::string::npos) return json();
  return json::parse(html.substr(from + open.size(), to - from - open.size()));
}

// `multicpg replay SAVED` makes the recording `page` holds, its title aside.
void expect_same_replay(const fs::path& saved, const fs::path& page) {
  const fs::path again = saved.parent_path() / (saved.stem().string() + "-again.html");
  const CliResult re = run_cli("replay " + saved.string() + " --out " + again.string());
  ASSERT_EQ(re.exit_code, 0) << re.err;
  json a = page_data(page);
  json b = page_data(again);
  ASSERT_TRUE(a.is_object() && b.is_object());
  a.erase("title");
  b.erase("title");
  EXPECT_TRUE(a == b) << "the replay of " << saved << " differs from the run's own";
}

// The trunk (x, y, z) of each row of a `walk --csv` record.
std::vector<std::array<double, 3>> csv_trunk(const fs::path& csv) {
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string cell; std::getline(hs, cell, ',');) header.push_back(cell);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t x = col("x_m"), y = col("y_m"), z = col("z_m");
  std::vector<std::array<double, 3>> out;
  if (z >= header.size()) {
    ADD_FAILURE() << "no trunk columns in " << csv << ": " << line;
    return out;
  }
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) cells.push_back(cell);
    out.push_back({std::stod(cells[x]), std::stod(cells[y]), std::stod(cells[z])});
  }
  return out;
}

// The world position of `body` after each controller step of a walk, computed from the state's
// joint positions (mj_kinematics) in the model the physics steps then.
class BodyTrace final : public sim::Observer {
 public:
  BodyTrace(const sim::SimModel& model, const std::string& body)
      : id_(mj_name2id(model.mj.get(), mjOBJ_BODY, body.c_str())),
        scratch_(mj_makeData(model.mj.get())) {}
  ~BodyTrace() override { mj_deleteData(scratch_); }
  void on_start(const sim::SimModel& model, const sim::SimState& state) override {
    add(model, state);
  }
  void on_step(const sim::SimModel& model, const sim::SimState& state) override {
    add(model, state);
  }
  std::vector<std::array<double, 3>> rows;

 private:
  void add(const sim::SimModel& model, const sim::SimState& state) {
    const mjModel* m = sim::physics_model(model, state);
    std::copy(state.data->qpos, state.data->qpos + m->nq, scratch_->qpos);
    mj_kinematics(m, scratch_);
    rows.push_back(
        {scratch_->xpos[3 * id_], scratch_->xpos[3 * id_ + 1], scratch_->xpos[3 * id_ + 2]});
  }
  int id_;
  mjData* scratch_;
};

double distance(const json& shown, const std::array<double, 3>& truth) {
  return std::hypot(shown.at(0).get<double>() - truth[0], shown.at(1).get<double>() - truth[1],
                    shown.at(2).get<double>() - truth[2]);
}

TEST(Replay, WalkShowsTheSimulatedPosesAndEventsInChromium) {
  const fs::path dir = make_temp_dir("replay-walk-");
  const fs::path page = dir / "walk.html";
  const fs::path csv = dir / "walk.csv";
  const CliResult r = run_cli(
      "walk --steps 300 --disable R1 --fault R2.CTr:locked@100 "
      "--recover R1@200 --csv " +
      csv.string() + " --replay " + page.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + page.string()), std::string::npos) << r.out;

  // The same walk in this process: the foot of R2 (after its joint locks) at each step.
  const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
  const robot::Morphology& morph = model.controller.morphology;
  sim::WalkSpec walk;
  walk.steps = 300;
  walk.faults = {body::parse_fault(morph, "R1@0", false),
                 body::parse_fault(morph, "R2.CTr:locked@100", false),
                 body::parse_fault(morph, "R1@200", true)};
  BodyTrace foot(model, "R2_foot");
  walk.observer = &foot;
  sim::walk(model, walk);
  ASSERT_EQ(foot.rows.size(), 301u);
  const std::vector<std::array<double, 3>> trunk = csv_trunk(csv);
  ASSERT_EQ(trunk.size(), 301u);

  std::vector<std::string> console;
  const json result = probe_page(
      page,
      std::string(kStateProbe) +
          ",trunk:[0,150,300].map(s=>r.bodyPosition(s,'trunk')),"
          "foot:[0,120,250].map(s=>r.bodyPosition(s,'R2_foot')),shownStep:r.currentStep()};",
      console);
  expect_clean(result, console);
  EXPECT_EQ(result.at("first"), 0);
  EXPECT_EQ(result.at("last"), 300);
  const std::vector<int> trunk_steps{0, 150, 300};
  for (std::size_t i = 0; i < trunk_steps.size(); ++i) {
    EXPECT_LT(distance(result.at("trunk").at(i), trunk[trunk_steps[i]]), kToleranceM)
        << "trunk at step " << trunk_steps[i];
  }
  const std::vector<int> foot_steps{0, 120, 250};
  for (std::size_t i = 0; i < foot_steps.size(); ++i) {
    EXPECT_LT(distance(result.at("foot").at(i), foot.rows[foot_steps[i]]), kToleranceM)
        << "R2_foot at step " << foot_steps[i];
  }
  EXPECT_EQ(result.at("shownStep"), 250);

  // The timeline: the run's three faults, in order, at their steps.
  const json& events = result.at("events");
  ASSERT_EQ(events.size(), 3u) << events.dump();
  EXPECT_EQ(events[0].at("kind"), "fault");
  EXPECT_EQ(events[0].at("step"), "0");
  EXPECT_EQ(events[0].at("legs"), "R1");
  EXPECT_EQ(events[1].at("kind"), "fault");
  EXPECT_EQ(events[1].at("step"), "100");
  EXPECT_EQ(events[1].at("fault"), "R2.CTr:locked");
  EXPECT_EQ(events[2].at("kind"), "recovery");
  EXPECT_EQ(events[2].at("step"), "200");
  EXPECT_EQ(events[2].at("legs"), "R1");

  // Compact: 301 steps of 26 bodies take well under a kilobyte a step.
  EXPECT_LT(fs::file_size(page), 2'000'000u);

  // The walk's record (its faults in their one JSON shape) replays as the same recording.
  const CliResult saved =
      run_cli("walk --steps 300 --disable R1 --fault R2.CTr:locked@100 --recover R1@200 --json");
  ASSERT_EQ(saved.exit_code, 0) << saved.err;
  const json faults = json::parse(saved.out).at("faults");
  ASSERT_EQ(faults.size(), 3u);
  EXPECT_EQ(faults[1], json::parse(R"({"step": 100, "legs": "R2", "recover": false,
                                       "kind": "locked", "joint": "CTr"})"));
  write_text(dir / "walk.json", saved.out);
  expect_same_replay(dir / "walk.json", page);
  fs::remove_all(dir);
}

TEST(Replay, ScreenshotShowsTheRobotWithItsFailedLegInRed) {
  const fs::path dir = make_temp_dir("replay-shot-");
  const fs::path page = dir / "walk.html";
  ASSERT_EQ(run_cli("walk --steps 60 --disable R1 --replay " + page.string()).exit_code, 0);
  const fs::path shot = dir / "shot.png";
  const std::string profile = make_temp_dir("chromium-");
  const CliResult r = run_shell(kChromium + "--user-data-dir=" + profile +
                                " --virtual-time-budget=3000 --screenshot=" + shot.string() +
                                " file://" + fs::absolute(page).string());
  fs::remove_all(profile);
  ASSERT_TRUE(fs::exists(shot)) << r.err;
  const report::Image image = report::read_png(shot);
  std::set<std::uint32_t> colours;
  int red = 0;
  int grey = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      colours.insert(static_cast<std::uint32_t>(p[0] << 16 | p[1] << 8 | p[2]));
      // R1 failed: red as the films draw it (0.85, 0.08, 0.08), shaded.
      red += p[0] > 90 && p[1] < p[0] / 3 && p[2] < p[0] / 3 ? 1 : 0;
      // The robot's grey segments (0.5, 0.5, 0.5), shaded: neither the ground's blue-grey nor
      // the sky's.
      grey += std::abs(p[0] - p[1]) < 6 && std::abs(p[1] - p[2]) < 6 && p[0] > 40 && p[0] < 200;
    }
  }
  EXPECT_GT(colours.size(), 100u) << "a blank screenshot";
  EXPECT_GT(red, 30) << "the failed leg R1 is not in the picture";
  EXPECT_GT(grey, 300) << "the robot's segments are not in the picture";
  fs::remove_all(dir);
}

// A model-based learner's trials show its forecast of E in the trial table, as the run recorded
// it (docs/learning.md "Inside the model"); the annealing's table has no such column.
TEST(Replay, AModelLearnersTrialTableShowsItsForecasts) {
  const fs::path dir = make_temp_dir("replay-forecast-");
  const fs::path page = dir / "learn.html";
  const CliResult r = run_cli(
      "learn --mode paper --disable R1 --seed 1 --learner bayes "
      "--max-trials 3 --json --replay " +
      page.string());
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 3) << r.err;
  const json trace = json::parse(r.out).at("trace");
  ASSERT_FALSE(trace.empty());
  std::vector<std::string> console;
  const json result =
      probe_page(page, std::string(kStateProbe) + ",header:r.trialHeader()};", console);
  expect_clean(result, console);
  const json& header = result.at("header");
  const auto column = std::find(header.begin(), header.end(), "predicted (deg) [band]");
  ASSERT_NE(column, header.end()) << header.dump();
  const auto at = static_cast<std::size_t>(column - header.begin());
  ASSERT_EQ(result.at("trials").size(), trace.size());
  for (std::size_t t = 0; t < trace.size(); ++t) {
    const std::string cell = result.at("trials")[t].at("cells")[at];
    double e = 0.0;
    double low = 0.0;
    double high = 0.0;
    ASSERT_EQ(std::sscanf(cell.c_str(), "%lf [%lf, %lf]", &e, &low, &high), 3) << cell;
    EXPECT_NEAR(e, trace[t].at("predicted_e_deg").get<double>(), 0.005) << cell;
    EXPECT_NEAR(low, trace[t].at("predicted_e_low_deg").get<double>(), 0.005) << cell;
    EXPECT_NEAR(high, trace[t].at("predicted_e_high_deg").get<double>(), 0.005) << cell;
  }
  // The saved run replays with its forecasts.
  write_text(dir / "learn.json", r.out);
  expect_same_replay(dir / "learn.json", page);
  fs::remove_all(dir);
}

TEST(Replay, LearningTimelineHoldsEveryEventOfTheRun) {
  const fs::path dir = make_temp_dir("replay-learn-");
  const fs::path page = dir / "learn.html";
  const CliResult r =
      run_cli("learn --mode paper --disable R1 --seed 1 --json --replay " + page.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json learned = json::parse(r.out);
  write_text(dir / "learn.json", r.out);

  std::vector<std::string> console;
  const json result =
      probe_page(page, std::string(kStateProbe) + ",header:r.trialHeader()};", console);
  expect_clean(result, console);
  // The annealing has no model: no forecast column.
  for (const json& th : result.at("header")) {
    EXPECT_EQ(th.get<std::string>().find("predicted"), std::string::npos) << th;
  }
  const json& events = result.at("events");
  const json& trace = learned.at("trace");
  // The fault, the detection, each trial, the end of the episode.
  ASSERT_EQ(events.size(), 3 + trace.size()) << events.dump();
  EXPECT_EQ(events[0].at("kind"), "fault");
  EXPECT_EQ(events[1].at("kind"), "detection");
  EXPECT_EQ(events[1].at("step"), std::to_string(learned.at("detection_step").get<long>()));
  const robot::Morphology& morph = robot::morphology(robot::RobotKind::hexapod);
  for (std::size_t t = 0; t < trace.size(); ++t) {
    const json& e = events[2 + t];
    EXPECT_EQ(e.at("kind"), "trial_end");
    EXPECT_EQ(e.at("trial"), std::to_string(trace[t].at("trial").get<int>()));
    std::string periods;
    for (const robot::Leg& leg : morph.legs) {
      if (!periods.empty()) periods += ',';
      periods += std::to_string(trace[t].at("periods").at(leg.name).get<int>());
    }
    EXPECT_EQ(e.at("periods"), periods);
    EXPECT_NEAR(std::stod(e.at("deviation").get<std::string>()),
                trace[t].at("deviation_deg").get<double>(), 1e-9);
    EXPECT_EQ(e.at("accepted"), trace[t].at("accepted").get<bool>() ? "true" : "false");
  }
  const json& end = events.back();
  EXPECT_EQ(end.at("kind"), "episode_end");
  EXPECT_EQ(end.at("accepted"), learned.at("converged").get<bool>() ? "true" : "false");
  EXPECT_EQ(result.at("trials").size(), trace.size());

  // `multicpg replay` of the saved result makes the same recording.
  expect_same_replay(dir / "learn.json", page);

  // A result this simulation does not make again (other ground) is refused, one line.
  expect_bad_input("replay " + (dir / "learn.json").string() + " --terrain rough:0.02 --out " +
                       (dir / "x.html").string(),
                   "does not rerun as saved");
  fs::remove_all(dir);
}

TEST(Replay, RobotFileOnRoughGroundReplays) {
  const fs::path dir = make_temp_dir("replay-spider-");
  const fs::path page = dir / "spider.html";
  const fs::path csv = dir / "spider.csv";
  const CliResult r = run_cli(std::string("walk --robot ") + MULTICPG_SOURCE_DIR +
                              "/examples/robots/spider_quadruped.toml --terrain rough:0.02 "
                              "--steps 200 --disable R1 --csv " +
                              csv.string() + " --replay " + page.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json data = page_data(page);
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data.at("hfields").size(), 1u) << "the rough ground's heightfield";
  EXPECT_EQ(data.at("legs").size(), 4u);
  std::vector<std::string> console;
  const json result = probe_page(
      page, std::string(kStateProbe) + ",trunk:[0,200].map(s=>r.bodyPosition(s,'base'))};",
      console);
  expect_clean(result, console);
  const std::vector<std::array<double, 3>> trunk = csv_trunk(csv);
  ASSERT_EQ(trunk.size(), 201u);
  EXPECT_LT(distance(result.at("trunk").at(0), trunk[0]), kToleranceM);
  EXPECT_LT(distance(result.at("trunk").at(1), trunk[200]), kToleranceM);
  fs::remove_all(dir);
}

TEST(Replay, TunnelAndMeshesReplay) {
  const fs::path dir = make_temp_dir("replay-tunnel-");
  // The tunnel's walls are geoms of the model.
  const fs::path tunnel = dir / "tunnel.html";
  ASSERT_EQ(run_cli("tunnel --disable R1 --max-steps 150 --replay " + tunnel.string()).exit_code,
            0);
  const json data = page_data(tunnel);
  ASSERT_TRUE(data.is_object());
  EXPECT_TRUE(data.at("tunnel").is_object());
  int walls = 0;
  for (const json& g : data.at("geoms")) {
    walls += g.at("name").get<std::string>().find("wall") != std::string::npos ? 1 : 0;
  }
  EXPECT_GE(walls, 2);

  // A robot file whose trunk is a mesh (the spider's, its box as a mesh of 8 vertices).
  const fs::path examples = fs::path(MULTICPG_SOURCE_DIR) / "examples" / "robots";
  std::string xml = slurp(examples / "spider_quadruped.xml");
  const std::regex base_geom("<geom name=\"base\" type=\"box\" size=\"([^\"]*)\"([^>]*)/>");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(xml, m, base_geom)) << "the spider's trunk box";
  std::istringstream sizes(m[1].str());
  double sx = 0, sy = 0, sz = 0;
  sizes >> sx >> sy >> sz;
  std::ostringstream vertices;
  for (int i = 0; i < 8; ++i) {
    vertices << (i & 1 ? sx : -sx) << " " << (i & 2 ? sy : -sy) << " " << (i & 4 ? sz : -sz) << " ";
  }
  xml.replace(m.position(0), m.length(0),
              "<geom name=\"base\" type=\"mesh\" mesh=\"trunk_mesh\"" + m[2].str() + "/>");
  const std::size_t asset = xml.find("<worldbody>");
  ASSERT_NE(asset, std::string::npos);
  xml.insert(asset,
             "<asset><mesh name=\"trunk_mesh\" vertex=\"" + vertices.str() + "\"/></asset>\n");
  write_text(dir / "spider_quadruped.xml", xml);
  write_text(dir / "spider_mesh.toml", slurp(examples / "spider_quadruped.toml"));
  const fs::path page = dir / "mesh.html";
  const CliResult r = run_cli("walk --robot " + (dir / "spider_mesh.toml").string() +
                              " --steps 100 --replay " + page.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json mesh = page_data(page);
  ASSERT_TRUE(mesh.is_object());
  EXPECT_EQ(mesh.at("meshes").size(), 1u);
  for (const fs::path& p : {tunnel, page}) {
    std::vector<std::string> console;
    expect_clean(probe_page(p, std::string(kStateProbe) + "};", console), console);
  }
  fs::remove_all(dir);
}

TEST(Replay, ExperimentRunFilesReplayAndBadRunFilesAreRefused) {
  const fs::path dir = make_temp_dir("replay-runs-");
  write_text(dir / "e.toml",
             "scenarios = [\"R1\"]\nruns = 1\n[learning]\nmode = \"paper\"\n"
             "[learning.annealing]\nmax_trials = 3\n");
  const fs::path out = dir / "out";
  const CliResult ran =
      run_cli("run " + (dir / "e.toml").string() + " --out " + out.string() + " --jobs 1");
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  fs::path run;
  for (const auto& entry : fs::directory_iterator(out / "runs")) run = entry.path();
  ASSERT_FALSE(run.empty());
  const fs::path page = dir / "run.html";
  const CliResult r = run_cli("replay " + run.string() + " --out " + page.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> console;
  const json result = probe_page(page, std::string(kStateProbe) + "};", console);
  expect_clean(result, console);
  EXPECT_FALSE(result.at("events").empty());
  expect_bad_input(
      "replay " + run.string() + " --terrain rough:0.02 --out " + (dir / "x.html").string(),
      "give no simulation flags");

  // Missing, truncated, damaged, of another version: one line naming the file, exit 2.
  expect_bad_input(
      "replay " + (dir / "missing.json").string() + " --out " + (dir / "x.html").string(),
      "missing.json");
  const std::string learned = run_cli("walk --steps 50 --disable R1 --json").out;
  write_text(dir / "truncated.json", learned.substr(0, learned.size() / 2));
  expect_bad_input(
      "replay " + (dir / "truncated.json").string() + " --out " + (dir / "x.html").string(),
      "truncated.json");
  json other = json::parse(learned);
  other.erase("warmup");
  other["format_version"] = 99;
  write_text(dir / "other.json", other.dump());
  expect_bad_input(
      "replay " + (dir / "other.json").string() + " --out " + (dir / "x.html").string(),
      "other.json");
  // A walk edited to 10^8 steps is refused before a step is walked (docs/replay.md: a replay
  // holds at most 1000000 steps), and so is a FIFO named as the run (never waited on).
  json long_walk = json::parse(learned);
  long_walk["steps"] = 100000000;
  write_text(dir / "long.json", long_walk.dump());
  expect_bad_input("replay " + (dir / "long.json").string() + " --out " + (dir / "x.html").string(),
                   "long.json': steps 100000000 is outside 1..1000000");
  ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
  expect_bad_input("replay " + (dir / "fifo.json").string() + " --out " + (dir / "x.html").string(),
                   "fifo.json: is a FIFO, not a file");
  std::string damaged = slurp(run);
  damaged.replace(damaged.find("\"trials\""), 8, "\"TRIALS\"");
  write_text(dir / "runs-damaged.json", damaged);
  fs::copy_file(dir / "runs-damaged.json", out / "runs" / "damaged.json");
  expect_bad_input(
      "replay " + (out / "runs" / "damaged.json").string() + " --out " + (dir / "x.html").string(),
      "damaged.json");
  // A page that cannot be written fails before any run.
  for (const std::string& command :
       std::vector<std::string>{"walk --steps 10", "learn --disable R1", "tunnel --disable R1",
                                "render --out " + (dir / "r.png").string()}) {
    expect_bad_input(command + " --replay " + (dir / "x.mp4").string(), "--replay");
    expect_bad_input(command + " --replay " + (dir / "no" / "x.html").string(), "--replay");
  }
  expect_bad_input("replay " + run.string() + " --out " + (dir / "x.png").string(), "x.png");
  EXPECT_FALSE(fs::exists(dir / "x.html"));
  fs::remove_all(dir);
}

}  // namespace
