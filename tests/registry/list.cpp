// SPDX-License-Identifier: BSL-1.0
// Prints every message seawire/registry.hpp lists, one a line: each sentence's address, each
// PGN struct as "PGN <number> <struct>", the 0xAB00 frame as "frame". registry_complete.cmake
// compares this with what the headers declare and what docs/messages.md describes.

#include <cstdio>
#include <string>

#include "seawire/registry.hpp"

int main() {
  namespace registry = seawire::registry;
  registry::for_each_type<registry::sentences>([](auto tag) {
    using M = typename decltype(tag)::type;
    std::printf("%s\n", std::string(M::nmea.address).c_str());
  });
  registry::for_each_type<registry::pgns>([](auto tag) {
    using P = typename decltype(tag)::type;
    std::printf("PGN %u %s\n", static_cast<unsigned>(seawire::nmea2000::pgn_table<P>.info.pgn),
                std::string(seawire::nmea2000::pgn_table<P>.info.name).c_str());
  });
  registry::for_each_type<registry::frames>([](auto) { std::printf("frame\n"); });
  return 0;
}
