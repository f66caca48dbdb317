#include "report/fault_colours.h"

#include <algorithm>

#include "sim/fault_spec.h"

namespace multicpg::report {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
// Spelled out: clang 14 (the sanitizer job's) does not deduce an aggregate's template arguments.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// The segment bodies a fault strikes, as named in the MJCF (robot/mjcf.h): "<leg>_coxa",
// "_femur", "_tibia", "_foot". A whole leg adds its shoulder, a geom of the trunk.
struct Parts {
  std::vector<std::string> bodies;
  bool shoulder = false;
};

Parts parts_of(const sim::Fault& fault) {
  static const std::array<const char*, robot::kJointsPerLeg> kSegmentOf{"_coxa", "_femur",
                                                                        "_tibia"};
  const auto whole_leg = [] { return Parts{{"_coxa", "_femur", "_tibia", "_foot"}, true}; };
  return std::visit(
      Overloaded{
          [&](const sim::LegFault&) { return whole_leg(); },
          [&](const sim::WeakMotor&) {
            return fault.joint ? Parts{{kSegmentOf[static_cast<std::size_t>(*fault.joint)]}}
                               : whole_leg();
          },
          [&](const sim::ShortTibia&) { return Parts{{"_tibia", "_foot"}}; },
          [&](const sim::SlipperyFoot&) { return Parts{{"_foot"}}; },
          [&](const sim::ImuDrift&) { return Parts{}; },
          [&](const sim::ImuNoise&) { return Parts{}; },
          [&](const auto&) {  // joint kinds: the segment the joint moves
            return fault.joint ? Parts{{kSegmentOf[static_cast<std::size_t>(*fault.joint)]}}
                               : whole_leg();
          },
      },
      fault.kind);
}

}  // namespace

Rgba kind_colour(const sim::Malfunction& kind) {
  return std::visit(Overloaded{
                        [](const sim::LegFault&) { return Rgba{0.85F, 0.08F, 0.08F, 1.0F}; },
                        [](const sim::LockedJoint&) { return Rgba{0.95F, 0.55F, 0.05F, 1.0F}; },
                        [](const sim::PassiveJoint&) { return Rgba{0.95F, 0.9F, 0.1F, 1.0F}; },
                        [](const sim::WeakMotor&) { return Rgba{0.6F, 0.25F, 0.85F, 1.0F}; },
                        [](const sim::ShortTibia&) { return Rgba{0.15F, 0.35F, 0.95F, 1.0F}; },
                        [](const sim::SlipperyFoot&) { return Rgba{0.1F, 0.85F, 0.9F, 1.0F}; },
                        [](const auto&) { return Rgba{0.5F, 0.5F, 0.5F, 1.0F}; },
                    },
                    kind);
}

Colouring fault_colours(const sim::SimModel& model, const sim::FaultTimeline& in_force) {
  const mjModel* m = model.mj.get();
  const robot::Morphology& morph = model.controller.morphology;
  Colouring out;
  for (const sim::Fault& f : in_force) {
    const Parts parts = parts_of(f);
    const Rgba rgba = kind_colour(f.kind);
    for (std::size_t leg : f.legs) {
      const std::string& name = morph.legs[leg].name;
      std::vector<int> bodies;
      for (const std::string& part : parts.bodies) {
        const int body = mj_name2id(m, mjOBJ_BODY, (name + part).c_str());
        if (body >= 0) bodies.push_back(body);
      }
      for (int g = 0; g < m->ngeom; ++g) {
        if (std::find(bodies.begin(), bodies.end(), m->geom_bodyid[g]) != bodies.end()) {
          out.push_back({g, rgba});
        }
      }
      const int shoulder = mj_name2id(m, mjOBJ_GEOM, (name + "_shoulder").c_str());
      if (parts.shoulder && shoulder >= 0) out.push_back({shoulder, rgba});
    }
  }
  return out;
}

std::string faults_caption(const robot::Morphology& morph, const sim::FaultTimeline& in_force) {
  // The atoms in force (one per leg) joined back into one fault per kind, joint and value.
  sim::FaultTimeline joined;
  for (const sim::Fault& f : in_force) {
    const auto same = std::find_if(joined.begin(), joined.end(), [&](const sim::Fault& j) {
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
  for (const sim::Fault& f : joined) {
    if (!out.empty()) out += ", ";
    out += sim::malfunction_text(morph, f);
  }
  return out.empty() ? "none" : out;
}

}  // namespace multicpg::report
