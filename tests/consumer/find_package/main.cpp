// SPDX-License-Identifier: BSL-1.0
// A program using seawire as a downstream project would. ctest builds it against an installed
// seawire (find_package) and against the source tree (add_subdirectory), each time twice:
// header-only (seawire::seawire) and with the library's decoders and encoders compiled once
// (seawire::compiled).
#include <cstdio>
#include <string_view>
#include <variant>

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
  // A role decoder: its set's decoder is declared only when SEAWIRE_SEPARATE_COMPILATION is
  // defined.
  const auto alt = seawire::kingfisher::decode_from_vehicle("$CPALT,164959.100,1*62\r\n");
  expect(alt && std::holds_alternative<seawire::kingfisher::cpalt>(alt.value) &&
             std::get<seawire::kingfisher::cpalt>(alt.value).lights_on,
         "decode_from_vehicle($CPALT...)");
  expect(seawire::kingfisher::decode_from_vehicle("$CPALT,164959.100,1*63\r\n").ec ==
             seawire::errc::checksum_mismatch,
         "decode_from_vehicle refuses a wrong checksum");
#ifdef SEAWIRE_SEPARATE_COMPILATION
  std::printf("decoders and encoders compiled once\n");
#endif
  return failures == 0 ? 0 : 1;
}
