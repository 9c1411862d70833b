// SPDX-License-Identifier: BSL-1.0
// One command encoded.
#include <cstdio>
#include <seawire/kingfisher/messages.hpp>

int main(int argc, char**) {
  seawire::kingfisher::pydir d;
  d.thrust_left = argc;
  const auto out = seawire::nmea::encode(d);
  std::printf("%.*s", static_cast<int>(out.view().size()), out.view().data());
  return 0;
}
