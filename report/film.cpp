#include "report/film.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "common/atomic_file.h"
#include "common/errors.h"

namespace multicpg::report {
namespace {

std::string fmt_deviation(const std::string& prefix, double deg) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f deg", deg);
  return prefix + text;
}

}  // namespace

FilmFormat film_format(const std::filesystem::path& out) {
  const std::string ext = out.extension().string();
  if (ext == ".mp4") return FilmFormat::video;
  if (ext == ".png") return FilmFormat::picture;
  throw BadInput("cannot render to '" + out.string() + "': the file type must be .mp4 (video) or " +
                 ".png (one frame)");
}

Film::Film(const sim::SimModel& model, FilmSpec spec)
    : model_(model),
      spec_(std::move(spec)),
      format_(film_format(spec_.out)),
      renderer_(model.mj.get(), spec_.width, spec_.height) {
  require_writable_file(spec_.out);
  if (spec_.speed < 1) {
    throw BadInput("--speed must be at least 1, got " + std::to_string(spec_.speed));
  }
  if (format_ == FilmFormat::video) {
    const int fps = static_cast<int>(std::lround(1.0 / model.control_dt));
    video_.emplace(spec_.out, spec_.width, spec_.height, fps);
  }
}

Image Film::frame(const sim::SimState& state, const std::string& caption) {
  return film_frame(renderer_, model_, state, spec_.camera, caption);
}

Image film_frame(Renderer& renderer, const sim::SimModel& model, const sim::SimState& state,
                 const CameraSpec& camera, const std::string& caption) {
  std::vector<std::string> red;
  std::ostringstream periods;
  std::string disabled;
  const robot::Morphology& morph = model.controller.morphology;
  for (std::size_t i = 0; i < morph.size(); ++i) {
    const neural::LegState& leg = state.controller.legs[i];
    periods << (i ? " " : "") << morph.legs[i].name << "=" << leg.cpg.period;
    if (leg.disabled) {
      red.push_back(morph.legs[i].name + "_");
      disabled += (disabled.empty() ? "" : " ") + morph.legs[i].name;
    }
  }
  std::ostringstream time;
  time.precision(1);
  time << std::fixed << state.data->time << " s";
  Overlay overlay;
  overlay.titles = "Step\nTime\nPeriods\nDisabled";
  overlay.values = std::to_string(state.step) + "\n" + time.str() + "\n" + periods.str() + "\n" +
                   (disabled.empty() ? "none" : disabled);
  if (!caption.empty()) {
    overlay.titles += "\n";
    overlay.values += "\n" + caption;
  }
  return render_frame(renderer, model.mj.get(), state.data.get(), camera, red, overlay);
}

void Film::capture(const sim::SimState& state, const std::string& caption) {
  if (video_ && state.step % spec_.speed == 0) video_->add_frame(frame(state, caption));
}

void Film::finish() {
  if (video_) video_->finish();
}

void Film::picture(const sim::SimState& state, const std::string& caption) {
  write_png(frame(state, caption), spec_.out);
}

void FilmObserver::on_step(const sim::SimModel& /*model*/, const sim::SimState& state) {
  film_.capture(state, caption_);
}

void FilmObserver::on_event(const sim::SimModel& model, const sim::SimState& /*state*/,
                            const sim::Event& e) {
  const robot::Morphology& morph = model.controller.morphology;
  switch (e.kind) {
    case sim::EventKind::fault:
      caption_ = robot::leg_list_name(morph, e.legs) + " failed";
      break;
    case sim::EventKind::recovery:
      caption_ = robot::leg_list_name(morph, e.legs) + " works again";
      break;
    case sim::EventKind::detection:
      caption_ = fmt_deviation("deviation ", e.deviation_deg) + ": learning starts";
      break;
    case sim::EventKind::trial_start:
      caption_ = "learning: trial " + std::to_string(e.trial);
      break;
    case sim::EventKind::trial_end:
      caption_ = "trial " + std::to_string(e.trial) + fmt_deviation(": ", e.deviation_deg) +
                 (e.accepted ? ", kept" : ", rejected");
      break;
    case sim::EventKind::episode_end:
      caption_ = std::string(e.accepted ? "walks straight" : "learning stopped") + " after " +
                 std::to_string(e.trial) + " trials";
      break;
  }
}

int Film::frames() const {
  return video_ ? video_->frames() : 1;
}

}  // namespace multicpg::report
