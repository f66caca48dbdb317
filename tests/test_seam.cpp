// The body seam (docs/development.md "Layout"): what a run needs of any body (body/) and the real
// robot (hw/) link no MuJoCo. This program links those two libraries alone, every library on
// their link line kept (--no-as-needed), and looks at what the loader brought in.
#include <gtest/gtest.h>
#include <link.h>

#include <string>
#include <vector>

#include "body/body.h"
#include "hw/hardware_body.h"

namespace {

std::vector<std::string> loaded_libraries() {
  std::vector<std::string> out;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        static_cast<std::vector<std::string>*>(data)->emplace_back(info->dlpi_name);
        return 0;
      },
      &out);
  return out;
}

TEST(Seam, TheBodyAndTheHardwareLinkNoMuJoCo) {
  // Use both libraries, so neither is dropped from the program.
  multicpg::body::Senses senses;
  EXPECT_FALSE(senses.pose().has_position());
  multicpg::hw::BodyMap map;
  EXPECT_EQ(map.control_dt, 0.0);
  const std::vector<std::string> libraries = loaded_libraries();
  ASSERT_FALSE(libraries.empty());
  for (const std::string& name : libraries) {
    EXPECT_EQ(name.find("mujoco"), std::string::npos) << name << " was linked";
  }
}

}  // namespace
