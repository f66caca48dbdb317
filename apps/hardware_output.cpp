#include "apps/hardware_output.h"

#include <iostream>

#include "common/atomic_file.h"

namespace multicpg::apps {

experiments::StoppedSink stopped_record(bool json, const std::string& file) {
  return [json, file](const nlohmann::json& record) {
    if (!file.empty()) write_file_atomic(file, record.dump(2) + "\n");
    if (json) std::cout << record.dump(2) << "\n" << std::flush;
  };
}

}  // namespace multicpg::apps
