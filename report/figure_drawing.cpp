// Drawing a figure (figure_drawing.h): gnuplot run on a figure's script, the shared checks.
#include "report/figure_drawing.h"

#include <unistd.h>

#include <system_error>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/installed_data.h"
#include "report/subprocess.h"

namespace multicpg::report::drawing {

namespace fs = std::filesystem;

namespace {

constexpr const char* kGnuplot = "gnuplot";
// Installed in <prefix>/share/multicpg/gnuplot (common/installed_data.h).
constexpr const char* kInstalledScripts = "gnuplot";

std::string temp_name(const fs::path& path) {
  return path.string() + ".tmp" + std::to_string(::getpid());
}

}  // namespace

std::string gp_string(std::string_view text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

fs::path scripts_dir() {
  const fs::path source(MULTICPG_GNUPLOT_SOURCE_DIR);
  if (fs::is_directory(source)) return source;
  const fs::path data = program_data_dir();
  if (!data.empty() && fs::is_directory(data / kInstalledScripts)) return data / kInstalledScripts;
  throw RuntimeFailure("gnuplot scripts not found in " + source.string() +
                       " nor next to the program");
}

void run_gnuplot(const fs::path& script, const std::string& terminal, const Params& params,
                 const fs::path& out) {
  // A symlink is written through (the file it names replaced, the link kept), as every output
  // file is (common/atomic_file.h).
  const fs::path target = follow_symlinks(out);
  const std::string tmp = temp_name(target);
  const std::string preamble = terminal + "; set output " + gp_string(tmp) + "; " + params.code();
  const ProcessResult result = run_process({kGnuplot, "-e", preamble, script.string()});
  std::error_code ec;
  if (result.exit_code != 0 || !fs::exists(tmp) || fs::file_size(tmp, ec) == 0) {
    fs::remove(tmp, ec);
    throw RuntimeFailure("gnuplot " + script.filename().string() + " failed: " +
                         (result.exit_code == 0 ? "wrote no picture (" + tool_error(result) + ")"
                                                : tool_error(result)));
  }
  try {
    sync_and_rename(tmp, target);
  } catch (const RuntimeFailure&) {
    fs::remove(tmp, ec);
    throw;
  }
}

FigureFiles draw(const FigureInfo& info, const fs::path& out_dir, std::string_view stem,
                 const Csv& csv, Params params) {
  const std::string name(stem.empty() ? info.stem : stem);
  FigureFiles files{out_dir / (name + ".png"), out_dir / (name + ".svg"),
                    out_dir / (name + ".csv")};
  write_file_atomic(files.csv, csv.text());
  const fs::path dir = scripts_dir();
  params.text("data", files.csv.string()).text("dir", (dir / "").string());
  const fs::path script = dir / info.script;
  const std::string size =
      " size " + std::to_string(info.width) + "," + std::to_string(info.height);
  const std::string look = " enhanced font " + gp_string(kFont) + " background rgb 'white'";
  run_gnuplot(script, "set terminal pngcairo" + size + look, params, files.png);
  run_gnuplot(script, "set terminal svg" + size + look, params, files.svg);
  return files;
}

void require(bool ok, std::string_view figure, const std::string& what) {
  if (!ok) throw BadInput(std::string(figure) + ": " + what);
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) {
    if (!out.empty()) out += ' ';
    out += w;
  }
  return out;
}

std::vector<std::pair<std::size_t, std::size_t>> runs_of(
    const std::vector<std::vector<bool>>& table, std::size_t leg, bool value) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  std::size_t t = 0;
  while (t < table.size()) {
    if (table[t][leg] != value) {
      ++t;
      continue;
    }
    const std::size_t start = t;
    while (t < table.size() && table[t][leg] == value) ++t;
    runs.emplace_back(start, t);
  }
  return runs;
}

std::vector<double> reference_deviations(const std::vector<TrialPoint>& trials) {
  std::vector<double> out;
  double reference = trials.empty() ? 0.0 : trials.front().deviation_deg;
  for (const TrialPoint& trial : trials) {
    if (trial.accepted) reference = trial.deviation_deg;
    out.push_back(reference);
  }
  return out;
}

}  // namespace multicpg::report::drawing
