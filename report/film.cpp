#include "report/film.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <memory>
#include <sstream>

#include "body/fault_spec.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/interrupt.h"
#include "common/table.h"
#include "report/fault_colours.h"
#include "robot/leg_sets.h"

namespace multicpg::report {
namespace {

std::string fmt_deviation(const std::string& prefix, double deg) {
  return prefix + fixed(deg, 1) + " deg";
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
    : model_(model), spec_(std::move(spec)), format_(film_format(spec_.out)) {
  require_writable_file(spec_.out);
  if (spec_.speed < 1) {
    throw BadInput("--speed must be at least 1, got " + std::to_string(spec_.speed));
  }
  if (format_ == FilmFormat::picture) {
    renderer_.emplace(model.mj.get(), spec_.width, spec_.height);
    return;
  }
  const int fps = static_cast<int>(std::lround(1.0 / model.control_dt));
  video_.emplace(spec_.out, spec_.width, spec_.height, fps);
  // The render thread opens its GL context itself (a context is current on one thread); wait
  // for it so a missing GL platform fails here, not at the first frame.
  std::promise<void> opened;
  std::future<void> ready = opened.get_future();
  worker_ = std::thread([this, &opened] {
    std::optional<Renderer> renderer;
    try {
      renderer.emplace(model_.mj.get(), spec_.width, spec_.height);
    } catch (...) {
      opened.set_exception(std::current_exception());
      return;
    }
    opened.set_value();
    const std::unique_ptr<mjData, void (*)(mjData*)> data(mj_makeData(model_.mj.get()),
                                                          mj_deleteData);
    for (;;) {
      Pose next;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return closing_ || !queue_.empty(); });
        if (const int signal = interrupt_signal(); signal != 0 && !queue_.empty()) {
          // Stopped by SIGINT or SIGTERM: the frames left are not drawn (common/interrupt.h).
          failure_ = std::make_exception_ptr(Interrupted(signal));
          queue_.clear();
        }
        if (queue_.empty()) return;
        next = std::move(queue_.front());
        queue_.pop_front();
      }
      try {
        video_->add_frame(draw(*renderer, data.get(), next));
      } catch (...) {
        const std::lock_guard lock(mutex_);
        failure_ = std::current_exception();
        queue_.clear();
        return;
      }
    }
  });
  try {
    ready.get();
  } catch (...) {
    worker_.join();
    throw;
  }
}

Film::~Film() {
  {
    const std::lock_guard lock(mutex_);
    queue_.clear();  // without finish() the video is not written: no frame left to draw
  }
  stop_worker();
}

void Film::stop_worker() {
  if (!worker_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    closing_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

void Film::rethrow_failure() {
  const std::lock_guard lock(mutex_);
  if (failure_) std::rethrow_exception(failure_);
}

namespace {

// What a fault event struck, for a caption: "R1+R3", "R2.CTr locked", "imu drift 0.5".
std::string fault_event_text(const robot::Morphology& morph, const body::Fault& fault) {
  std::string text = body::malfunction_text(morph, fault);
  std::replace(text.begin(), text.end(), ':', ' ');
  std::replace(text.begin(), text.end(), '=', ' ');
  return text;
}

}  // namespace

FramePose frame_pose(const sim::SimModel& model, const sim::SimState& state,
                     const std::string& caption) {
  FramePose out;
  const mjModel* m = model.mj.get();
  out.qpos.assign(state.data->qpos, state.data->qpos + m->nq);
  out.model = state.faults.model;
  out.colours = fault_colours(model, state.faults.schedule.in_force());
  std::vector<int> periods;
  const robot::Morphology& morph = model.controller.morphology;
  for (const neural::LegState& leg : state.controller.legs) periods.push_back(leg.cpg.period);
  out.overlay.titles = "Step\nTime\nPeriods\nFaults";
  out.overlay.values = std::to_string(state.step) + "\n" + fixed(state.data->time, 1) + " s\n" +
                       robot::period_map_text(morph, periods) + "\n" +
                       faults_caption(morph, state.faults.schedule.in_force());
  if (!caption.empty()) {
    out.overlay.titles += "\n";
    out.overlay.values += "\n" + caption;
  }
  return out;
}

Image draw_frame(Renderer& renderer, const sim::SimModel& model, mjData* data,
                 const CameraSpec& camera, const FramePose& pose) {
  const mjModel* m = pose.model ? pose.model.get() : model.mj.get();
  std::copy(pose.qpos.begin(), pose.qpos.end(), data->qpos);
  mj_fwdPosition(m, data);  // body and geom poses, the tracked subtree's centre, the lights
  return render_frame(renderer, m, data, camera, pose.colours, pose.overlay);
}

Image film_frame(Renderer& renderer, const sim::SimModel& model, const sim::SimState& state,
                 const CameraSpec& camera, const std::string& caption) {
  const std::unique_ptr<mjData, void (*)(mjData*)> scratch(mj_makeData(model.mj.get()),
                                                           mj_deleteData);
  return draw_frame(renderer, model, scratch.get(), camera, frame_pose(model, state, caption));
}

Film::Pose Film::pose(const sim::SimState& state, const std::string& caption) const {
  return frame_pose(model_, state, caption);
}

Image Film::draw(Renderer& renderer, mjData* data, const Pose& pose) const {
  return draw_frame(renderer, model_, data, spec_.camera, pose);
}

void Film::capture(const sim::SimState& state, const std::string& caption) {
  if (!video_ || state.step % spec_.speed != 0) return;
  rethrow_failure();
  Pose next = pose(state, caption);
  {
    const std::lock_guard lock(mutex_);
    queue_.push_back(std::move(next));
  }
  wake_.notify_one();
}

void Film::finish() {
  if (!video_) return;
  stop_worker();
  rethrow_failure();
  video_->finish();
}

void Film::picture(const sim::SimState& state, const std::string& caption) {
  if (!renderer_) throw BadInput("'" + spec_.out.string() + "' is a video, not a picture");
  const Pose p = pose(state, caption);
  const mjModel* m = model_.mj.get();
  const std::unique_ptr<mjData, void (*)(mjData*)> data(mj_makeData(m), mj_deleteData);
  write_png(draw(*renderer_, data.get(), p), spec_.out);
}

void FilmObserver::on_step(const sim::SimModel& /*model*/, const sim::SimState& state) {
  film_.capture(state, caption_);
}

void FilmObserver::on_event(const sim::SimModel& model, const sim::SimState& /*state*/,
                            const body::Event& e) {
  const robot::Morphology& morph = model.controller.morphology;
  switch (e.kind) {
    case body::EventKind::fault:
      caption_ = e.fault ? fault_event_text(morph, *e.fault) + " failed" : "a fault";
      break;
    case body::EventKind::recovery:
      caption_ = e.fault ? fault_event_text(morph, *e.fault) + " works again" : "a recovery";
      break;
    case body::EventKind::detection:
      caption_ = fmt_deviation("deviation ", e.deviation_deg) + ": learning starts";
      break;
    case body::EventKind::trial_start:
      caption_ = "learning: trial " + std::to_string(e.trial);
      break;
    case body::EventKind::trial_end:
      caption_ = "trial " + std::to_string(e.trial) + fmt_deviation(": ", e.deviation_deg) +
                 (e.accepted ? ", kept" : ", rejected");
      break;
    case body::EventKind::episode_end:
      caption_ = std::string(e.accepted ? "walks straight" : "learning stopped") + " after " +
                 std::to_string(e.trial) + " trials";
      break;
  }
}

int Film::frames() const {
  return video_ ? video_->frames() : 1;
}

}  // namespace multicpg::report
