#include "sim/robot_file.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/errors.h"
#include "common/input_file.h"
#include "common/toml_file.h"
#include "sim/model_build.h"
#include "sim/mujoco_load.h"

namespace multicpg::sim {
namespace {

// One joint of a leg map: { joint = ..., sign = ..., window = [lo, hi] }.
robot::JointMap joint(const TomlReader& r, const toml::table& table, const std::string& prefix,
                      std::string_view key) {
  const std::string k = prefix + std::string(key);
  const toml::table* t = r.node(table, prefix, key).as_table();
  if (t == nullptr) r.fail(k, "must be a table { joint = ..., sign = ..., window = [lo, hi] }");
  r.only(*t, k + ".", {"joint", "sign", "window"});
  robot::JointMap j;
  j.name = r.text(*t, k + ".", "joint");
  j.sign = r.number(*t, k + ".", "sign");
  if (j.sign != 1.0 && j.sign != -1.0) r.fail(k + ".sign", "must be 1 or -1");
  const toml::array* w = r.node(*t, k + ".", "window").as_array();
  if (w == nullptr || w->size() != 2) r.fail(k + ".window", "must be [lo, hi] in rad");
  j.window = {r.number(*w->get(0), k + ".window"), r.number(*w->get(1), k + ".window")};
  if (!(j.window.lo < j.window.hi)) r.fail(k + ".window", "lo must be below hi");
  return j;
}

// The built-in robot whose layout has `legs` legs.
robot::RobotKind layout_of(std::size_t legs, const TomlReader& r) {
  for (robot::RobotKind kind : robot::kRobotKinds) {
    if (robot::morphology(kind).size() == legs) return kind;
  }
  r.fail("legs", std::to_string(legs) +
                     " legs; a robot file has 4, 6 or 8 (the quadruped's, hexapod's or octopod's "
                     "layout, docs/controller.md)");
}

// The joints of the map (legs, backbone) that the model `m` has but drives with no actuator.
std::vector<std::string> unactuated_joints(const mjModel* m, const robot::RobotFile& file) {
  std::vector<std::string> names;
  for (const robot::LegMap& leg : file.legs) {
    for (const robot::JointMap& joint : leg.joints) names.push_back(joint.name);
  }
  if (file.backbone) names.push_back(file.backbone->name);
  std::vector<std::string> unactuated;
  for (const std::string& name : names) {
    const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str());
    if (j < 0) continue;  // make_sim_model names the key
    bool actuated = false;
    for (int a = 0; a < m->nu; ++a) {
      actuated |= m->actuator_trntype[a] == mjTRN_JOINT && m->actuator_trnid[2 * a] == j;
    }
    if (!actuated) unactuated.push_back(name);
  }
  return unactuated;
}

// Whether the world of `m` has a ground plane.
bool has_ground(const mjModel* m) {
  for (int g = 0; g < m->ngeom; ++g) {
    if (is_ground_plane(m, g)) return true;
  }
  return false;
}

// The MJCF of a URDF (MuJoCo's loader reads it) with a free joint on its trunk, which URDF fixes
// to the world.
std::string urdf_model(const std::string& urdf, const std::string& trunk, const TomlReader& r) {
  std::string xml = urdf_as_mjcf(urdf);
  const auto m = compile_mjcf(xml);
  const int body = mj_name2id(m.get(), mjOBJ_BODY, trunk.c_str());
  if (body < 0 || m->body_jntnum[body] > 0) return xml;  // make_sim_model says what is wrong
  if (m->body_parentid[body] != 0) r.fail("trunk", "'" + trunk + "' is not the URDF's root link");
  const std::size_t at = xml.find("<body name=\"" + trunk + "\"");
  if (at == std::string::npos) r.fail("trunk", "cannot find '" + trunk + "' in the URDF's MJCF");
  xml.insert(xml.find('>', at) + 1, "<freejoint name=\"" + trunk + "_free\"/>");
  return xml;
}

// A motor the servo law drives brings its servo's armature (docs/robots.md "Servos", departure 2)
// to a joint that has none: the explicit velocity loop is stable only with it.
void give_armature(SimModel& model, const std::vector<std::string>& servo_joints) {
  mjModel* m = model.mj.get();
  bool changed = false;
  for (const std::string& name : servo_joints) {
    const int dof = m->jnt_dofadr[mj_name2id(m, mjOBJ_JOINT, name.c_str())];
    if (m->dof_armature[dof] == 0.0) {
      m->dof_armature[dof] = model.body.tc_servo.armature;
      changed = true;
    }
  }
  if (!changed) return;
  // The constants MuJoCo derives from inertias at compile time.
  const std::unique_ptr<mjData, MjDataDeleter> scratch(mj_makeData(m));
  if (!scratch) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
  mj_setConst(m, scratch.get());
}

// Other ground than a robot file's own flat one (robot::robot_file_mjcf): where the terrain does
// not stand on it (a slope, rough ground) its own planes no longer collide nor show. Throws
// OptionError ("scene.terrain") for a model whose contacts are only its <pair>s: they hold its feet
// to its own ground.
void leave_own_ground(mjModel* m, const robot::Terrain& terrain, const robot::RobotFile& file) {
  if (m->opt.collision == mjCOL_PAIR || m->npair > 0) {
    throw OptionError("scene.terrain",
                      fmt::format("{}: its model's <contact><pair>s hold the feet to its own "
                                  "ground: it walks only there, not on {} (docs/robots.md)",
                                  file.path.string(), robot::terrain_text(terrain)));
  }
  if (robot::keeps_own_ground(terrain)) return;
  const int ours = mj_name2id(m, mjOBJ_GEOM, robot::kRobotFileGround);
  for (int g = 0; g < m->ngeom; ++g) {
    if (g == ours || !is_ground_plane(m, g)) continue;
    m->geom_contype[g] = 0;
    m->geom_conaffinity[g] = 0;
    m->geom_rgba[4 * g + 3] = 0.0F;
  }
}

// A robot file's start on other ground, as make_mjcf places the built-in robots: above rough
// ground's highest bump, or on a slope tilted with it about the start.
void place_on_terrain(SimModel& model, const robot::Terrain& terrain) {
  const mjModel* m = model.mj.get();
  std::vector<double> qpos = model.start_qpos;
  if (model.start_key >= 0) {
    qpos.assign(m->key_qpos + model.start_key * m->nq, m->key_qpos + (model.start_key + 1) * m->nq);
  }
  double* root = qpos.data() + model.root_qpos;
  root[2] += robot::rise(terrain);
  if (robot::tilted(terrain)) {
    const std::array<double, 4> q = robot::ground_rotation(terrain);
    const std::array<double, 3> p = robot::rotate(q, {root[0], root[1], root[2]});
    std::array<double, 4> tilted{};
    mju_mulQuat(tilted.data(), q.data(), root + 3);
    std::copy(p.begin(), p.end(), root);
    std::copy(tilted.begin(), tilted.end(), root + 3);
  }
  model.start_key = -1;
  model.start_qpos = std::move(qpos);
}

}  // namespace

bool is_robot_file(const std::string& robot) {
  return std::filesystem::path(robot).extension() == ".toml";
}

robot::RobotFile load_robot_file(const std::filesystem::path& path) {
  const TomlReader r(path);
  const toml::table doc = r.parse(r.read(kMaxRobotFileBytes, kMaxRobotFileText, "a robot file"));
  r.only(doc, "", {"name", "model", "trunk", "yaw", "master", "backbone", "legs"});
  robot::RobotFile file;
  file.path = path;
  file.name = r.text(doc, "", "name");
  file.model = path.parent_path() / r.text(doc, "", "model");
  file.trunk = r.text(doc, "", "trunk");
  file.yaw = r.text(doc, "", "yaw");
  file.master = r.text(doc, "", "master");
  if (doc.contains("backbone")) file.backbone = joint(r, doc, "", "backbone");

  const toml::array* legs = r.node(doc, "", "legs").as_array();
  if (legs == nullptr) r.fail("legs", "must be an array of tables ([[legs]])");
  file.layout = layout_of(legs->size(), r);
  const robot::Morphology& morph = robot::morphology(file.layout);
  for (std::size_t i = 0; i < legs->size(); ++i) {
    const std::string key = "legs[" + std::to_string(i) + "]";
    const toml::table* t = legs->get(i)->as_table();
    if (t == nullptr) r.fail(key, "must be a table");
    const std::string p = key + ".";
    r.only(*t, p, {"name", "side", "position", "foot", "TC", "CTr", "FTi"});
    const robot::Leg& expected = morph.legs[i];
    robot::LegMap leg{r.text(*t, p, "name"), expected.side, expected.position, {}, {}};
    if (leg.name != expected.name) {
      r.fail(p + "name", "'" + leg.name + "', expected '" + expected.name + "' (legs are listed " +
                             morph.legs.front().name + ".." +
                             morph.legs[morph.size() / 2 - 1].name + ", then " +
                             morph.legs[morph.size() / 2].name + ".." + morph.legs.back().name +
                             ")");
    }
    if (r.text(*t, p, "side") != robot::to_string(expected.side)) {
      r.fail(p + "side", "leg " + leg.name + " is on the " +
                             std::string(robot::to_string(expected.side)) + " side");
    }
    const std::optional<int64_t> position = r.node(*t, p, "position").value_exact<int64_t>();
    if (position != expected.position) {
      r.fail(p + "position", "leg " + leg.name + " is at position " +
                                 std::to_string(expected.position) + " (0 = front)");
    }
    leg.foot = r.text(*t, p, "foot");
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      leg.joints[j] = joint(r, *t, p, robot::to_string(robot::kJoints[j]));
    }
    file.legs.push_back(leg);
  }
  if (file.master != morph.legs[0].name) {
    r.fail("master", "'" + file.master + "': the controller's master is " + morph.legs[0].name +
                         " (paper §2.3)");
  }

  try {
    file.model_xml = read_input_file(file.model, kMaxModelBytes, kMaxModelText, "a robot's model");
  } catch (const BadInput& e) {
    r.fail("model", e.what());
  }
  try {
    if (file.model.extension() == ".urdf")
      file.model_xml = urdf_model(file.model_xml, file.trunk, r);
    const auto raw = compile_mjcf(file.model_xml);
    file.servo_joints = unactuated_joints(raw.get(), file);
    file.add_ground = !has_ground(raw.get());
    make_sim_model(file);
  } catch (const OptionError& e) {
    r.fail(e.key(), e.what());
  } catch (const RuntimeFailure& e) {
    r.fail("model", e.what());
  }
  return file;
}

SimModel make_sim_model(const robot::RobotFile& file, const SimOptions& options) {
  SimModel model = new_model(file.layout, options, file);
  const robot::Terrain& terrain = options.scene.terrain;
  const bool flat = robot::is_flat(terrain);
  if (options.scene.tunnel || !file.servo_joints.empty() || file.add_ground || !flat) {
    // Included as MJCF whatever it was (a URDF as MuJoCo's loader read it).
    const std::string name = file.model.stem().string() + ".xml";
    model.xml = robot::robot_file_mjcf(model.body, options.scene, file, name);
    model.files = robot::scene_files(options.scene);
    model.files.push_back({name, file.model_xml});
  } else {
    model.xml = file.model_xml;
  }
  model.mj = compile_mjcf(model.xml, model.files);
  give_armature(model, file.servo_joints);
  // The physics step and, in the tunnel, the wall contacts, as make_mjcf writes them.
  model.mj->opt.timestep = robot::mjcf_value(model.physics_dt);
  if (options.scene.tunnel) model.mj->opt.collision = mjCOL_ALL;
  if (!flat) leave_own_ground(model.mj.get(), terrain, file);
  index_model(model, file, options);
  if (!flat) place_on_terrain(model, terrain);
  return model;
}

}  // namespace multicpg::sim
