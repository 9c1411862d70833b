// SPDX-License-Identifier: BSL-1.0
// A main() for compilers without libFuzzer (GCC): runs a fuzz target's LLVMFuzzerTestOneInput
// over every file of the directories or files named on the command line, in name order, so the
// corpus and every crash kept in it are replayed as a ctest test. A property that fails aborts,
// which fails the test; so does a directory that is missing or empty.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool run_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "replay: cannot read %s\n", path.c_str());
    return false;
  }
  // A buffer of exactly the file's size, so ASan sees a read past the end as libFuzzer would.
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  (void)LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t runs = 0;
  for (int a = 1; a < argc; ++a) {
    const std::filesystem::path target(argv[a]);
    std::error_code ec;
    if (std::filesystem::is_regular_file(target, ec)) {
      if (!run_file(target)) return 1;
      ++runs;
      continue;
    }
    std::vector<std::filesystem::path> files;
    for (std::filesystem::directory_iterator it(target, ec), end; !ec && it != end;
         it.increment(ec)) {
      if (it->is_regular_file(ec)) files.push_back(it->path());
    }
    if (ec || files.empty()) {
      std::fprintf(stderr, "replay: no inputs in %s\n", target.c_str());
      return 1;
    }
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& f : files) {
      if (!run_file(f)) return 1;
      ++runs;
    }
  }
  if (runs == 0) {
    std::fprintf(stderr, "usage: %s <corpus dir or file>...\n", argv[0]);
    return 1;
  }
  std::printf("replayed %zu inputs: all properties held\n", runs);
  return 0;
}
