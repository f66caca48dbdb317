// A run recorded for its 3D replay (report/replay/page.h): the scene's geometry once, from the
// mjModel (every visible geom with its body, local pose, size and colour; meshes' vertices and
// faces; heightfields), then per controller step the pose of every body (mjData's xpos, xquat)
// and each foot's contact, and every event of the run (faults, recoveries, detections, trials,
// episodes) with the fault colours the films draw (report/fault_colours.h). It is a sim::Observer,
// so any run that steps through sim::Stepper can be recorded.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "report/render.h"
#include "robot/morphology.h"
#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::report {

// Poses are kept quantised: positions in units of 0.1 mm, quaternion components in units of
// 1e-4 (an orientation error under 1e-4 rad, 0.01 mm at the end of a 10 cm segment), well inside
// the millimetre a replay is checked to (docs/replay.md).
inline constexpr double kReplayPositionUnit = 1e-4;    // m
inline constexpr double kReplayQuaternionUnit = 1e-4;  // of a unit quaternion's component
// Values per body and step: x y z, then the quaternion w x y z.
inline constexpr std::size_t kReplayPoseValues = 7;

// A texture's checker as the page draws it (MuJoCo's builtin "checker": two colours).
struct ReplayChecker {
  Rgba first{};
  Rgba second{};
  std::array<double, 2> repeat{1.0, 1.0};  // the material's texrepeat
};

// One visible geom, in its body's frame (MuJoCo's geom_pos, geom_quat, geom_size).
struct ReplayGeom {
  int type = mjGEOM_BOX;  // mjtGeom
  int body = -1;          // index into ReplayScene::bodies; -1: the world (static)
  int model_geom = -1;    // the geom's id in the mjModel (fault colours name geoms by it)
  std::string name;
  std::array<double, 3> pos{};
  std::array<double, 4> quat{1.0, 0.0, 0.0, 0.0};
  std::array<double, 3> size{};
  Rgba rgba{};
  int mesh = -1;    // index into ReplayScene::meshes
  int hfield = -1;  // index into ReplayScene::hfields
  std::optional<ReplayChecker> checker;
};

struct ReplayMesh {
  std::vector<float> vertices;      // x y z per vertex, in the mesh's frame
  std::vector<std::int32_t> faces;  // three vertex indices per triangle
};

struct ReplayHfield {
  int nrow = 0;
  int ncol = 0;
  std::array<double, 4> size{};  // MuJoCo's: x and y half-sizes, elevation, base depth
  std::vector<float> data;       // nrow x ncol elevations in 0..1, row-major (row = y)
};

struct ReplayBody {
  std::string name;
  int parent = -1;  // index into ReplayScene::bodies; -1: the world
};

// What the run walks in and on, read once from its model.
struct ReplayScene {
  std::string robot;  // the layout's name ("hexapod") or the robot file's
  robot::Morphology morphology;
  double control_dt = 0.0;
  std::vector<ReplayBody> bodies;  // every body but the world, in model order
  int trunk = -1;                  // the body of the free joint
  std::vector<ReplayGeom> geoms;
  std::vector<ReplayMesh> meshes;
  std::vector<ReplayHfield> hfields;
  std::optional<std::array<double, 2>> tunnel;  // the corridor's length and width, m
};

// A geom a fault reshapes (a short tibia), as the run's own model has it while the fault is in
// force (sim/fault_effects.h).
struct ReplayReshape {
  int geom = -1;  // index into ReplayScene::geoms
  std::array<double, 3> pos{};
  std::array<double, 4> quat{};
  std::array<double, 3> size{};
};

// The faults in force from `step` on: each struck geom's colour (fault_colours), each struck
// leg's (its fault kind's colour), the faults as the films' caption names them, and the geoms
// they reshape.
struct ReplayPaint {
  long step = 0;
  Colouring colours;  // model geom ids
  std::vector<std::pair<std::size_t, Rgba>> legs;
  std::string faults;
  std::vector<ReplayReshape> reshaped;
};

// The legs' periods from `step` on.
struct ReplayPeriods {
  long step = 0;
  std::vector<int> periods;
};

struct Recording {
  ReplayScene scene;
  long first_step = 0;  // the step of row 0
  // Row r (the state after first_step + r steps), body b: [(r * bodies + b) * 7 + value],
  // quantised (kReplayPositionUnit, kReplayQuaternionUnit). Each body's quaternion keeps the sign
  // nearest its previous one, so that it changes smoothly from step to step.
  std::vector<std::int32_t> poses;
  std::vector<std::uint8_t> contacts;  // [row * legs + leg], 1 = the foot touches the ground
  std::vector<body::Event> events;
  std::vector<ReplayPaint> paints;
  std::vector<ReplayPeriods> periods;  // each change, the first at first_step
  // The trunk at row 0: the course the run holds starts there, along its heading.
  std::array<double, 3> start{};  // x, y (m), yaw (deg)

  std::size_t rows() const {
    return scene.bodies.empty() ? 0 : poses.size() / (scene.bodies.size() * kReplayPoseValues);
  }
  // A body's position at row `row`, m, as recorded (quantised).
  std::array<double, 3> position(std::size_t row, std::size_t body) const;
};

// The scene of `model`: its bodies, its visible geoms (MuJoCo's visible groups 0-2, not fully
// transparent; a geom with a material and the default colour takes the material's), its meshes,
// heightfields and the tunnel.
ReplayScene replay_scene(const sim::SimModel& model);

// Records a run. Attach it to a sim::Stepper (or walk(), run_learning(), run_tunnel()) from the
// start; then row 0 is the start. Attached later (a Python simulation already walking), pass the
// step of the first state it will see.
class ReplayRecorder final : public sim::Observer {
 public:
  explicit ReplayRecorder(long first_step = 0);
  ReplayRecorder(const ReplayRecorder&) = delete;
  ReplayRecorder& operator=(const ReplayRecorder&) = delete;
  ~ReplayRecorder() override;

  void on_start(const sim::SimModel& model, const sim::SimState& state) override;
  void on_step(const sim::SimModel& model, const sim::SimState& state) override;
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const body::Event& event) override;

  const Recording& recording() const { return recording_; }

 private:
  // The scene and the faults in force, at the first call.
  void begin(const sim::SimModel& model, const sim::SimState& state);
  void append_row(const sim::SimModel& model, const sim::SimState& state);
  void paint(const sim::SimModel& model, const sim::SimState& state, long step);

  Recording recording_;
  bool begun_ = false;
  // Bodies' poses are computed from the state's qpos in a scratch mjData: the state's own xpos
  // is one physics step old after mj_step, and must not be recomputed (the yaw of a model without
  // a framequat sensor is read from it, sim.h).
  std::unique_ptr<mjData, sim::MjDataDeleter> scratch_;
  std::vector<std::array<std::int32_t, 4>> last_quat_;
};

}  // namespace multicpg::report
