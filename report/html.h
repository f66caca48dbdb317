// The reproduction report: index.html with every figure, table and video, each with a
// caption saying what the paper reports and what we measured, and the CSV behind it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "common/table.h"

namespace multicpg::report {

// Whether a claim of the paper came out the same in our runs.
enum class Reproduced { yes, partly, no };
std::string_view to_string(Reproduced r);

// One row of the verdict table that opens the report: a claim of the paper, the paper's number
// (experiments/paper.h), ours from this run's data, and the verdict by the rule `claim` states.
struct Verdict {
  std::string claim;
  std::string paper;
  std::string ours;
  Reproduced reproduced = Reproduced::no;
};

// One part of the report, e.g. "Gaits (paper Fig. 2)". Paths are relative to index.html.
struct Section {
  std::string id;
  std::string title;
  std::string paper;                // what the paper reports
  std::string measured;             // what we measured
  std::vector<std::string> images;  // PNG, each shown with its SVG and CSV beside it
  std::vector<std::string> videos;  // MP4
  std::vector<std::string> files;   // further data (CSV, JSON, Markdown)
  std::vector<Table> tables;
  // 3D replays (HTML, docs/replay.md), linked beside the video of the same name.
  std::vector<std::string> replays = {};
  // The section's rows of the verdict table (linked to the section).
  std::vector<Verdict> verdicts = {};
  // Data committed to the repository the section draws instead of computing it in this run
  // (e.g. a calibration that takes hours); empty when the run computed everything it shows.
  std::string reused = {};
  // Wall time of the stage that computed the section, in seconds (the report shows it beside the
  // section; a resumed report keeps the time of the run that computed it).
  double seconds = 0.0;
};

// "N of M claims reproduced" over every section's verdicts, with how many partly ("; K partly"):
// the report's first line and the run's last.
std::string verdict_line(const std::vector<Section>& sections);

nlohmann::json to_json(const Section& section);
Section section_from_json(const nlohmann::json& j);

// The whole page: the verdict table of every section's verdicts first, then the sections. It checks
// on load that every image and video loaded, marks any that did not in red, and sets <body
// data-media="ok"> or "broken:<files>" (read by the browser test).
std::string index_html(const std::string& title, const std::string& intro,
                       const std::vector<Section>& sections);

}  // namespace multicpg::report
