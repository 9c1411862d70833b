// SPDX-License-Identifier: BSL-1.0
// Every family's role decoders in one translation unit, as a multi-protocol logger has them.
#include <cstdio>
#include <seawire/seawire.hpp>

int main(int argc, char** argv) {
  const char* line = argc > 1 ? argv[1] : "";
  int ok = 0;
  ok += seawire::kingfisher::decode_from_vehicle(line).ok();
  ok += seawire::kingfisher::decode_to_vehicle(line).ok();
  ok += seawire::sandshark::decode_from_vehicle(line).ok();
  ok += seawire::sandshark::decode_to_vehicle(line).ok();
  ok += seawire::robotx::decode_report(line).ok();
  ok += seawire::anello::decode_input(line).ok();
  std::printf("%d\n", ok);
  return 0;
}
