#include "learning/landscape_cache.h"

#include <map>
#include <mutex>
#include <string>

#include "common/errors.h"

namespace multicpg::learning {

std::shared_ptr<const LandscapeDataset> read_landscape_dataset_once(
    const std::filesystem::path& path) {
  LandscapeFiles files;
  try {
    files = read_landscape_files(path);
  } catch (const BadInput&) {
    // Named as read_landscape_dataset names it: whatever is wrong with the manifest first.
    return std::make_shared<const LandscapeDataset>(read_landscape_dataset(path));
  }
  // No manifest holds a NUL (JSON text), so the two files' bytes cannot run together.
  std::string key = files.manifest + '\0' + files.csv_gzip;
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const LandscapeDataset>> parsed;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = parsed.find(key); it != parsed.end()) return it->second;
  }
  auto dataset = std::make_shared<const LandscapeDataset>(parse_landscape_dataset(path, files));
  const std::lock_guard<std::mutex> lock(mutex);
  return parsed.emplace(std::move(key), std::move(dataset)).first->second;
}

}  // namespace multicpg::learning
