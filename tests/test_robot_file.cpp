// Robot files through the real CLI (docs/robots.md "Your robot: robot files"): a built-in robot
// written with `model --out DIR` walks, learns and crosses the tunnel from its robot file exactly
// as the built-in does, its results recording the file; `model --check` reads a file; broken files
// exit 2 with one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "common/checksum.h"
#include "tests/cli_runner.h"

namespace {

using namespace multicpg::testing;

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// `text` with its first `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// A run's JSON as its CLI printed it, without the robot file's record.
std::string without_record(const std::string& out) {
  nlohmann::json j = nlohmann::json::parse(out);
  j.erase("robot_file");
  return j.dump(2) + "\n";
}

class RobotFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("robot-file-");
    for (const char* robot : {"hexapod", "quadruped"}) {
      const CliResult r = run_cli(std::string("model --robot ") + robot + " --out " + dir_);
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // `command` (with ROBOT for the robot, --json) prints the same from the built-in robot and
  // its file, byte for byte once the file's record (robot_file) is taken out.
  void expect_same(const std::string& robot, const std::string& command) {
    const auto with = [&](const std::string& r) {
      return replaced(command, "ROBOT", "--robot " + r);
    };
    const std::string path = dir_ + "/" + robot + ".toml";
    const CliResult builtin = run_cli(with(robot));
    const CliResult file = run_cli(with(path));
    ASSERT_EQ(builtin.exit_code, 0) << builtin.err;
    ASSERT_EQ(file.exit_code, 0) << file.err;
    EXPECT_FALSE(builtin.out.empty());
    EXPECT_EQ(nlohmann::json::parse(builtin.out).count("robot_file"), 0U) << command;
    const nlohmann::json record = nlohmann::json::parse(file.out).at("robot_file");
    EXPECT_EQ(record.at("path"), path);
    EXPECT_EQ(record.at("name"), robot);
    EXPECT_EQ(record.at("checksum_toml"), multicpg::checksum_text(read_file(path)));
    EXPECT_EQ(record.at("checksum_model"),
              multicpg::checksum_text(read_file(dir_ + "/" + robot + ".xml")));
    EXPECT_EQ(builtin.out, without_record(file.out)) << command;
  }

  std::string dir_;
};

TEST_F(RobotFile, ModelWritesTheMjcfAndTheLegMap) {
  for (const char* robot : {"hexapod", "quadruped"}) {
    const std::string xml = read_file(dir_ + "/" + robot + ".xml");
    EXPECT_EQ(xml, run_cli(std::string("model --robot ") + robot).out);
    const std::string toml = read_file(dir_ + "/" + robot + ".toml");
    EXPECT_NE(toml.find(std::string("model = \"") + robot + ".xml\""), std::string::npos);
  }
}

TEST_F(RobotFile, WalksLearnsAndCrossesTheTunnelAsTheBuiltInRobot) {
  expect_same("hexapod", "walk ROBOT --json");
  expect_same("hexapod", "learn ROBOT --mode paper --disable R1 --max-trials 3 --json");
  expect_same("hexapod", "tunnel ROBOT --disable R1 --max-steps 500 --json");
  expect_same("quadruped", "walk ROBOT --json");
}

// R1's TC joint turned about the opposite axis, its start angle negated and its sign -1: the same
// robot, so the same walk to the bit, a locked joint included (locked at the paper's angle).
TEST_F(RobotFile, ASignTurnsAJointIntoThePapersConvention) {
  const std::string start_tc = " 0.436768645312";  // R1's TC in the start keyframe (front leg)
  std::string xml = replaced(read_file(dir_ + "/hexapod.xml"),
                             "<joint name=\"R1_TC\" type=\"hinge\" axis=\"0 0 1\"",
                             "<joint name=\"R1_TC\" type=\"hinge\" axis=\"0 0 -1\"");
  const std::size_t key = xml.find("<key name=\"start\"");
  ASSERT_NE(key, std::string::npos);
  const std::size_t at = xml.find(start_tc, key);
  ASSERT_NE(at, std::string::npos);
  xml.replace(at, start_tc.size(), " -" + start_tc.substr(1));
  write(dir_ + "/flipped.xml", xml);
  write(dir_ + "/flipped.toml",
        replaced(replaced(read_file(dir_ + "/hexapod.toml"), "model = \"hexapod.xml\"",
                          "model = \"flipped.xml\""),
                 "TC = { joint = \"R1_TC\", sign = 1,", "TC = { joint = \"R1_TC\", sign = -1,"));
  for (const std::string walk :
       {"walk --json --robot ", "walk --json --fault R1.TC:locked=10@100 --steps 800 --robot "}) {
    const CliResult builtin = run_cli(walk + "hexapod");
    const CliResult flipped = run_cli(walk + dir_ + "/flipped.toml");
    ASSERT_EQ(flipped.exit_code, 0) << flipped.err;
    EXPECT_EQ(builtin.out, without_record(flipped.out)) << walk;
  }
}

TEST_F(RobotFile, CheckSaysWhatItReadAndThatTheRobotStands) {
  const CliResult r = run_cli("model --check " + dir_ + "/hexapod.toml");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("6 legs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("L3 (left, position 2)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FTi L3_FTi [-130.0, -20.0] deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("standing height"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("it stands"), std::string::npos) << r.out;

  // Motors too weak to hold the robot up: it lies on its trunk (exit 1).
  std::string xml = read_file(dir_ + "/hexapod.xml");
  for (std::size_t at = xml.find("ctrlrange=\""); at != std::string::npos;
       at = xml.find("ctrlrange=\"", at + 1)) {
    const std::size_t value = at + std::string("ctrlrange=\"").size();
    xml.replace(value, xml.find('"', value) - value, "-0.001 0.001");
  }
  write(dir_ + "/weak.xml", xml);
  write(dir_ + "/weak.toml", replaced(read_file(dir_ + "/hexapod.toml"), "model = \"hexapod.xml\"",
                                      "model = \"weak.xml\""));
  const CliResult weak = run_cli("model --check " + dir_ + "/weak.toml");
  EXPECT_EQ(weak.exit_code, 1) << weak.err;
  EXPECT_NE(weak.err.find("does not stand"), std::string::npos) << weak.err;
}

// Its joints without an actuator get the servo law's motors: the built-in hexapod without its
// actuators walks as the built-in one to the bit. A velocity actuator of the model's own is given
// the servo's commanded velocity, and a passive joint none.
TEST_F(RobotFile, TheModelsOwnActuatorsOrTheServoLawsMotors) {
  const std::string xml = read_file(dir_ + "/hexapod.xml");
  const std::size_t from = xml.find("<actuator>");
  const std::size_t to = xml.find("</actuator>") + std::string("</actuator>").size();
  ASSERT_NE(from, std::string::npos);
  write(dir_ + "/bare.xml", xml.substr(0, from) + xml.substr(to));
  const std::string toml = read_file(dir_ + "/hexapod.toml");
  write(dir_ + "/bare.toml", replaced(toml, "model = \"hexapod.xml\"", "model = \"bare.xml\""));
  const CliResult builtin = run_cli("walk --json --robot hexapod");
  const CliResult bare = run_cli("walk --json --robot " + dir_ + "/bare.toml");
  ASSERT_EQ(bare.exit_code, 0) << bare.err;
  EXPECT_EQ(builtin.out, without_record(bare.out));

  std::string velocity = xml;
  for (std::size_t at = velocity.find("<motor "); at != std::string::npos;
       at = velocity.find("<motor ", at)) {
    const std::size_t end = velocity.find("ctrllimited", at);
    velocity.replace(at, end - at,
                     velocity.substr(at, end - at).replace(0, 7, "<velocity ") +
                         "kv=\"2.555\" forcelimited=\"true\" forcerange=\"-26.75 26.75\" ");
  }
  write(dir_ + "/velocity.xml", velocity);
  write(dir_ + "/velocity.toml",
        replaced(toml, "model = \"hexapod.xml\"", "model = \"velocity.xml\""));
  const CliResult walked = run_cli("walk --json --robot " + dir_ + "/velocity.toml");
  ASSERT_EQ(walked.exit_code, 0) << walked.err;
  const nlohmann::json j = nlohmann::json::parse(walked.out);
  EXPECT_GT(j.at("forward_m").get<double>(), 2.0);  // the built-in walks 3.5 m
  const CliResult passive = run_cli("walk --json --steps 100 --fault R1.CTr:passive@0 --robot " +
                                    dir_ + "/velocity.toml");
  EXPECT_EQ(passive.exit_code, 0) << passive.err;
}

struct Broken {
  std::string from;  // text of the good hexapod.toml ...
  std::string to;    // ... replaced by this
  std::string key;   // the key the one line of stderr names (":2:": a syntax error's line)
};

TEST_F(RobotFile, BrokenFilesExit2WithOneLineNamingTheFileAndTheKey) {
  const std::string good = read_file(dir_ + "/hexapod.toml");
  const std::string xml = read_file(dir_ + "/hexapod.xml");
  write(dir_ + "/refused.xml", "<mujoco><worldbody><geom type=\"nosuch\"/></worldbody></mujoco>");
  write(dir_ + "/refused.urdf",
        "<robot name=\"r\"><link name=\"a\"><collision><geometry><nosuch/></geometry>"
        "</collision></link></robot>");
  // An actuator whose gain depends on the joint's angle: not a motor, position or velocity servo.
  write(dir_ + "/general.xml",
        replaced(xml, "<motor name=\"R1_TC\" joint=\"R1_TC\"",
                 "<general name=\"R1_TC\" joint=\"R1_TC\" gaintype=\"affine\" gainprm=\"1 1 0\""));
  write(dir_ + "/unlimited.xml",
        replaced(xml, "<joint name=\"R1_TC\"", "<joint name=\"R1_TC\" limited=\"false\""));
  const std::string last_leg = good.substr(good.rfind("\n[[legs]]"));
  const Broken cases[] = {
      {"trunk = \"trunk\"\n", "", "trunk"},                          // missing key
      {"position = 0", "position = \"front\"", "legs[0].position"},  // wrong type
      {"name = \"hexapod\"", "name = 6", "name"},                    // wrong type
      {"\"R1_TC\"", "\"R1_TX\"", "legs[0].TC.joint"},                // no such joint
      {"trunk = \"trunk\"", "trunk = \"torso\"", "trunk"},           // no such body
      {"trunk = \"trunk\"", "trunk = \"R1_coxa\"", "trunk"},         // no free joint
      {"yaw = \"front_trunk\"", "yaw = \"head\"", "yaw"},            // no such body or site
      {"foot = \"R2_foot\"", "foot = \"R2_toe\"", "legs[1].foot"},   // no such geom
      {"window = [-1.2217304763960306, 1.2217304763960306]", "window = [1, -1]",
       "legs[0].TC.window"},  // lo above hi
      {"window = [-1.2217304763960306, 1.2217304763960306]", "window = [-3, 3]",
       "legs[0].TC.window"},                                            // beyond the joint's range
      {"model = \"hexapod.xml\"", "model = \"refused.xml\"", "model"},  // MuJoCo refuses it
      {"model = \"hexapod.xml\"", "model = \"unlimited.xml\"", "legs[0].TC.joint"},  // no range
      {"model = \"hexapod.xml\"", "model = \"nosuch.xml\"", "model"},                // unreadable
      {"model = \"hexapod.xml\"", "model = \"refused.urdf\"", "model"},  // a URDF MuJoCo refuses
      {"model = \"hexapod.xml\"", "model = \"general.xml\"", "legs[0].TC.joint"},
      {last_leg, "", "legs"},  // five legs
      {"master = \"R1\"", "master = \"L2\"", "master"},
      {"sign = 1", "sign = 2", "backbone.sign"},
      {"name = \"R1\"", "name = \"R2\"", "legs[0].name"},  // out of order
      {"side = \"right\"", "side = \"left\"", "legs[0].side"},
      {"yaw = ", "colour = \"red\"\nyaw = ", "colour"},  // unknown key
      {"name = \"hexapod\"", "name = ", ":2:"},          // TOML syntax: line and column
  };
  int n = 0;
  for (const Broken& c : cases) {
    const std::string path = dir_ + "/broken" + std::to_string(n++) + ".toml";
    write(path, replaced(good, c.from, c.to));
    for (const std::string command : {"model --check ", "walk --robot "}) {
      const CliResult r = run_cli(command + path);
      EXPECT_EQ(r.exit_code, 2) << command << c.key << ": " << r.err;
      EXPECT_EQ(count_lines(r.err), 1) << command << c.key << ": " << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
      EXPECT_NE(r.err.find(path + (c.key.starts_with(':') ? "" : ": ") + c.key), std::string::npos)
          << c.key << ": " << r.err;
    }
  }
  // Legs too short to hold the trunk up: its plate hangs below the feet in the start pose.
  const std::string examples = std::string(MULTICPG_SOURCE_DIR) + "/examples/robots/";
  write(dir_ + "/low.xml", replaced(read_file(examples + "hobby_hexapod.xml"),
                                    "size=\"0.13 0.09 0.02\"", "size=\"0.13 0.09 0.3\""));
  write(dir_ + "/low.toml", replaced(read_file(examples + "hobby_hexapod.toml"),
                                     "model = \"hobby_hexapod.xml\"", "model = \"low.xml\""));
  expect_bad_input("model --check " + dir_ + "/low.toml", dir_ + "/low.toml: legs");

  const CliResult missing = run_cli("model --check " + dir_ + "/nosuch.toml");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(count_lines(missing.err), 1) << missing.err;
  EXPECT_NE(missing.err.find("nosuch.toml: cannot read (No such file or directory)"),
            std::string::npos)
      << missing.err;
  // The built-in robots' contact pairs hold their feet to their own ground; a tunnel's model
  // makes no robot file.
  expect_bad_input("walk --terrain slope:5:0 --robot " + dir_ + "/hexapod.toml",
                   dir_ + "/hexapod.toml: its model's <contact><pair>s");
  // Its body is its model: body flags that would change the MJCF are refused.
  expect_bad_input("walk --trunk-mass 2 --robot " + dir_ + "/hexapod.toml", "--trunk-mass");
  expect_bad_input("learn --disable R1 --model real --robot " + dir_ + "/hexapod.toml", "--model");
  const CliResult lifted =
      run_cli("walk --steps 10 --lift-body 5 --robot " + dir_ + "/hexapod.toml");
  EXPECT_EQ(lifted.exit_code, 0) << lifted.err;
  expect_bad_input("model --robot hexapod --tunnel --out " + dir_ + "/tunnel", "--tunnel");
  expect_bad_input("model --robot hexapod --terrain slope:5:0 --out " + dir_ + "/slope",
                   "--terrain");
}

}  // namespace
