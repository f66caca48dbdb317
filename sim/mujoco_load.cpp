#include "sim/mujoco_load.h"

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "common/errors.h"

namespace multicpg::sim {
namespace {

// The XML parser is not documented as thread-safe, and it keeps the last model it read (for
// mj_saveLastXML), so loads are serialised.
std::mutex& loader_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Loads `main` (MJCF or URDF, by its root element) with `files` beside it from MuJoCo's in-memory
// file system. Call with loader_mutex() held.
mjModel* load_in_memory(const std::string& name, const std::string& main,
                        const std::vector<robot::ModelFile>& files) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const auto add = [&](const std::string& file, const std::string& bytes) {
    if (mj_makeEmptyFileVFS(vfs.get(), file.c_str(), static_cast<int>(bytes.size())) != 0) {
      mj_deleteVFS(vfs.get());
      throw RuntimeFailure("MuJoCo: cannot make the in-memory model file " + file);
    }
    std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), file.c_str())], bytes.data(), bytes.size());
  };
  add(name, main);
  for (const robot::ModelFile& f : files) add(f.name, f.bytes);
  std::array<char, 1000> error{};
  mjModel* m = mj_loadXML(name.c_str(), vfs.get(), error.data(), static_cast<int>(error.size()));
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw RuntimeFailure(std::string("MuJoCo rejected the model: ") + error.data());
  return m;
}

}  // namespace

std::unique_ptr<mjModel, MjModelDeleter> compile_mjcf(const std::string& xml,
                                                      const std::vector<robot::ModelFile>& files) {
  const std::lock_guard<std::mutex> lock(loader_mutex());
  return std::unique_ptr<mjModel, MjModelDeleter>(load_in_memory("multicpg.xml", xml, files));
}

std::string urdf_as_mjcf(const std::string& urdf) {
  const std::lock_guard<std::mutex> lock(loader_mutex());
  const std::unique_ptr<mjModel, MjModelDeleter> m(load_in_memory("multicpg.urdf", urdf, {}));
  // MuJoCo writes the model it read last only to a file.
  static std::atomic<unsigned> count{0};
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     fmt::format("multicpg-urdf-{}-{}.xml", ::getpid(), count++);
  std::array<char, 1000> error{};
  const int saved =
      mj_saveLastXML(path.string().c_str(), m.get(), error.data(), static_cast<int>(error.size()));
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  if (saved == 0 || !in) {
    throw RuntimeFailure(std::string("MuJoCo cannot write the URDF as MJCF: ") + error.data());
  }
  return text.str();
}

}  // namespace multicpg::sim
