// SPDX-License-Identifier: BSL-1.0
// A program using seawire as a downstream project would. ctest builds it twice: against an
// installed seawire (find_package) and against the source tree (add_subdirectory).
#include <cstdio>
#include <string_view>

#include <seawire/seawire.hpp>

namespace {

int failures = 0;

void expect(bool ok, std::string_view what) {
  if (!ok) {
    std::fprintf(stderr, "FAILED: %.*s\n", static_cast<int>(what.size()), what.data());
    ++failures;
  }
}

}  // namespace

int main() {
  std::printf("seawire %.*s\n", static_cast<int>(seawire::version.size()), seawire::version.data());
#ifdef SEAWIRE_EXPECTED_VERSION
  expect(seawire::version == SEAWIRE_EXPECTED_VERSION, "version matches the package version");
#endif
  expect(seawire::name(seawire::errc::checksum_mismatch) == "checksum_mismatch",
         "name(errc::checksum_mismatch)");
  return failures == 0 ? 0 : 1;
}
