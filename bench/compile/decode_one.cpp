// SPDX-License-Identifier: BSL-1.0
// One message type decoded, from its own header.
#include <cstdio>
#include <seawire/standard/rmc.hpp>

int main(int argc, char** argv) {
  const auto r = seawire::nmea::decode<seawire::standard::rmc>(argc > 1 ? argv[1] : "");
  std::printf("%d\n", r ? static_cast<int>(r.value.status) : -1);
  return 0;
}
