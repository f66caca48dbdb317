#include "report/fault_colours.h"

#include <algorithm>

#include "body/fault_spec.h"
#include "common/variants.h"

namespace multicpg::report {
namespace {

// The segments a fault strikes, found through the joints that move them (robot files name their
// bodies as they like): a joint's segment is its body, the foot the foot geom's body. A whole leg
// is every body from its first joint down, and its shoulder, a geom of the trunk (robot/mjcf.h).
struct Parts {
  std::vector<robot::Joint> segments;  // the bodies of these joints
  bool foot = false;
  bool whole_leg = false;
};

Parts parts_of(const body::Fault& fault) {
  const Parts whole{{}, false, true};
  const auto joint_or_leg = [&] {
    return fault.joint ? Parts{{*fault.joint}, false, false} : whole;
  };
  return std::visit(Overloaded{
                        [&](const body::LegFault&) { return whole; },
                        [&](const body::ShortTibia&) {
                          return Parts{{robot::Joint::FTi}, true, false};
                        },
                        [&](const body::SlipperyFoot&) {
                          return Parts{{}, true, false};
                        },
                        [&](const body::ImuDrift&) { return Parts{}; },
                        [&](const body::ImuNoise&) { return Parts{}; },
                        [&](const auto&) { return joint_or_leg(); },  // the segment it moves
                    },
                    fault.kind);
}

// Whether `body` is `root` or below it.
bool within(const mjModel* m, int body, int root) {
  for (; body > 0; body = m->body_parentid[body]) {
    if (body == root) return true;
  }
  return false;
}

// The leg's topmost segment: the body of the joint nearest the trunk.
int leg_root(const mjModel* m, const sim::LegSlots& slots) {
  int root = m->jnt_bodyid[slots.joints[0].joint];
  for (const sim::JointSlot& j : slots.joints) {
    if (within(m, root, m->jnt_bodyid[j.joint])) root = m->jnt_bodyid[j.joint];
  }
  return root;
}

}  // namespace

Rgba kind_colour(const body::Malfunction& kind) {
  return std::visit(Overloaded{
                        [](const body::LegFault&) {
                          return Rgba{0.85F, 0.08F, 0.08F, 1.0F};
                        },
                        [](const body::LockedJoint&) {
                          return Rgba{0.95F, 0.55F, 0.05F, 1.0F};
                        },
                        [](const body::PassiveJoint&) {
                          return Rgba{0.95F, 0.9F, 0.1F, 1.0F};
                        },
                        [](const body::WeakMotor&) {
                          return Rgba{0.6F, 0.25F, 0.85F, 1.0F};
                        },
                        [](const body::ShortTibia&) {
                          return Rgba{0.15F, 0.35F, 0.95F, 1.0F};
                        },
                        [](const body::SlipperyFoot&) {
                          return Rgba{0.1F, 0.85F, 0.9F, 1.0F};
                        },
                        [](const auto&) {
                          return Rgba{0.5F, 0.5F, 0.5F, 1.0F};
                        },
                    },
                    kind);
}

Colouring fault_colours(const sim::SimModel& model, const body::FaultTimeline& in_force) {
  const mjModel* m = model.mj.get();
  const robot::Morphology& morph = model.controller.morphology;
  Colouring out;
  for (const body::Fault& f : in_force) {
    const Parts parts = parts_of(f);
    const Rgba rgba = kind_colour(f.kind);
    for (std::size_t leg : f.legs) {
      const sim::LegSlots& slots = model.legs[leg];
      const int root = leg_root(m, slots);
      std::vector<int> bodies;
      for (robot::Joint joint : parts.segments) {
        bodies.push_back(m->jnt_bodyid[slots.joints[static_cast<std::size_t>(joint)].joint]);
      }
      if (parts.foot) bodies.push_back(slots.foot_body);
      for (int g = 0; g < m->ngeom; ++g) {
        const int body = m->geom_bodyid[g];
        if ((parts.whole_leg && within(m, body, root)) ||
            std::find(bodies.begin(), bodies.end(), body) != bodies.end()) {
          out.push_back({g, rgba});
        }
      }
      const int shoulder = mj_name2id(m, mjOBJ_GEOM, (morph.legs[leg].name + "_shoulder").c_str());
      if (parts.whole_leg && shoulder >= 0) out.push_back({shoulder, rgba});
    }
  }
  return out;
}

std::string faults_caption(const robot::Morphology& morph, const body::FaultTimeline& in_force) {
  // The atoms in force (one per leg) joined back into one fault per kind, joint and value.
  body::FaultTimeline joined;
  for (const body::Fault& f : in_force) {
    const auto same = std::find_if(joined.begin(), joined.end(), [&](const body::Fault& j) {
      return j.kind == f.kind && j.joint == f.joint;
    });
    if (same == joined.end()) {
      joined.push_back(f);
    } else {
      same->legs.insert(same->legs.end(), f.legs.begin(), f.legs.end());
      std::sort(same->legs.begin(), same->legs.end());
    }
  }
  std::string out;
  for (const body::Fault& f : joined) {
    if (!out.empty()) out += ", ";
    out += body::malfunction_text(morph, f);
  }
  return out.empty() ? "none" : out;
}

}  // namespace multicpg::report
