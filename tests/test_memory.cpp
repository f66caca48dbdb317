// Memory that does not grow with the run (docs/cli.md: `walk --csv` streams its rows): a walk of
// 10^8 steps writing its CSV keeps a flat peak resident memory (VmHWM) between a few seconds and
// three times as long, as the rows go to the file and nothing per step stays in memory.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <string>
#include <thread>

#include "tests/cli_process.h"
#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

namespace fs = std::filesystem;

// When the peak is read: after the start-up (model, first rows), and three times as late.
constexpr std::chrono::seconds kEarly{4};
constexpr std::chrono::seconds kLate{12};
// Flat: the later peak within 10 % of the earlier (the bound), plus 1 MB for the
// allocator's slack on a small process.
constexpr double kGrowth = 0.10;
constexpr long kSlackKb = 1024;

TEST(Memory, LongWalkWithCsvStaysFlat) {
  const std::string dir = make_temp_dir("multicpg-mem-");
  const fs::path csv = fs::path(dir) / "walk.csv";
  CliProcess cli({"walk", "--steps", "100000000", "--csv", csv.string()});
  std::this_thread::sleep_for(kEarly);
  const long early = cli.status_kb("VmHWM");
  std::this_thread::sleep_for(kLate - kEarly);
  const long late = cli.status_kb("VmHWM");
  const std::uintmax_t rows_bytes =
      fs::file_size(csv.string() + ".tmp" + std::to_string(cli.pid()));
  cli.signal(SIGTERM);
  ASSERT_TRUE(cli.wait(std::chrono::seconds(20)));
  EXPECT_EQ(cli.exit_code(), 143) << cli.err();
  ASSERT_GT(early, 0);
  EXPECT_LE(late, static_cast<long>(early * (1 + kGrowth)) + kSlackKb)
      << "VmHWM " << early << " kB after " << kEarly.count() << " s, " << late << " kB after "
      << kLate.count() << " s; " << rows_bytes << " bytes of CSV written";
  EXPECT_GT(rows_bytes, 1u << 20) << "the walk wrote its rows as it went";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace multicpg::testing
