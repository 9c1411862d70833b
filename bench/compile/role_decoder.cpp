// SPDX-License-Identifier: BSL-1.0
// A Kingfisher payload: the vehicle's role decoder (8 messages) and a visit over them.
#include <cstdio>
#include <seawire/kingfisher/messages.hpp>

int main(int argc, char** argv) {
  const auto r = seawire::kingfisher::decode_from_vehicle(argc > 1 ? argv[1] : "");
  if (r) std::visit([](const auto& m) { std::printf("%zu\n", sizeof m); }, r.value);
  return 0;
}
