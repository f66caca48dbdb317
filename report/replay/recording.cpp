#include "report/replay/recording.h"

#include <algorithm>
#include <cmath>

#include "report/fault_colours.h"

namespace multicpg::report {
namespace {

// MuJoCo shows geom groups 0, 1 and 2 by default (mjv_defaultOption); the others are hidden
// helpers (collision shapes, markers), as in the films.
constexpr int kVisibleGroups = 3;
// A geom whose colour is MuJoCo's default takes its material's (mjv_updateScene does so).
constexpr Rgba kDefaultGeomRgba{0.5F, 0.5F, 0.5F, 1.0F};

std::int32_t quantise(double value, double unit) {
  return static_cast<std::int32_t>(std::lround(value / unit));
}

template <std::size_t N>
std::array<double, N> copy_array(const mjtNum* values) {
  std::array<double, N> out{};
  std::copy(values, values + N, out.begin());
  return out;
}

Rgba rgba_at(const float* values) {
  return {values[0], values[1], values[2], values[3]};
}

// The two colours of a 2D texture's checker (texels at the ends of its first row), with the
// material's repeat; none for a texture of one colour or of another type.
std::optional<ReplayChecker> checker_of(const mjModel* m, int material) {
  const int tex = m->mat_texid[material];
  if (tex < 0 || m->tex_type[tex] != mjTEXTURE_2D || m->tex_width[tex] < 2) return std::nullopt;
  const unsigned char* rgb = m->tex_rgb + m->tex_adr[tex];
  const unsigned char* last = rgb + 3 * (m->tex_width[tex] - 1);
  const auto colour = [](const unsigned char* c) {
    return Rgba{c[0] / 255.0F, c[1] / 255.0F, c[2] / 255.0F, 1.0F};
  };
  if (std::equal(rgb, rgb + 3, last)) return std::nullopt;
  return ReplayChecker{colour(rgb),
                       colour(last),
                       {m->mat_texrepeat[2 * material], m->mat_texrepeat[2 * material + 1]}};
}

}  // namespace

std::array<double, 3> Recording::position(std::size_t row, std::size_t body) const {
  const std::int32_t* p = poses.data() + (row * scene.bodies.size() + body) * kReplayPoseValues;
  return {p[0] * kReplayPositionUnit, p[1] * kReplayPositionUnit, p[2] * kReplayPositionUnit};
}

ReplayScene replay_scene(const sim::SimModel& model) {
  const mjModel* m = model.mj.get();
  ReplayScene scene;
  scene.morphology = model.controller.morphology;
  scene.robot = scene.morphology.name;
  scene.control_dt = model.control_dt;
  for (int b = 1; b < m->nbody; ++b) {
    const char* name = mj_id2name(m, mjOBJ_BODY, b);
    scene.bodies.push_back(
        {name != nullptr ? name : "body" + std::to_string(b), m->body_parentid[b] - 1});
  }
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] == mjJNT_FREE && m->jnt_qposadr[j] == model.root_qpos) {
      scene.trunk = m->jnt_bodyid[j] - 1;
    }
  }
  std::vector<int> mesh_index(static_cast<std::size_t>(m->nmesh), -1);
  std::vector<int> hfield_index(static_cast<std::size_t>(m->nhfield), -1);
  for (int g = 0; g < m->ngeom; ++g) {
    Rgba rgba = rgba_at(m->geom_rgba + 4 * g);
    const int material = m->geom_matid[g];
    if (material >= 0 && rgba == kDefaultGeomRgba) rgba = rgba_at(m->mat_rgba + 4 * material);
    if (m->geom_group[g] >= kVisibleGroups || rgba[3] <= 0.0F) continue;
    ReplayGeom geom;
    geom.type = m->geom_type[g];
    geom.body = m->geom_bodyid[g] - 1;
    geom.model_geom = g;
    const char* name = mj_id2name(m, mjOBJ_GEOM, g);
    geom.name = name != nullptr ? name : "geom" + std::to_string(g);
    geom.pos = copy_array<3>(m->geom_pos + 3 * g);
    geom.quat = copy_array<4>(m->geom_quat + 4 * g);
    geom.size = copy_array<3>(m->geom_size + 3 * g);
    geom.rgba = rgba;
    if (material >= 0) geom.checker = checker_of(m, material);
    const int data = m->geom_dataid[g];
    if (geom.type == mjGEOM_MESH && data >= 0) {
      int& index = mesh_index[static_cast<std::size_t>(data)];
      if (index < 0) {
        index = static_cast<int>(scene.meshes.size());
        ReplayMesh mesh;
        const float* v = m->mesh_vert + 3 * m->mesh_vertadr[data];
        mesh.vertices.assign(v, v + 3 * m->mesh_vertnum[data]);
        const int* f = m->mesh_face + 3 * m->mesh_faceadr[data];
        mesh.faces.assign(f, f + 3 * m->mesh_facenum[data]);
        scene.meshes.push_back(std::move(mesh));
      }
      geom.mesh = index;
    }
    if (geom.type == mjGEOM_HFIELD && data >= 0) {
      int& index = hfield_index[static_cast<std::size_t>(data)];
      if (index < 0) {
        index = static_cast<int>(scene.hfields.size());
        ReplayHfield field;
        field.nrow = m->hfield_nrow[data];
        field.ncol = m->hfield_ncol[data];
        field.size = copy_array<4>(m->hfield_size + 4 * data);
        const float* h = m->hfield_data + m->hfield_adr[data];
        field.data.assign(h, h + static_cast<std::size_t>(field.nrow) * field.ncol);
        scene.hfields.push_back(std::move(field));
      }
      geom.hfield = index;
    }
    scene.geoms.push_back(std::move(geom));
  }
  if (model.scene.tunnel) {
    scene.tunnel = std::array<double, 2>{model.scene.tunnel_length, model.scene.tunnel_width};
  }
  return scene;
}

ReplayRecorder::ReplayRecorder(long first_step) {
  recording_.first_step = first_step;
}

ReplayRecorder::~ReplayRecorder() = default;

void ReplayRecorder::begin(const sim::SimModel& model, const sim::SimState& state) {
  if (begun_) return;
  begun_ = true;
  recording_.scene = replay_scene(model);
  scratch_.reset(mj_makeData(model.mj.get()));
  last_quat_.assign(recording_.scene.bodies.size(), {1, 0, 0, 0});
  const sim::Position p = sim::trunk_position(model, state);
  recording_.start = {p.x, p.y, sim::trunk_yaw_deg(model, state)};
  if (!state.faults.schedule.in_force().empty()) paint(model, state, recording_.first_step);
}

void ReplayRecorder::on_start(const sim::SimModel& model, const sim::SimState& state) {
  begin(model, state);
  append_row(model, state);
}

void ReplayRecorder::on_step(const sim::SimModel& model, const sim::SimState& state) {
  begin(model, state);
  append_row(model, state);
}

void ReplayRecorder::on_event(const sim::SimModel& model, const sim::SimState& state,
                              const body::Event& event) {
  begin(model, state);
  recording_.events.push_back(event);
  if (event.kind == body::EventKind::fault || event.kind == body::EventKind::recovery) {
    paint(model, state, event.step);
  }
}

void ReplayRecorder::append_row(const sim::SimModel& model, const sim::SimState& state) {
  // The model the run steps now: a fault may have moved a body (a short tibia's foot).
  const mjModel* m = sim::physics_model(model, state);
  mjData* d = scratch_.get();
  std::copy(state.data->qpos, state.data->qpos + m->nq, d->qpos);
  mj_kinematics(m, d);
  for (std::size_t b = 0; b < recording_.scene.bodies.size(); ++b) {
    const int id = static_cast<int>(b) + 1;
    for (int i = 0; i < 3; ++i) {
      recording_.poses.push_back(quantise(d->xpos[3 * id + i], kReplayPositionUnit));
    }
    std::array<std::int32_t, 4> q{};
    for (int i = 0; i < 4; ++i) q[i] = quantise(d->xquat[4 * id + i], kReplayQuaternionUnit);
    // q and -q are one orientation: keep the one nearest the last, so the steps stay small.
    std::array<std::int32_t, 4>& last = last_quat_[b];
    std::int64_t dot = 0;
    for (int i = 0; i < 4; ++i) dot += static_cast<std::int64_t>(q[i]) * last[i];
    if (dot < 0) {
      for (std::int32_t& v : q) v = -v;
    }
    last = q;
    recording_.poses.insert(recording_.poses.end(), q.begin(), q.end());
  }
  for (std::size_t leg = 0; leg < model.legs.size(); ++leg) {
    recording_.contacts.push_back(sim::foot_contact(model, state, leg) ? 1 : 0);
  }
  std::vector<int> periods;
  for (const neural::LegState& leg : state.controller.legs) periods.push_back(leg.cpg.period);
  if (recording_.periods.empty() || recording_.periods.back().periods != periods) {
    const long row = static_cast<long>(recording_.rows()) - 1;
    recording_.periods.push_back({recording_.first_step + row, std::move(periods)});
  }
}

void ReplayRecorder::paint(const sim::SimModel& model, const sim::SimState& state, long step) {
  ReplayPaint p;
  p.step = step;
  p.colours = fault_colours(model, state.faults.schedule.in_force());
  for (const body::Fault& f : state.faults.schedule.in_force()) {
    for (std::size_t leg : f.legs) p.legs.emplace_back(leg, kind_colour(f.kind));
  }
  p.faults = faults_caption(model.controller.morphology, state.faults.schedule.in_force());
  const mjModel* shared = model.mj.get();
  const mjModel* now = sim::physics_model(model, state);
  const std::vector<ReplayGeom>& geoms = recording_.scene.geoms;
  for (std::size_t i = 0; now != shared && i < geoms.size(); ++i) {
    const int g = geoms[i].model_geom;
    const bool same =
        std::equal(now->geom_size + 3 * g, now->geom_size + 3 * g + 3, shared->geom_size + 3 * g) &&
        std::equal(now->geom_pos + 3 * g, now->geom_pos + 3 * g + 3, shared->geom_pos + 3 * g) &&
        std::equal(now->geom_quat + 4 * g, now->geom_quat + 4 * g + 4, shared->geom_quat + 4 * g);
    if (same) continue;
    p.reshaped.push_back({static_cast<int>(i), copy_array<3>(now->geom_pos + 3 * g),
                          copy_array<4>(now->geom_quat + 4 * g),
                          copy_array<3>(now->geom_size + 3 * g)});
  }
  recording_.paints.push_back(std::move(p));
}

}  // namespace multicpg::report
