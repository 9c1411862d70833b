// SPDX-License-Identifier: BSL-1.0
// A Kingfisher payload's whole use of seawire: the vehicle's sentences through the role decoder
// and a visit, and the four PY* commands encoded.
#include <cstdio>
#include <seawire/kingfisher/messages.hpp>
#include <string_view>

namespace kf = seawire::kingfisher;

int main(int argc, char** argv) {
  const char* line = argc > 1 ? argv[1] : "";
  const auto r = kf::decode_from_vehicle(line);
  if (r) std::visit([](const auto& m) { std::printf("%zu\n", sizeof m); }, r.value);
  const auto s = seawire::nmea::parse(line, kf::payload_policy());
  if (s)
    (void)kf::from_vehicle::visit(s.value, kf::payload_policy(),
                                  [](const auto& m) { std::printf("%zu\n", sizeof m); });
  kf::pydir dir{};
  kf::pydev dev{};
  kf::pydep dep{};
  kf::pyclt clt{};
  for (const std::string_view out :
       {seawire::nmea::encode(dir).view(), seawire::nmea::encode(dev).view(),
        seawire::nmea::encode(dep).view(), seawire::nmea::encode(clt).view()})
    std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}
