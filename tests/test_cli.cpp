// The real multicpg binary: gait and cpg commands, their files and their bad-input handling;
// the CLI's own manners (--help, --version, suggestions, messages, failed writes and tools).
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "common/user_text.h"
#include "tests/cli_runner.h"

namespace {

using namespace multicpg::testing;

TEST(CliGait, PrintsDiagramAndWritesCsv) {
  const std::string dir = make_temp_dir("gait-");
  const auto r = run_cli("gait --robot hexapod --period 4 --steps 36 --csv " + dir + "/g.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("R1 "), std::string::npos);
  EXPECT_NE(r.out.find("swing fraction"), std::string::npos);
  const std::string csv = read_file(dir + "/g.csv");
  EXPECT_EQ(first_line(csv), "step,R1,R2,R3,L1,L2,L3");
  EXPECT_EQ(count_lines(csv), 37);
  std::filesystem::remove_all(dir);
}

TEST(CliGait, QuadrupedAndOctopodColumns) {
  const std::string dir = make_temp_dir("gait-");
  ASSERT_EQ(
      run_cli("gait --robot quadruped --period 4 --steps 10 --csv " + dir + "/q.csv").exit_code, 0);
  EXPECT_EQ(first_line(read_file(dir + "/q.csv")), "step,R1,R2,L1,L2");
  ASSERT_EQ(run_cli("gait --robot octopod --period 5 --steps 10 --csv " + dir + "/o.csv").exit_code,
            0);
  EXPECT_EQ(first_line(read_file(dir + "/o.csv")), "step,R1,R2,R3,R4,L1,L2,L3,L4");
  std::filesystem::remove_all(dir);
}

TEST(CliGait, BadInput) {
  expect_bad_input("gait --robot spider --period 4", "spider");
  expect_bad_input("gait --period 3", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --period 7", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --period 0", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --period 10", "1, 4, 5, 6, 8, 9");
  expect_bad_input("gait --steps 0", "--steps");
  expect_bad_input("gait --steps -5", "--steps");
  expect_bad_input("gait --disable R4", "R4");
  expect_bad_input("gait --robot quadruped --disable R3", "R3");
  expect_bad_input("gait --period four", "--period");
  expect_bad_input("gait --csv /nonexistent-dir/g.csv", "/nonexistent-dir/g.csv");
  expect_bad_input("gait --no-such-flag", "--no-such-flag");
  expect_bad_input("", "subcommand");
}

TEST(CliGait, UnwritableCsvLeavesNoFile) {
  const std::string dir = make_temp_dir("gait-");
  const std::string target = dir + "/sub/g.csv";  // parent directory missing
  EXPECT_EQ(run_cli("gait --csv " + target).exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(target));
  std::filesystem::remove_all(dir);
}

TEST(CliCpg, WritesColumnsAndReportsOrbits) {
  const std::string dir = make_temp_dir("cpg-");
  const auto r = run_cli("cpg --period 5 --client-period 6 --sync off --csv " + dir + "/c.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("master x1: period-5 orbit"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("client x1: period-6 orbit"), std::string::npos) << r.out;
  const std::string csv = read_file(dir + "/c.csv");
  EXPECT_EQ(first_line(csv), "step,master_x1,master_x2,client_x1,client_x2");
  EXPECT_EQ(count_lines(csv), 3001);

  const auto synced = run_cli("cpg --period 5 --client-period 6 --sync on");
  ASSERT_EQ(synced.exit_code, 0);
  EXPECT_NE(synced.out.find("client x1: period-5 orbit"), std::string::npos) << synced.out;
  EXPECT_NE(synced.out.find("identical to the master's"), std::string::npos) << synced.out;

  const auto chaos = run_cli("cpg --uncontrolled --sync off");
  ASSERT_EQ(chaos.exit_code, 0);
  EXPECT_NE(chaos.out.find("master x1: no periodic orbit"), std::string::npos) << chaos.out;
  std::filesystem::remove_all(dir);
}

TEST(CliCpg, BadInput) {
  expect_bad_input("cpg --period 0", "1..9");
  expect_bad_input("cpg --period 10", "1..9");
  expect_bad_input("cpg --period 4 --client-period 11", "--client-period");
  expect_bad_input("cpg --steps 0", "--steps");
  expect_bad_input("cpg --sync maybe", "--sync");
  expect_bad_input("cpg --csv /nonexistent-dir/c.csv", "/nonexistent-dir/c.csv");
}

TEST(Cli, HelpExitsZero) {
  const auto r = run_cli("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("gait"), std::string::npos);
}

TEST(Cli, VersionSaysWhatTheProgramIs) {
  const auto r = run_cli("--version");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_lines(r.out), 1) << r.out;
  EXPECT_EQ(r.out.rfind("multicpg 0.", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("(git "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", MuJoCo 2.2.2, compiler "), std::string::npos) << r.out;
}

TEST(Cli, HelpShowsNoValidatorNoise) {
  for (const std::string command : {"", "walk", "learn", "run", "experiment table", "tunnel"}) {
    const auto r = run_cli(command + " --help");
    EXPECT_EQ(r.exit_code, 0) << command << ": " << r.err;
    EXPECT_EQ(r.out.find(":not empty"), std::string::npos) << command << ":\n" << r.out;
  }
  EXPECT_NE(run_cli("walk --help").out.find("--periods TEXT=4"), std::string::npos);
}

// docs/cli.md lists every command and every flag its --help lists: a flag added without a word
// there fails here.
TEST(Cli, DocsListEveryCommandAndFlag) {
  const std::string docs = read_file(std::string(MULTICPG_SOURCE_DIR) + "/docs/cli.md");
  const auto documented = [&](const std::string& word) {
    for (std::size_t at = docs.find(word); at != std::string::npos; at = docs.find(word, at + 1)) {
      const std::size_t end = at + word.size();
      if (end == docs.size() || (!std::isalnum(static_cast<unsigned char>(docs[end])) &&
                                 docs[end] != '-' && docs[end] != '_')) {
        return true;
      }
    }
    return false;
  };
  // The names an --help lists under "Subcommands:", and the long flags under "Options:".
  const auto listed = [](const std::string& help, const std::regex& line) {
    std::vector<std::string> out;
    std::istringstream in(help);
    for (std::string l; std::getline(in, l);) {
      std::smatch m;
      if (std::regex_search(l, m, line)) out.push_back(m[1]);
    }
    return out;
  };
  const std::regex subcommand("^  ([a-z][a-z-]*) ");
  const std::regex flag("^  (?:-[A-Za-z],)?(--[a-z][a-z-]*)");
  const auto subcommands = [&](const std::string& help) {
    const std::size_t at = help.find("Subcommands:");
    return at == std::string::npos ? std::vector<std::string>{}
                                   : listed(help.substr(at), subcommand);
  };
  const CliResult top = run_cli("--help");
  ASSERT_EQ(top.exit_code, 0) << top.err;
  std::map<std::string, std::string> helps;  // of each command that has no subcommands
  for (const std::string& c : subcommands(top.out)) {
    const CliResult help = run_cli(c + " --help");
    ASSERT_EQ(help.exit_code, 0) << c << ": " << help.err;
    const std::vector<std::string> inner = subcommands(help.out);
    if (inner.empty()) helps[c] = help.out;
    for (const std::string& i : inner) {
      const CliResult inner_help = run_cli(c + " " + i + " --help");
      ASSERT_EQ(inner_help.exit_code, 0) << c << " " << i << ": " << inner_help.err;
      helps[c + " " + i] = inner_help.out;
    }
  }
  ASSERT_GE(helps.size(), 20u) << "the command list was not read";
  for (const auto& [c, help] : helps) {
    EXPECT_TRUE(documented("multicpg " + c)) << "docs/cli.md has no row for `multicpg " << c << "`";
    for (const std::string& f : listed(help, flag)) {
      if (f == "--help") continue;
      EXPECT_TRUE(documented(f)) << "docs/cli.md does not name " << f << " of `" << c << "`";
    }
  }
}

TEST(Cli, MistypedNamesGetASuggestion) {
  expect_bad_input("walk --period 5", "unknown flag '--period' of walk (did you mean --periods?)");
  expect_bad_input("walk --period=5", "unknown flag '--period' of walk (did you mean --periods?)");
  expect_bad_input("learn --disable R1 --betta 3",
                   "unknown flag '--betta' of learn (did you "
                   "mean --beta?)");
  expect_bad_input("walk --total-mas 9",
                   "unknown flag '--total-mas' of walk (did you mean "
                   "--total-mass?)");
  expect_bad_input("walk --zzzzzzzz 3",
                   "unknown flag '--zzzzzzzz' of walk (see multicpg walk --help)");
  expect_bad_input("walk 5", "unexpected argument '5' to walk (see multicpg walk --help)");
  expect_bad_input("wlak", "unknown command 'wlak' (did you mean walk?)");
  expect_bad_input("tunel --disable R1", "unknown command 'tunel' (did you mean tunnel?)");
  expect_bad_input("experiment tabel",
                   "unknown command 'experiment tabel' (did you mean experiment table?)");
  expect_bad_input("fly", "unknown command 'fly' (see multicpg --help)");
}

TEST(Cli, OnePrefixPerMessage) {
  const std::string allowed = " gives no gait (allowed: 1, 4, 5, 6, 8, 9)\n";
  EXPECT_EQ(run_cli("walk --periods 7").err, "multicpg: --periods: period 7" + allowed);
  EXPECT_EQ(run_cli("walk --periods R1=7").err, "multicpg: --periods: period 7 of R1" + allowed);
  EXPECT_EQ(run_cli("walk --periods R1=x").err,
            "multicpg: --periods: period 'x' of R1 is not a whole number\n");
  EXPECT_EQ(run_cli("gait --period 7").err, "multicpg: --period: period 7" + allowed);
  EXPECT_EQ(run_cli("walk --terrain slope:31").err,
            "multicpg: --terrain: the slope must be in 0..30 deg, got 31\n");
  EXPECT_EQ(run_cli("walk --robot /nonexistent/robot.toml").err,
            "multicpg: /nonexistent/robot.toml: cannot read (No such file or directory)\n");
}

// A flag that does nothing without another, or contradicts it, is refused (exit 2), never
// silently ignored.
TEST(Cli, FlagsThatNeedAnotherAreRefused) {
  expect_bad_input("walk --disable-at 600", "--disable-at requires --disable");
  expect_bad_input("learn --fault R1@0 --disable-at 600", "--disable-at requires --disable");
  expect_bad_input("walk --cold --warmup 5", "--warmup excludes --cold");
  expect_bad_input("tunnel --disable R1 --beta 3", "--beta requires --learn");
  expect_bad_input("tunnel --disable R1 --mode paper", "--mode requires --learn");
  expect_bad_input("render --out /tmp/multicpg-needs.png --seed 3", "--seed requires --learn");
  expect_bad_input("render --out /tmp/multicpg-needs.png --disable R1 --learn --steps 5",
                   "--steps excludes --learn");
}

TEST(Cli, ControlCharactersAreEscapedInMessages) {
  for (const auto& [typed, shown] : std::vector<std::pair<std::string, std::string>>{
           {"spi\\033[31mder", "spi\\x1b[31mder"},
           {"spi\\nder", "spi\\nder"},
           {"spi\\tder\\a", "spi\\tder\\x07"},
       }) {
    const auto r = run_cli("walk --robot \"$(printf '" + typed + "')\"");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(shown), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find_first_of(std::string("\x1b\t\a", 3)), std::string::npos) << r.err;
  }
}

TEST(Cli, FullDiskWritesNameTheCause) {
  for (const std::string command :
       {"gait --steps 10 --csv /dev/full", "gait --steps 20000 --csv /dev/full",
        "walk --steps 20 --csv /dev/full"}) {
    const auto r = run_cli(command);
    EXPECT_EQ(r.exit_code, 1) << command << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << command << ": " << r.err;
    EXPECT_NE(r.err.find("writing '/dev/full' failed: No space left on device"), std::string::npos)
        << command << ": " << r.err;
  }
}

// A helper program that fails is named with how it ended and the last line it printed.
TEST(Cli, FailingHelperProgramIsNamedWithWhatItSaid) {
  namespace fs = std::filesystem;
  const std::string dir = make_temp_dir("helper-");
  const auto fake_gnuplot = [&](const std::string& body) {
    fs::create_directories(dir + "/bin");
    std::ofstream(dir + "/bin/gnuplot") << "#!/bin/sh\n" << body << "\n";
    fs::permissions(dir + "/bin/gnuplot", fs::perms::owner_all);
    return run_shell("PATH=" + dir + "/bin:$PATH " + MULTICPG_EXE + " figure gait --out " + dir +
                     "/out");
  };
  const auto said = fake_gnuplot("echo 'warming up'; echo 'no font here' >&2; exit 3");
  EXPECT_EQ(said.exit_code, 1) << said.err;
  // Progress lines come first; the error is the last line, whole.
  EXPECT_NE(said.err.find("\nmulticpg: gnuplot gait.gp failed: exit status 3: no font here\n"),
            std::string::npos)
      << said.err;
  const auto silent = fake_gnuplot("exit 0");
  EXPECT_EQ(silent.exit_code, 1) << silent.err;
  EXPECT_NE(silent.err.find("failed: wrote no picture (exit status 0, printed nothing)"),
            std::string::npos)
      << silent.err;
  const auto killed = fake_gnuplot("kill -9 $$");
  EXPECT_EQ(killed.exit_code, 1) << killed.err;
  EXPECT_NE(killed.err.find("failed: killed by signal 9 (Killed), printed nothing"),
            std::string::npos)
      << killed.err;
  fs::remove_all(dir);
}

TEST(UserText, PrintableEscapesControlCharactersOnce) {
  EXPECT_EQ(multicpg::printable(std::string("a\0b\nc\x1b[0m\x7f", 10)), "a\\0b\\nc\\x1b[0m\\x7f");
  EXPECT_EQ(multicpg::printable("R1=5, 'ok' \\ done"), "R1=5, 'ok' \\ done");
  const std::string once = multicpg::printable("x\ty");
  EXPECT_EQ(multicpg::printable(once), once);
  EXPECT_EQ(multicpg::printable("\xc3\xa9"), "\xc3\xa9");  // UTF-8 passes
}

TEST(UserText, ClosestNameOnlyWhenNear) {
  const std::vector<std::string> known{"walk", "learn", "tunnel", "experiment"};
  EXPECT_EQ(multicpg::closest_name("wlak", known), "walk");
  EXPECT_EQ(multicpg::closest_name("lern", known), "learn");
  EXPECT_EQ(multicpg::closest_name("experimnet", known), "experiment");
  EXPECT_EQ(multicpg::closest_name("fly", known), std::nullopt);
  EXPECT_EQ(multicpg::closest_name("", known), std::nullopt);
}

}  // namespace
