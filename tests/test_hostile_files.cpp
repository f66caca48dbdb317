// Hostile experiment files through the real CLI (docs/experiments.md "Experiment files"): every
// file below is generated here, the giants included (200,000 levels of tables, dotted keys, lists
// and inline tables; grids of 2*10^9 runs and more; lists of millions of values; /dev/zero, a FIFO,
// a symlink loop, a directory), and `multicpg run FILE --check` must refuse each with exit 2,
// exactly one line on stderr naming the file and what is wrong, and nothing on stdout. A guard
// of a few seconds catches a hang; nothing here measures speed.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli_process.h"
#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

namespace fs = std::filesystem;

// Far more than any case takes (they are refused before any work); catches a hang.
constexpr std::chrono::seconds kHangGuard{30};
// The depth of the giants, and the lengths of the long lists.
constexpr int kGiantDepth = 200'000;
// Peak memory a refused giant grid may take (the issue's bound): it is refused before any run
// is allocated. Not checked under AddressSanitizer, whose shadow memory alone is larger.
#if defined(__SANITIZE_ADDRESS__)
#define MULTICPG_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MULTICPG_ASAN 1
#endif
#endif
#ifdef MULTICPG_ASAN
constexpr long kGiantGridMaxRssKb = 0;
#else
constexpr long kGiantGridMaxRssKb = 50 * 1024;
#endif

std::string repeat(const std::string& part, int times) {
  std::string out;
  out.reserve(part.size() * static_cast<std::size_t>(times));
  for (int i = 0; i < times; ++i) out += part;
  return out;
}

// `n` values "v" as a TOML list.
std::string list_of(int n, const std::string& v) {
  std::string out = "[";
  for (int i = 0; i < n; ++i) out += (i == 0 ? "" : ",") + v;
  return out + "]";
}

struct Case {
  std::string name;
  // Writes the file at the path it is given, or returns another path to use (a device).
  std::function<std::string(const std::string&)> make;
  std::string mention;     // what the one stderr line must say
  std::string extra = "";  // more arguments after --check
  bool names_file = true;  // the line names the file (not for a bad flag)
  long max_rss_kb = 0;     // > 0: peak memory bound
};

std::function<std::string(const std::string&)> text(const std::string& content) {
  return [content](const std::string& path) {
    std::ofstream(path, std::ios::binary) << content;
    return path;
  };
}

const std::string kOk = "scenarios = [\"R1\"]\n";

std::vector<Case> giant_cases() {
  const std::string a = repeat("a.", kGiantDepth - 1) + "a";
  const std::string deep = "nested more than 64 levels deep";
  return {
      {"tables", text(kOk + "[" + a + "]\n"), deep},
      {"arrays of tables", text(kOk + "[[" + a + "]]\n"), deep},
      {"dotted key", text(kOk + a + " = 1\n"), deep},
      {"dotted key in a table", text(kOk + "[learning]\n" + a + " = 1\n"), deep},
      {"dotted key in an inline table", text(kOk + "x = {" + a + " = 1}\n"), deep},
      {"lists", text(kOk + "x = " + repeat("[", kGiantDepth) + repeat("]", kGiantDepth) + "\n"),
       deep},
      {"inline tables",
       text(kOk + "x = " + repeat("{a=", kGiantDepth) + "1" + repeat("}", kGiantDepth) + "\n"),
       deep},
      {"lists of inline tables",
       text(kOk + "x = " + repeat("[{a=", kGiantDepth / 2) + "1" + repeat("}]", kGiantDepth / 2) +
            "\n"),
       deep},
      {"65 levels", text(kOk + repeat("a.", 64) + "a = 1\n"), deep},
      {"2e9-run grid",
       text(kOk + "runs = 2000\n[learning.annealing]\nbeta = " + list_of(1000, "0.5") +
            "\nthreshold_deg = " + list_of(1000, "5") + "\n"),
       "2000000000 runs (learning.annealing.beta: 1000 values x learning.annealing.threshold_deg: "
       "1000 values x 1 scenario x 2000 runs), more than the 100000 allowed (--max-runs)",
       "", true, kGiantGridMaxRssKb},
      {"1e10-run grid",
       text(kOk + "runs = 10000\n[learning.annealing]\nbeta = " + list_of(1000, "0.5") +
            "\nmax_trials = " + list_of(1000, "20") + "\n"),
       "10000000000 runs", "", true, kGiantGridMaxRssKb},
      {"grid past 64 bits",
       text("scenarios = \"all\"\nruns = 100000\n[learning.annealing]\nbeta = " +
            list_of(10000, "1") + "\nthreshold_deg = " + list_of(10000, "5") + "\nmax_trials = " +
            list_of(10000, "20") + "\n[learning]\nwindow_steps = " + list_of(10000, "400") + "\n"),
       "about 2.40e+22 runs", "", true, kGiantGridMaxRssKb},
      {"2.4e6 runs", text("scenarios = \"all\"\nruns = 100000\n"),
       "2400000 runs (24 scenarios x 100000 runs)"},
      {"five million values",
       text(kOk + "[learning.annealing]\nbeta = " + list_of(5'000'000, "0") + "\n"),
       "more than the 1 MiB an experiment file may have"},
      {"half a million values",
       text(kOk + "[learning.annealing]\nbeta = " + list_of(500'000, "0") + "\n"),
       "learning.annealing.beta has 500000 values, more than the 10000 a list may have"},
      {"10001 values", text(kOk + "[learning.annealing]\nbeta = " + list_of(10'001, "0") + "\n"),
       "has 10001 values"},
      {"10001 scenarios", text("scenarios = " + list_of(10'001, "\"R1\"") + "\n"),
       "scenarios has 10001 values"},
      {"oversize", text(kOk + repeat("# padding\n", 110'000)), "more than the 1 MiB"},
      {"sparse 10 GB",
       [](const std::string& path) {
         std::ofstream(path) << kOk;
         fs::resize_file(path, std::uintmax_t{10} << 30);
         return path;
       },
       "is 10737418240 bytes, more than the 1 MiB"},
      {"landscape of 279936 combinations",
       text("kind = \"landscape\"\nrobot = \"octopod\"\nscenarios = [\"R1\"]\n[landscape]\n"
            "period_set = [1, 4, 5, 6, 8, 9]\n"),
       "279936 combinations (6 periods ^ 7 working legs), more than the 100000 allowed"},
  };
}

std::vector<Case> kind_cases() {
  return {
      {"/dev/zero", [](const std::string&) { return std::string("/dev/zero"); },
       "is a device, not a file"},
      {"FIFO",
       [](const std::string& path) {
         ::mkfifo(path.c_str(), 0600);
         return path;
       },
       "is a FIFO, not a file"},
      {"symlink loop",
       [](const std::string& path) {
         fs::create_symlink(path + ".b", path);
         fs::create_symlink(path, path + ".b");
         return path;
       },
       "cannot read (Too many levels of symbolic links)"},
      {"directory",
       [](const std::string& path) {
         fs::create_directory(path);
         return path;
       },
       "is a directory"},
      {"missing", [](const std::string& path) { return path + ".missing"; },
       "cannot read (No such file or directory)"},
      // Unreadable even for root: reading a process's memory at address 0 fails.
      {"unreadable", [](const std::string&) { return std::string("/proc/self/mem"); },
       "cannot read ("},
      {"empty", text(""), "scenarios is missing"},
  };
}

std::vector<Case> syntax_cases() {
  return {
      {"bad UTF-8 in a key", text("\xff\xfe = 1\n" + kOk), ":1:"},
      {"bad UTF-8 in a string", text("scenarios = [\"R1\xc3\x28\"]\n"), ":1:"},
      {"bad UTF-8 in a comment", text(kOk + "# \xed\xa0\x80\n"), ":2:"},
      {"NUL byte", text(kOk + std::string("runs = 1\0\n", 10)), ":2:"},
      {"repeated key", text(kOk + "runs = 1\nruns = 2\n"), ":3:"},
      {"repeated table", text(kOk + "[sim]\n[sim]\n"), ":3:"},
      {"key then table", text(kOk + "sim = 1\n[sim]\n"), ":3:"},
      {"unterminated string", text("scenarios = [\"R1]\n"), ":1:"},
      {"unterminated list", text("scenarios = [\"R1\",\n"), ":"},
      {"unterminated multi-line string", text("robot = \"\"\"hexapod\n"), ":"},
      {"bad escape", text("robot = \"hexa\\qpod\"\n" + kOk), ":1:"},
      {"no value", text(kOk + "runs = \n"), ":2:"},
      {"no key", text(kOk + "= 3\n"), ":2:"},
      {"junk", text(kOk + "@@@\n"), ":2:"},
      {"date", text(kOk + "seed = 1979-05-27\n"), "seed must be a number, string"},
      {"infinity", text(kOk + "[learning.annealing]\nbeta = inf\n"), "must be a finite number"},
      {"nan", text(kOk + "[learning.annealing]\nbeta = nan\n"), "must be a finite number"},
  };
}

// Every option below with values of the wrong type or out of its range: each refused naming the
// option's key (and the file and line).
std::vector<Case> value_cases() {
  const std::vector<std::pair<std::string, std::vector<std::string>>> bad{
      {"robot", {"5", "true", "[]", "{}", "\"spider\""}},
      {"kind", {"5", "\"tunnel\""}},
      {"runs", {"\"x\"", "2.5", "0", "-1", "100001", "true", "[1, 2]"}},
      {"seed", {"\"x\"", "1.5", "-1", "4294967296", "[1]"}},
      {"learning", {"5", "\"x\"", "[]"}},
      {"learning.mode", {"5", "\"fast\""}},
      {"learning.steering", {"1", "\"wheel\""}},
      {"learning.window_steps", {"\"x\"", "0", "100001", "1.5"}},
      {"learning.hold_windows", {"0", "101"}},
      {"learning.monitor_windows", {"0", "1001"}},
      {"learning.detection_windows", {"0"}},
      {"learning.max_episodes", {"0"}},
      {"learning.learn_periods", {"\"yes\"", "1"}},
      {"learning.annealing", {"5"}},
      {"learning.annealing.beta", {"\"high\"", "-1", "100.5", "true", "{}", "[1, \"x\"]"}},
      {"learning.annealing.threshold_deg", {"0", "181", "\"x\""}},
      {"learning.annealing.max_trials", {"0", "100001", "2.5"}},
      {"learning.annealing.period_set", {"[4, 10]", "[4, 7]", "[1, 2]", "4", "[\"4\"]"}},
      {"learning.steering_params", {"3"}},
      {"learning.steering_params.max_effort", {"2", "0"}},
      {"learning.disabled", {"[0]"}},
      {"learning.seed", {"3"}},
      {"learning.colour", {"1"}},
      {"sim", {"5"}},
      {"sim.control_dt", {"\"fast\"", "0", "2", "-1"}},
      {"sim.physics_dt", {"-1", "0.5"}},
      {"sim.servo_gain", {"-1", "100000"}},
      {"sim.gravity", {"9.8"}},
      {"sim.scene.tunnel", {"1"}},
      {"record", {"5"}},
      {"record.check_windows", {"-1", "1001", "\"x\""}},
      {"record.trace", {"1"}},
      {"record.film", {"true"}},
      {"landscape", {"{}"}},
      {"colour", {"1"}},
  };
  std::vector<Case> cases;
  for (const auto& [key, values] : bad) {
    for (const std::string& v : values) {
      cases.push_back({key + " = " + v, text(kOk + key + " = " + v + "\n"), ":2: " + key});
    }
  }
  const std::vector<std::pair<std::string, std::string>> scenarios{
      {"5", "scenarios must be"},
      {"\"some\"", "scenarios must be"},
      {"[]", "scenarios is an empty list"},
      {"[5]", "scenarios[0] must be a leg set"},
      {"[\"R7\"]", "scenarios[0]"},
      {"[\"R1+R1\"]", "scenarios[0] leg R1 is named twice"},
      {"[\"R1\", \"R1\"]", "scenarios[1] repeats"},
      {"[\"R1+R2+R3+L1+L2+L3\"]",
       "scenarios[0] cannot happen: every leg of the hexapod has failed"},
      {"[{}]", "scenarios[0].name"},
      {"[{name = \"a b\", faults = [{legs = \"R1\"}]}]", "scenarios[0].name"},
      {"[{name = \"x\", faults = []}]", "scenarios[0].faults"},
      {"[{name = \"x\", faults = [{step = -1, legs = \"R1\"}]}]",
       "scenarios[0].faults[0].step must be in 0..100000000, got -1"},
      {"[{name = \"x\", faults = [{step = 200000000, legs = \"R1\"}]}]",
       "scenarios[0].faults[0].step must be in 0..100000000"},
      {"[{name = \"x\", faults = [{legs = \"R1\"}, {legs = \"R1\"}]}]",
       "scenarios[0].faults leg R1 fails at step 0 but has already failed"},
      {"[{name = \"x\", faults = [{legs = \"R1\", recover = true}]}]",
       "scenarios[0].faults leg R1 recovers at step 0 but has not failed before"},
      {"[{name = \"x\", when = 3, faults = [{legs = \"R1\"}]}]", "scenarios[0].when"},
      // Names of run files: NAME_MAX bytes less ".json.tmp<pid>" (experiments/runner.h).
      {"[{name = \"" + std::string(300, 'x') + "\", faults = [{legs = \"R1\"}]}]",
       "scenarios[0].name names run files, but its 300 characters are more than a file name "
       "holds (237)"},
      {"[{name = \"" + std::string(235, 'x') + "\", faults = [{legs = \"R1\"}]}]",
       "scenarios[0].name makes run files named '" + std::string(235, 'x') + "_run000.json'"},
  };
  for (const auto& [value, mention] : scenarios) {
    cases.push_back(
        {"scenarios = " + value, text("scenarios = " + value + "\n"), ":1: " + mention});
  }
  // A period that gives no gait, in a landscape's period set as in learning's.
  cases.push_back({"landscape period 7",
                   text("kind = \"landscape\"\nscenarios = [\"R1\"]\n[landscape]\n"
                        "period_set = [4, 7]\n"),
                   "period 7, which gives no gait (allowed: 1, 4, 5, 6, 8, 9)"});
  // Control characters in keys, shown escaped on the one line (a NUL does not cut it short).
  for (const auto& [key, shown] : std::vector<std::pair<std::string, std::string>>{
           {"\"a\\u0000b\"", "a\\0b is not an option"},
           {"\"a\\u001b[31mb\"", "a\\x1b[31mb is not an option"},
           {"\"a\\nb\"", "a\\nb is not an option"},
       }) {
    cases.push_back({"key " + shown, text(kOk + "[sim]\n" + key + " = 1\n"), ":3: sim." + shown});
  }
  return cases;
}

// Flags of `run` that bound the file, checked before it is read.
std::vector<Case> flag_cases() {
  const auto ok = text(kOk);
  return {
      {"--max-runs 0", ok, "--max-runs: must be in 1..1000000, got 0", "--max-runs 0", false},
      {"--max-runs 1000001", ok, "--max-runs: must be in 1..1000000", "--max-runs 1000001", false},
      {"--max-runs x", ok, "--max-runs", "--max-runs x", false},
      {"--runs 0", ok, "--runs: must be in 1..100000, got 0", "--runs 0", false},
      {"--jobs 0", ok, "--jobs: must be in 1..4096, got 0", "--jobs 0", false},
      {"--max-runs 23", text("scenarios = \"all\"\nruns = 1\n"),
       "24 runs (24 scenarios x 1 run), more than the 23 allowed (--max-runs)", "--max-runs 23"},
  };
}

TEST(HostileFiles, EachIsRefusedWithOneLineAndExitTwo) {
  std::vector<Case> cases = giant_cases();
  for (auto more : {kind_cases(), syntax_cases(), value_cases(), flag_cases()}) {
    cases.insert(cases.end(), more.begin(), more.end());
  }
  ASSERT_GE(cases.size(), 100u);
  const std::string dir = make_temp_dir("multicpg-hostile-");
  int n = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = c.make(dir + "/case" + std::to_string(n++) + ".toml");
    std::vector<std::string> args{"run", path, "--check"};
    if (!c.extra.empty()) {
      std::istringstream words(c.extra);
      for (std::string w; words >> w;) args.push_back(w);
    }
    CliProcess cli(args);
    ASSERT_TRUE(cli.wait(kHangGuard)) << "hangs";
    const std::string err = cli.err();
    EXPECT_EQ(cli.exit_code(), 2) << err;
    EXPECT_EQ(count_lines(err), 1) << err.substr(0, 2000);
    EXPECT_NE(err.find(c.mention), std::string::npos) << err.substr(0, 2000);
    if (c.names_file) {
      EXPECT_EQ(err.rfind("multicpg: " + path, 0), 0u) << err.substr(0, 2000);
    }
    EXPECT_EQ(cli.out(), "");
    if (c.max_rss_kb > 0) {
      EXPECT_LT(cli.max_rss_kb(), c.max_rss_kb) << "peak memory, kB";
    }
  }
  fs::remove_all(dir);
}

// The limits themselves are accepted: 64 levels, a 10000-value list and a file of exactly 1 MiB
// get past the bounds (to the checks of what they say), and a sweep of exactly --max-runs runs.
TEST(HostileFiles, TheLimitsThemselvesAreAccepted) {
  const std::string dir = make_temp_dir("multicpg-limits-");
  const std::string file = dir + "/edge.toml";
  // [sim] counts 2 levels (it could be an array of tables), the key 62.
  std::ofstream(file) << kOk + "[sim]\n" + repeat("a.", 61) + "a = 1\n";
  expect_bad_input("run " + file + " --check", file + ":3: sim.a is not an option");
  std::ofstream(file) << kOk + "[learning.annealing]\nperiod_set = " + list_of(10'000, "4") + "\n";
  expect_bad_input("run " + file + " --check", file + ":3: learning.annealing.period_set");
  std::string full = read_file(std::string(MULTICPG_SOURCE_DIR) + "/examples/quick.toml") + "#";
  full.resize(std::size_t{1} << 20, 'x');
  full.back() = '\n';
  std::ofstream(file) << full;
  ASSERT_EQ(fs::file_size(file), std::uintmax_t{1} << 20);
  const CliResult r = run_cli("run " + file + " --check --max-runs 8");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("8 runs (2 grid points x 2 scenarios x 2 runs)"), std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

// The other files the program reads are held to the same rule as experiment files: a run file
// given to replay (a result, or an experiment's run file) and landscape --learned are refused,
// naming the file, when they are a FIFO (without waiting for a writer) or a device (without
// reading it).
// Each command (its words split at spaces) ends at once with exit 2 and exactly "multicpg: LINE".
void expect_refused_without_waiting(const std::vector<std::pair<std::string, std::string>>& cases) {
  for (const auto& [args, line] : cases) {
    SCOPED_TRACE(args);
    std::vector<std::string> words;
    std::istringstream split(args);
    for (std::string w; split >> w;) words.push_back(w);
    CliProcess cli(words);
    ASSERT_TRUE(cli.wait(kHangGuard)) << "hangs";
    EXPECT_EQ(cli.exit_code(), 2) << cli.err();
    EXPECT_EQ(cli.err(), "multicpg: " + line + "\n");
    EXPECT_EQ(cli.out(), "");
  }
}

TEST(HostileFiles, RunFilesAndLearnedCombinationsMustBeRegularFiles) {
  const std::string dir = make_temp_dir("multicpg-hostile-runs-");
  const std::string fifo = dir + "/fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // An experiment's run file: DIR/runs/ID.json beside DIR/experiment.json.
  fs::create_directories(dir + "/experiment/runs");
  std::ofstream(dir + "/experiment/experiment.json") << "{}\n";
  const std::string run_fifo = dir + "/experiment/runs/r1.json";
  ASSERT_EQ(::mkfifo(run_fifo.c_str(), 0600), 0);
  const std::string html = " --out " + dir + "/replay.html";
  const std::string landscape = "landscape --disable R1 --windows 1 --out " + dir + "/l --learned ";
  expect_refused_without_waiting(std::vector<std::pair<std::string, std::string>>{
      {"replay " + fifo + html, fifo + ": is a FIFO, not a file"},
      {"replay /dev/zero" + html, "/dev/zero: is a device, not a file"},
      {"replay " + run_fifo + html, run_fifo + ": is a FIFO, not a file"},
      {landscape + fifo, "--learned: " + fifo + ": is a FIFO, not a file"},
      {landscape + "/dev/zero", "--learned: /dev/zero: is a device, not a file"},
  });
  EXPECT_FALSE(fs::exists(dir + "/replay.html"));
  fs::remove_all(dir);
}

// A robot file and the model it names are read as every input file is (common/toml_file.h): a
// FIFO is refused without waiting for a writer, a directory named as such, in one line.
TEST(HostileFiles, RobotFilesAndTheirModelsMustBeRegularFiles) {
  const std::string dir = make_temp_dir("multicpg-hostile-robots-");
  const std::string fifo = dir + "/fifo.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directories(dir + "/folder.toml");
  // A good robot file whose model is a FIFO.
  const std::string examples = std::string(MULTICPG_SOURCE_DIR) + "/examples/robots/";
  std::ifstream in(examples + "hobby_hexapod.toml");
  std::string toml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string model = "model = \"hobby_hexapod.xml\"";
  ASSERT_NE(toml.find(model), std::string::npos);
  toml.replace(toml.find(model), model.size(), "model = \"fifo.xml\"");
  std::ofstream(dir + "/robot.toml") << toml;
  ASSERT_EQ(::mkfifo((dir + "/fifo.xml").c_str(), 0600), 0);
  expect_refused_without_waiting(std::vector<std::pair<std::string, std::string>>{
      {"model --check " + fifo, fifo + ": is a FIFO, not a file"},
      {"walk --robot " + dir + "/folder.toml", dir + "/folder.toml: is a directory, not a file"},
      {"model --check " + dir + "/robot.toml",
       dir + "/robot.toml: model: " + dir + "/fifo.xml: is a FIFO, not a file"},
  });
  fs::remove_all(dir);
}

// An address space of 3 GB: the program and its libraries fit, 4096 thread stacks (8 MiB each
// by default) do not.
constexpr long kAddressSpaceKb = 3'000'000;

// Threads the system refuses end a command with one line and exit 1, not std::terminate: the
// learner benchmark's, and the runner's with as many runs as threads.
TEST(HostileLimits, ThreadsTheSystemRefusesEndInOneLine) {
#ifdef MULTICPG_ASAN
  GTEST_SKIP() << "AddressSanitizer's shadow memory does not fit under an address-space limit";
#endif
  const std::string dir = make_temp_dir("multicpg-jobs-");
  std::ofstream(dir + "/many.toml") << "scenarios = [\"R1\"]\nruns = 4096\n";
  for (const std::string& args :
       {"learner-benchmark --steering off --seeds 1 --jobs 4096 --out " + dir + "/bench",
        "run " + dir + "/many.toml --jobs 4096 --out " + dir + "/run"}) {
    SCOPED_TRACE(args);
    const CliResult r = run_shell("ulimit -v " + std::to_string(kAddressSpaceKb) + " && exec " +
                                  MULTICPG_EXE + " " + args);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err.substr(r.err.find("multicpg: "))), 1) << r.err;
    EXPECT_NE(r.err.find("multicpg: cannot start thread "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" of 4096 ("), std::string::npos) << r.err;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace multicpg::testing
