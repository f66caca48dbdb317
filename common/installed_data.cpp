#include "common/installed_data.h"

#include <dlfcn.h>
#include <sys/auxv.h>

#include <system_error>

namespace multicpg {
namespace {

namespace fs = std::filesystem;

// An installed program is <prefix>/bin/multicpg with its data in <prefix>/share/multicpg; the
// Python package multicpg/ holds the module's shared library and data/.
constexpr const char* kProgramData = "../share/multicpg";
constexpr const char* kPackageData = "data";

}  // namespace

fs::path program_data_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return (exe.parent_path() / kProgramData).lexically_normal();
}

// dladdr names the object holding `anchor`: the Python module's shared library, or the program
// itself when that object also holds the program's headers (AT_PHDR); a program's name as dladdr
// gives it is argv[0], so its path is read from /proc/self/exe instead.
fs::path installed_data_dir() {
  static const int anchor = 0;
  Dl_info code{};
  if (dladdr(&anchor, &code) == 0 || code.dli_fname == nullptr) return {};
  Dl_info program{};
  const void* headers = reinterpret_cast<const void*>(getauxval(AT_PHDR));
  if (dladdr(headers, &program) == 0 || program.dli_fbase != code.dli_fbase) {
    return fs::path(code.dli_fname).parent_path() / kPackageData;
  }
  return program_data_dir();
}

}  // namespace multicpg
