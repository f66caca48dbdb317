// Reading a file the user names (a dataset, a run record, a robot, hardware or experiment file):
// the one way every input file is opened, so none can block or exhaust the program. It must be a
// regular file (a FIFO is refused without waiting for a writer, a directory or device named as
// such), at most a stated size, and it is never read past that size (/dev/zero, a file that grows).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace multicpg {

// The most a file multicpg wrote and reads back may have (a run record, a learning result, an
// experiment's summary, a report's section): a learning result of 100,000 trials is some 35 MB.
inline constexpr std::size_t kMaxRecordBytes = std::size_t{64} << 20;
inline constexpr std::string_view kMaxRecordText = "64 MiB";

// The bytes of `path`, at most `max_bytes` (whose text, e.g. "1 MiB", `max_text` gives).
// Throws BadInput "NAME: cannot read (strerror)", "NAME: is a directory, not a file", "NAME: is a
// FIFO, not a file" (device, socket), or "NAME: is N bytes, more than the MAX_TEXT WHAT may
// have", NAME being `path` as given.
std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes,
                            std::string_view max_text, std::string_view what);

}  // namespace multicpg
