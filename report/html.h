// The reproduction report: index.html with every figure, table and video, each with a
// caption saying what the paper reports and what we measured, and the CSV behind it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/table.h"

namespace multicpg::report {

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
};

nlohmann::json to_json(const Section& section);
Section section_from_json(const nlohmann::json& j);

// The whole page. It checks on load that every image and video loaded, marks any that did not
// in red, and sets <body data-media="ok"> or "broken:<files>" (read by the browser test).
std::string index_html(const std::string& title, const std::string& intro,
                       const std::vector<Section>& sections);

}  // namespace multicpg::report
