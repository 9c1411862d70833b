// SPDX-License-Identifier: BSL-1.0
// seawire-xor-baseline: the least a sentence checker can do, as the yardstick for
// seawire-decode --format none. Reads stdin in 64 KiB chunks, splits it into lines, and checks
// each line's XOR checksum ($...*hh); prints how many lines were good and bad. No fields, no
// dispatch, no framer. Exit status 1 when some line was bad.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "io.hpp"

namespace {

int hex(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// "$body*hh" (line ending already removed).
bool check(std::string_view line) {
  while (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() < 4 || line[0] != '$' || line[line.size() - 3] != '*') return false;
  unsigned x = 0;
  for (std::size_t i = 1; i + 3 < line.size(); ++i) x ^= static_cast<unsigned char>(line[i]);
  const int h = hex(line[line.size() - 2]);
  const int l = hex(line[line.size() - 1]);
  return h >= 0 && l >= 0 && static_cast<unsigned>(h * 16 + l) == x;
}

}  // namespace

int main() {
  seawire::tools::chunk_reader in(0);
  std::uint64_t good = 0;
  std::uint64_t bad = 0;
  const auto line = [&](std::string_view l) {
    if (l.empty() || l == "\r") return;
    (check(l) ? good : bad) += 1;
  };
  seawire::tools::for_each_line(in, line);
  std::printf("%llu good, %llu bad\n", static_cast<unsigned long long>(good),
              static_cast<unsigned long long>(bad));
  return bad == 0 ? 0 : 1;
}
