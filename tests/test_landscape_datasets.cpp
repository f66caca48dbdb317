// Landscape datasets: written and read back, damaged ones refused, where they are found.
#include "learning/landscape_cache.h"
#include "tests/synthetic_landscapes.h"

namespace multicpg::testing {
namespace {

TEST_F(Dataset, AWrittenDatasetReadsBackAndAnEditedOneIsRefused) {
  const LandscapeDataset back = learning::read_landscape_dataset(stem());
  ASSERT_EQ(back.scenarios.size(), data_.scenarios.size());
  EXPECT_EQ(back.period_set, kPeriodSet);
  for (std::size_t i = 0; i < back.scenarios.size(); ++i) {
    EXPECT_EQ(back.scenarios[i].failed, data_.scenarios[i].failed);
    EXPECT_EQ(back.scenarios[i].holding(), data_.scenarios[i].holding());
    ASSERT_EQ(back.scenarios[i].points.size(), data_.scenarios[i].points.size());
    EXPECT_EQ(back.scenarios[i].points.back().periods, data_.scenarios[i].points.back().periods);
    EXPECT_NEAR(back.scenarios[i].points.back().windows[2].yaw_deg,
                data_.scenarios[i].points.back().windows[2].yaw_deg,
                learning::kLandscapeAngleResolutionDeg);
  }
  EXPECT_GT(data_.find({kL2})->holding(), 0u);
  EXPECT_EQ(data_.find({0, 1})->holding(), 0u);
  // Walked by the built-in robot: no robot file recorded; by a robot file: its record kept.
  EXPECT_TRUE(back.robot_file.is_null());
  LandscapeDataset by_file = data_;
  by_file.robot_file = {{"path", "robots/spider.toml"}, {"name", "spider"}};
  learning::write_landscape_dataset(by_file, stem() + "-by-file");
  EXPECT_EQ(learning::read_landscape_dataset(stem() + "-by-file").robot_file, by_file.robot_file);

  // One byte changed in the compressed table: the manifest's checksum no longer matches.
  const fs::path csv = stem() + ".csv.gz";
  std::string bytes = read_file(csv.string());
  ASSERT_GT(bytes.size(), 40u);
  {
    std::string cut = bytes.substr(0, bytes.size() / 2);
    std::ofstream(csv, std::ios::binary) << cut;
    EXPECT_THROW(learning::read_landscape_dataset(stem()), BadInput);
  }
  fs::remove(csv);
  EXPECT_THROW(learning::read_landscape_dataset(stem()), BadInput);
}

// A run resolves its data when its spec is checked and again when it starts: the same bytes are
// parsed once, other bytes (an edited dataset, a damaged one) never served from memory.
TEST_F(Dataset, ADatasetIsParsedOncePerContentAndAnEditedOneIsReadAnew) {
  const std::shared_ptr<const LandscapeDataset> first =
      learning::read_landscape_dataset_once(stem());
  EXPECT_EQ(learning::read_landscape_dataset_once(stem()).get(), first.get());

  LandscapeDataset edited = data_;
  edited.scenarios.front().points.front().windows.front().yaw_deg += 1.0;
  learning::write_landscape_dataset(edited, stem());
  const std::shared_ptr<const LandscapeDataset> again =
      learning::read_landscape_dataset_once(stem());
  EXPECT_NE(again.get(), first.get());
  EXPECT_NEAR(again->scenarios.front().points.front().windows.front().yaw_deg,
              first->scenarios.front().points.front().windows.front().yaw_deg + 1.0,
              learning::kLandscapeAngleResolutionDeg);

  const fs::path csv = stem() + ".csv.gz";
  const std::string bytes = read_file(csv.string());
  std::ofstream(csv, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_THROW(learning::read_landscape_dataset_once(stem()), BadInput);
  fs::remove(csv);
  EXPECT_THROW(learning::read_landscape_dataset_once(stem()), BadInput);

  learning::write_landscape_dataset(data_, stem());
  EXPECT_EQ(learning::read_landscape_dataset_once(stem()).get(), first.get());
}

// A manifest whose checksum still matches its table but whose own fields are damaged is refused
// with one line naming the file and the field, never read as some other dataset.
TEST_F(Dataset, ADamagedManifestIsRefusedNamingTheFileAndTheField) {
  const fs::path manifest = stem() + ".json";
  const std::string good = read_file(manifest.string());
  const auto refused = [&](const std::string& what, const std::string& field,
                           const std::function<void(nlohmann::json&)>& damage) {
    nlohmann::json m = nlohmann::json::parse(good);
    damage(m);
    std::ofstream(manifest) << m.dump(2);
    try {
      learning::read_landscape_dataset(stem());
      ADD_FAILURE() << what << " was read";
    } catch (const BadInput& e) {
      const std::string line = e.what();
      EXPECT_NE(line.find("synthetic.json"), std::string::npos) << what << ": " << line;
      EXPECT_NE(line.find(field), std::string::npos) << what << ": " << line;
      EXPECT_EQ(line.find('\n'), std::string::npos) << what << ": " << line;
    }
  };
  refused("version 1.5", "version", [](nlohmann::json& m) { m["version"] = 1.5; });
  refused("threshold -1", "threshold", [](nlohmann::json& m) { m["threshold_deg"] = -1; });
  refused("threshold 0", "threshold", [](nlohmann::json& m) { m["threshold_deg"] = 0; });
  refused("threshold 1e308", "threshold", [](nlohmann::json& m) { m["threshold_deg"] = 1e308; });
  refused("count 125.5", "combinations",
          [](nlohmann::json& m) { m["scenarios"][0]["combinations"] = 125.5; });
  refused("no checksum", "checksum", [](nlohmann::json& m) { m.erase("checksum"); });
  refused("a numeric checksum", "checksum", [](nlohmann::json& m) { m["checksum"] = 7; });
  refused("a robot file without its name", "robot_file", [](nlohmann::json& m) {
    m["robot_file"] = {{"path", "robots/spider.toml"}};
  });
  refused("a robot file of a number", "robot_file", [](nlohmann::json& m) { m["robot_file"] = 3; });
  std::ofstream(manifest) << "";
  EXPECT_THROW(learning::read_landscape_dataset(stem()), BadInput);
  std::ofstream(manifest) << good;
  EXPECT_NO_THROW(learning::read_landscape_dataset(stem()));
}

TEST(Learners, TheRepositoryDatasetsReadWhole) {
  const LandscapeDataset q = learning::read_landscape_dataset(
      learning::repository_dataset(robot::RobotKind::quadruped, false));
  EXPECT_EQ(q.scenarios.size(), 14u);  // every loss of one, two or three legs
  EXPECT_EQ(q.windows, 6);
  EXPECT_EQ(q.find({3})->points.size(), 125u);  // L2
  EXPECT_EQ(q.find({3})->holding(), 2u);        // docs/learning.md "The landscape"
  const LandscapeDataset h = learning::read_landscape_dataset(
      learning::repository_dataset(robot::RobotKind::hexapod, false));
  EXPECT_GE(h.scenarios.size(), 35u);  // the two- and three-leg losses at least
  for (const ScenarioLandscape& s : h.scenarios) {
    const std::size_t working = 6 - s.failed.size();
    std::size_t expected = 1;
    for (std::size_t i = 0; i < working; ++i) expected *= kPeriodSet.size();
    EXPECT_EQ(s.points.size(), expected);
  }
  // Walked as the default run walks (docs/learning.md "Walked as the default run walks"): every
  // loss of one to three legs, each scenario's start windows kept.
  const LandscapeDataset r = learning::read_landscape_dataset(
      learning::repository_dataset(robot::RobotKind::hexapod, true));
  ASSERT_TRUE(r.reflex);
  EXPECT_EQ(r.scenarios.size(), 41u);
  EXPECT_EQ(r.find({0, 2})->holding(), 85u);  // R1+R3, docs/learning.md
  for (const ScenarioLandscape& s : r.scenarios) EXPECT_FALSE(s.start_windows.empty());
}

// The search path (learning/landscapes.h): $MULTICPG_DATA before the source tree (nothing is
// installed beside this test program), a dataset it lacks found further on, and one that no
// place holds refused on one line naming every place looked, by the CLI too (exit 2).
TEST_F(Dataset, MulticpgDataComesFirstAndAMissingDatasetNamesEveryPlaceLooked) {
  const fs::path source = learning::repository_dataset(robot::RobotKind::quadruped, false);
  const fs::path given = fs::path(dir_) / "landscapes";
  fs::create_directories(given);
  learning::write_landscape_dataset(data_, given / "quadruped");
  const auto missing = [] {
    try {
      learning::repository_dataset(robot::RobotKind::octopod, false);
    } catch (const BadInput& e) {
      return std::string(e.what());
    }
    return std::string("found");
  };
  struct DataEnv {
    explicit DataEnv(const std::string& dir) { setenv(learning::kDataEnv, dir.c_str(), 1); }
    ~DataEnv() { unsetenv(learning::kDataEnv); }
  };
  {
    const DataEnv env(dir_);
    EXPECT_EQ(learning::repository_dataset(robot::RobotKind::quadruped, false),
              given / "quadruped");
    EXPECT_EQ(learning::repository_dataset(robot::RobotKind::quadruped, true),
              source.parent_path() / "quadruped-reflex");
    const std::string named = missing();
    EXPECT_NE(named.find("no landscape dataset octopod"), std::string::npos) << named;
    EXPECT_NE(named.find(given.string() + ", "), std::string::npos) << named;
    EXPECT_NE(named.find(source.parent_path().string()), std::string::npos) << named;
    EXPECT_EQ(named.find('\n'), std::string::npos) << named;
  }
  EXPECT_EQ(learning::repository_dataset(robot::RobotKind::quadruped, false), source);
  EXPECT_NE(missing().find("$MULTICPG_DATA unset"), std::string::npos) << missing();
  expect_bad_input("learn --robot octopod --disable R1 --learner prior --steering off",
                   "no landscape dataset octopod");
}

}  // namespace
}  // namespace multicpg::testing
