// Where what the code reads is installed (apps/CMakeLists.txt, setup.py): <prefix>/share/multicpg
// beside an installed <prefix>/bin/multicpg, or data/ inside the Python package beside its module.
#pragma once

#include <filesystem>

namespace multicpg {

// <prefix>/share/multicpg for the running program (read from /proc/self/exe); empty when it
// cannot be read.
std::filesystem::path program_data_dir();

// The data directory installed beside the code running this: the Python package's data/ when it
// runs inside the module's shared library, else program_data_dir(); empty when it cannot tell.
std::filesystem::path installed_data_dir();

}  // namespace multicpg
