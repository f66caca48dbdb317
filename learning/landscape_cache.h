// The landscape datasets this process has parsed (learning/landscapes.h reads and writes the
// format, holding nothing): a run's data are resolved when its spec is checked and again when it
// starts, and a sweep checks every run's, so the same files are asked for many times.
#pragma once

#include <filesystem>
#include <memory>

#include "learning/landscapes.h"

namespace multicpg::learning {

// read_landscape_dataset, parsed once per process for each content. The key is both files' whole
// bytes, so an edited or damaged file is read (and refused) anew, never served from memory.
// Thread-safe.
std::shared_ptr<const LandscapeDataset> read_landscape_dataset_once(
    const std::filesystem::path& path);

}  // namespace multicpg::learning
