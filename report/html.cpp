#include "report/html.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "common/enum_names.h"

namespace multicpg::report {
namespace {

constexpr auto kReproducedNames = enum_names<Reproduced>(
    {{Reproduced::yes, "yes"}, {Reproduced::partly, "partly"}, {Reproduced::no, "no"}});

// Checks every <img> and <video> after load and marks the ones that failed (every
// image and video must load).
constexpr const char* kMediaCheck = R"(<script>
function checkMedia() {
  const broken = [];
  for (const img of document.images) {
    if (!(img.complete && img.naturalWidth > 0)) broken.push(img.getAttribute('src'));
  }
  for (const video of document.querySelectorAll('video')) {
    if (video.error || video.readyState < 1) broken.push(video.getAttribute('src'));
  }
  for (const src of broken) {
    const note = document.createElement('p');
    note.className = 'missing';
    note.textContent = 'Could not load ' + src;
    document.body.prepend(note);
  }
  document.body.dataset.media = broken.length ? 'broken:' + broken.join(',') : 'ok';
}
window.addEventListener('load', () => setTimeout(checkMedia, 1000));
</script>)";

constexpr const char* kStyle = R"(<style>
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; margin-top: 2em; }
figure { margin: 1em 0; }
figure img, video { max-width: 100%; border: 1px solid #ddd; }
figcaption, .files { font-size: .9em; color: #555; }
.paper { background: #eef3fb; padding: .5em .8em; border-left: 4px solid #4a78c2; }
.ours { background: #f2f8ee; padding: .5em .8em; border-left: 4px solid #4c9a2a; }
table { border-collapse: collapse; margin: 1em 0; font-size: .9em; }
th, td { border: 1px solid #ccc; padding: .25em .5em; text-align: right; }
th.left, td.left { text-align: left; }
.missing { color: #b00; font-weight: bold; }
.reused { background: #fdf6e3; padding: .5em .8em; border-left: 4px solid #c9a227; }
td.yes { background: #e3f2dc; } td.partly { background: #fdf1d6; } td.no { background: #f8dcdc; }
nav a { margin-right: 1em; }
</style>)";

std::string link(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  return "<a href=\"" + html_escape(path) + "\">" + html_escape(name) + "</a>";
}

std::string sibling(const std::string& png, const char* ext) {
  return std::filesystem::path(png).replace_extension(ext).string();
}

// The verdict table: one row per claim, linked to the section that shows it.
std::string verdict_table(const std::vector<Section>& sections) {
  std::ostringstream out;
  out << "<h2 id=\"verdicts\">What reproduced</h2>\n<table class=\"verdicts\">\n<tr><th "
         "class=\"left\">claim</th><th class=\"left\">paper</th><th class=\"left\">ours</th>"
         "<th class=\"left\">reproduced</th><th class=\"left\">section</th></tr>\n";
  for (const Section& s : sections) {
    for (const Verdict& v : s.verdicts) {
      const std::string word(to_string(v.reproduced));
      out << "<tr><td class=\"left\">" << html_escape(v.claim) << "</td><td class=\"left\">"
          << html_escape(v.paper) << "</td><td class=\"left\">" << html_escape(v.ours)
          << "</td><td class=\"left " << word << "\">" << word
          << "</td><td class=\"left\"><a href=\"#" << html_escape(s.id) << "\">"
          << html_escape(s.title) << "</a></td></tr>\n";
    }
  }
  out << "</table>\n";
  return out.str();
}

}  // namespace

std::string_view to_string(Reproduced r) {
  return kReproducedNames.name(r);
}

std::string verdict_line(const std::vector<Section>& sections) {
  int claims = 0;
  int yes = 0;
  int partly = 0;
  for (const Section& s : sections) {
    for (const Verdict& v : s.verdicts) {
      ++claims;
      yes += v.reproduced == Reproduced::yes ? 1 : 0;
      partly += v.reproduced == Reproduced::partly ? 1 : 0;
    }
  }
  return std::to_string(yes) + " of " + std::to_string(claims) + " claims reproduced" +
         (partly > 0 ? " (" + std::to_string(partly) + " partly)" : "");
}

nlohmann::json to_json(const Section& s) {
  nlohmann::json tables = nlohmann::json::array();
  for (const Table& t : s.tables) {
    nlohmann::json columns = nlohmann::json::array();
    for (const Column& c : t.columns) {
      columns.push_back({{"title", c.title}, {"left", c.align == Align::left}});
    }
    tables.push_back({{"columns", columns}, {"rows", t.rows}});
  }
  nlohmann::json verdicts = nlohmann::json::array();
  for (const Verdict& v : s.verdicts) {
    verdicts.push_back({{"claim", v.claim},
                        {"paper", v.paper},
                        {"ours", v.ours},
                        {"reproduced", std::string(to_string(v.reproduced))}});
  }
  return {{"id", s.id},           {"title", s.title},
          {"paper", s.paper},     {"measured", s.measured},
          {"images", s.images},   {"videos", s.videos},
          {"files", s.files},     {"tables", tables},
          {"replays", s.replays}, {"verdicts", verdicts},
          {"reused", s.reused},   {"seconds", s.seconds}};
}

Section section_from_json(const nlohmann::json& j) {
  Section s;
  s.id = j.at("id").get<std::string>();
  s.title = j.at("title").get<std::string>();
  s.paper = j.at("paper").get<std::string>();
  s.measured = j.at("measured").get<std::string>();
  s.images = j.at("images").get<std::vector<std::string>>();
  s.videos = j.at("videos").get<std::vector<std::string>>();
  s.files = j.at("files").get<std::vector<std::string>>();
  for (const nlohmann::json& t : j.at("tables")) {
    Table table;
    for (const nlohmann::json& c : t.at("columns")) {
      table.columns.push_back({c.at("title").get<std::string>(),
                               c.at("left").get<bool>() ? Align::left : Align::right});
    }
    table.rows = t.at("rows").get<std::vector<std::vector<std::string>>>();
    s.tables.push_back(std::move(table));
  }
  s.replays = j.value("replays", std::vector<std::string>{});
  for (const nlohmann::json& v : j.value("verdicts", nlohmann::json::array())) {
    const std::string word = v.at("reproduced").get<std::string>();
    const Reproduced r = kReproducedNames.find(word).value_or(Reproduced::no);
    s.verdicts.push_back({v.at("claim").get<std::string>(), v.at("paper").get<std::string>(),
                          v.at("ours").get<std::string>(), r});
  }
  s.reused = j.value("reused", std::string());
  s.seconds = j.value("seconds", 0.0);
  return s;
}

std::string index_html(const std::string& title, const std::string& intro,
                       const std::vector<Section>& sections) {
  std::ostringstream out;
  out << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>"
      << html_escape(title) << "</title>\n"
      << kStyle << "\n</head>\n<body>\n<h1>" << html_escape(title) << "</h1>\n"
      << "<p class=\"verdict\"><strong>" << html_escape(verdict_line(sections))
      << "</strong> (<a href=\"#verdicts\">each claim</a>)</p>\n<p>" << html_escape(intro)
      << "</p>\n"
      << verdict_table(sections) << "<nav>";
  for (const Section& s : sections) {
    out << "<a href=\"#" << html_escape(s.id) << "\">" << html_escape(s.title) << "</a> ";
  }
  out << "</nav>\n";
  for (const Section& s : sections) {
    out << "<section id=\"" << html_escape(s.id) << "\">\n<h2>" << html_escape(s.title)
        << "</h2>\n<p class=\"paper\"><b>The paper:</b> " << html_escape(s.paper)
        << "</p>\n<p class=\"ours\"><b>We measured:</b> " << html_escape(s.measured) << "</p>\n";
    if (!s.reused.empty()) {
      out << "<p class=\"reused\"><b>Reuses committed data, not computed by this run:</b> "
          << html_escape(s.reused) << "</p>\n";
    }
    for (const Table& t : s.tables) out << to_html(t);
    for (const std::string& png : s.images) {
      out << "<figure><img src=\"" << html_escape(png) << "\" alt=\"" << html_escape(s.title)
          << "\"><figcaption>" << link(png) << " · " << link(sibling(png, ".svg"))
          << " · data: " << link(sibling(png, ".csv")) << "</figcaption></figure>\n";
    }
    std::vector<std::string> replays = s.replays;
    for (const std::string& mp4 : s.videos) {
      out << "<figure><video src=\"" << html_escape(mp4)
          << "\" controls preload=\"metadata\" muted></video><figcaption>" << link(mp4);
      const auto replay = std::find_if(replays.begin(), replays.end(), [&](const std::string& r) {
        return std::filesystem::path(r).stem() == std::filesystem::path(mp4).stem();
      });
      if (replay != replays.end()) {
        out << " · 3D replay: " << link(*replay);
        replays.erase(replay);
      }
      out << "</figcaption></figure>\n";
    }
    if (!replays.empty()) {
      out << "<p class=\"files\">3D replays:";
      for (const std::string& r : replays) out << " " << link(r);
      out << "</p>\n";
    }
    if (!s.files.empty()) {
      out << "<p class=\"files\">Data:";
      for (const std::string& f : s.files) out << " " << link(f);
      out << "</p>\n";
    }
    out << "<p class=\"files\">Computed in " << fixed(s.seconds, 0)
        << " s (wall time of this stage).</p>\n";
    out << "</section>\n";
  }
  out << kMediaCheck << "\n</body></html>\n";
  return out.str();
}

}  // namespace multicpg::report
