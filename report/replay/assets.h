// The files the replay page inlines, embedded into the program at build time
// (report/replay/embed.cmake): three.js and its orbit controls from Debian's libjs-three, and
// the page's own template, script and style from this folder.
#pragma once

#include <string_view>

namespace multicpg::report {

struct ReplayAssets {
  std::string_view three;           // three.min.js
  std::string_view orbit_controls;  // examples/js/controls/OrbitControls.js
  std::string_view page;            // replay.html: the template, with @NAME@ markers
  std::string_view script;          // replay.js
  std::string_view style;           // replay.css
};

const ReplayAssets& replay_assets();

}  // namespace multicpg::report
