// Disabled legs drawn red, as in the paper's figures (Figs. 7, 11): shared by the headless
// renderer and the interactive viewer, so pictures and window look the same.
#pragma once

#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace multicpg::report {

inline constexpr std::array<float, 4> kDisabledRed{0.85F, 0.08F, 0.08F, 1.0F};

inline bool starts_with_any(const char* name, const std::vector<std::string>& prefixes) {
  if (name == nullptr) return false;
  const std::string_view n(name);
  return std::any_of(prefixes.begin(), prefixes.end(),
                     [&](const std::string& p) { return !p.empty() && n.starts_with(p); });
}

// True when the geom, its body or any ancestor body is named with one of the prefixes, so a
// leg's unnamed sub-parts turn red with it.
inline bool is_red(const mjModel* m, int geom, const std::vector<std::string>& prefixes) {
  if (starts_with_any(mj_id2name(m, mjOBJ_GEOM, geom), prefixes)) return true;
  for (int body = m->geom_bodyid[geom]; body > 0; body = m->body_parentid[body]) {
    if (starts_with_any(mj_id2name(m, mjOBJ_BODY, body), prefixes)) return true;
  }
  return false;
}

// Recolours the scene's geoms that is_red picks (call after mjv_updateScene).
inline void paint_red(const mjModel* m, mjvScene& scene, const std::vector<std::string>& prefixes) {
  if (prefixes.empty()) return;
  for (int i = 0; i < scene.ngeom; ++i) {
    mjvGeom& g = scene.geoms[i];
    if (g.objtype == mjOBJ_GEOM && g.objid >= 0 && is_red(m, g.objid, prefixes)) {
      std::copy(kDisabledRed.begin(), kDisabledRed.end(), g.rgba);
    }
  }
}

}  // namespace multicpg::report
